#include "core/scene/name_registry.h"

#include <algorithm>

#include "core/scene/closest_match.h"

namespace fissure {

void NameRegistry::add(const std::string& name, const ConfigNode& node) {
  if (const int i = find(name); i >= 0)
    node.error("found '" + name + "' again (already the name of " + what_ + " " +
               std::to_string(i) + " on line " + std::to_string(where_[i].line) +
               "); expected a unique " + what_ + " name");
  index_.emplace(name, static_cast<int>(names_.size()));
  names_.push_back(name);
  where_.push_back(node.location());
}

void NameRegistry::add_unreadable() {
  names_.emplace_back();
  where_.emplace_back();
  complete_ = false;
}

int NameRegistry::find(std::string_view name) const {
  if (name.empty()) return -1;
  const auto it = index_.find(std::string(name));
  return it == index_.end() ? -1 : it->second;
}

std::optional<int> NameRegistry::resolve(const ConfigNode& node) const {
  const std::optional<std::string> name = node.string("the name of a " + what_);
  if (!name) return std::nullopt;
  if (const int i = find(*name); i >= 0) return i;
  if (!complete_) return std::nullopt;  // may be the item whose name was unreadable
  std::vector<std::string_view> candidates;
  std::string list;
  for (const std::string& n : names_) {
    if (std::find(candidates.begin(), candidates.end(), n) != candidates.end()) continue;
    candidates.push_back(n);
    list += (list.empty() ? "" : ", ") + n;
  }
  std::string message = "found '" + *name + "'";
  if (const auto m = closest_match(*name, candidates)) message += " (did you mean '" + *m + "'?)";
  if (names_.empty())
    node.error(message + ", but the scene defines no " + what_ + "; expected the name of a " +
               what_);
  else
    node.error(message + ", which is not defined; expected the name of a " + what_ + ": " + list);
  return std::nullopt;
}

}  // namespace fissure
