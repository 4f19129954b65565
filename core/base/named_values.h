// Values of types that core does not know, by name (docs/architecture.md 4): the
// validated settings of each module's scene section (Scene::sections) and
// the fields that processes exchange through the shared state
// (RockMass::fields). A Key<T> names a value and fixes its type: the module
// that owns a value defines its key next to the type, and a read with the
// wrong type is a programming error, reported at the first access.
#pragma once

#include <any>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fissure {

/// The name of a value of type T.
template <class T>
struct Key {
  std::string_view name;
};

class NamedValues {
 public:
  bool contains(std::string_view name) const { return values_.find(name) != values_.end(); }

  /// The value, or nullptr when there is none.
  template <class T>
  const T* find(Key<T> key) const {
    const auto it = values_.find(key.name);
    return it == values_.end() ? nullptr : cast<T>(it->second, key);
  }
  template <class T>
  T* find(Key<T> key) {
    const auto it = values_.find(key.name);
    return it == values_.end() ? nullptr : cast<T>(it->second, key);
  }

  /// The value; throws std::logic_error when there is none.
  template <class T>
  const T& get(Key<T> key) const {
    if (const T* v = find(key)) return *v;
    throw std::logic_error("no value named '" + std::string(key.name) + "'");
  }
  template <class T>
  T& get(Key<T> key) {
    if (T* v = find(key)) return *v;
    throw std::logic_error("no value named '" + std::string(key.name) + "'");
  }

  /// The value, default-constructed first when there is none.
  template <class T>
  T& get_or_add(Key<T> key) {
    if (T* v = find(key)) return *v;
    return set(key, T{});
  }

  /// Sets (or replaces) the value.
  template <class T>
  T& set(Key<T> key, T value) {
    std::any& slot = values_[std::string(key.name)];
    slot = std::move(value);
    return *std::any_cast<T>(&slot);
  }

  void erase(std::string_view name) {
    const auto it = values_.find(name);
    if (it != values_.end()) values_.erase(it);
  }

  /// Names of every value, sorted.
  std::vector<std::string> names() const {
    std::vector<std::string> n;
    for (const auto& [name, value] : values_) n.push_back(name);
    return n;
  }

 private:
  template <class T>
  static T* cast(const std::any& slot, Key<T> key) {
    T* v = const_cast<T*>(std::any_cast<T>(&slot));
    if (!v)
      throw std::logic_error("the value named '" + std::string(key.name) +
                             "' has another type than the one asked for");
    return v;
  }

  std::map<std::string, std::any, std::less<>> values_;
};

}  // namespace fissure
