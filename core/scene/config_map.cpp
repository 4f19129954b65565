#include "core/scene/config_map.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "core/scene/closest_match.h"

namespace fissure {

namespace {

std::string key_list(std::span<const std::string_view> keys) {
  std::string s;
  for (std::string_view k : keys) {
    if (!s.empty()) s += ", ";
    s += k;
  }
  return s;
}

/// The note of an unknown key whose documented path `from` is now `to`: a
/// key renamed within its map reads as a suggestion of the new spelling
/// ("did you mean 'heat_flux'?"; a key that went into a map of its own,
/// "did you mean 'heat_transfer: {coefficient: ...}'?"); one that moved to
/// another section names its new path.
std::string moved_note(std::string_view section, std::string_view to) {
  const std::string prefix = std::string(section) + ".";
  if (section.empty() || to.substr(0, prefix.size()) != prefix)
    return " (moved to " + std::string(to) + ")";
  std::string_view rest = to.substr(prefix.size());
  std::string spelling, closing;
  for (size_t dot = rest.find('.'); dot != std::string_view::npos; dot = rest.find('.')) {
    spelling += std::string(rest.substr(0, dot)) + ": {";
    closing += "}";
    rest.remove_prefix(dot + 1);
  }
  spelling += closing.empty() ? std::string(rest) : std::string(rest) + ": ..." + closing;
  return " (renamed: did you mean '" + spelling + "'?)";
}

}  // namespace

std::vector<std::string> documented_keys(std::span<const KeyTable* const> tables) {
  std::vector<std::string> keys;
  for (const KeyTable* t : tables)
    for (std::string_view k : t->keys)
      keys.push_back(t->section.empty() ? std::string(k)
                                        : std::string(t->section) + "." + std::string(k));
  return keys;
}

ConfigMap::ConfigMap(const ConfigNode& node, const KeyTable& table) : node_(node), table_(table) {
  if (node_.is_null()) return;
  if (!node_.is_map()) {
    node_.error("found " + node_.found() + "; expected a map with keys: " + key_list(table_.keys));
    valid_ = false;
    return;
  }
  for (std::size_t k = 0; k < node_.entries(); ++k) {
    const ConfigNode key_node = node_.key(k);
    const SourceLocation& where = key_node.location();
    if (!key_node.is_scalar()) {
      node_.diagnostics().error(
          where, node_.path(),
          "found a key that is not a plain name; expected one of: " + key_list(table_.keys));
      continue;
    }
    const std::string key(key_node.text());
    if (const Entry* first = find(key)) {
      node_.diagnostics().error(where, child_path(key),
                                "found a second '" + key + "' (the first is on line " +
                                    std::to_string(first->key_location.line) +
                                    "); expected each key once");
      continue;
    }
    entries_.push_back(Entry{key, k, where});
  }
}

std::string ConfigMap::child_path(std::string_view key) const {
  return node_.path().empty() ? std::string(key) : node_.path() + "." + std::string(key);
}

ConfigMap::Entry* ConfigMap::find(std::string_view key) {
  for (Entry& e : entries_)
    if (e.key == key) return &e;
  return nullptr;
}

void ConfigMap::check_known(std::string_view key) const {
  // A programming error, not an input error: every key the parser reads must
  // be in its table, which is what the documentation test checks.
  if (std::find(table_.keys.begin(), table_.keys.end(), key) == table_.keys.end())
    throw std::logic_error("scene parser reads key '" + std::string(key) +
                           "' that is not in the key table of '" + std::string(table_.section) +
                           "'");
}

bool ConfigMap::contains(std::string_view key) const {
  return std::any_of(entries_.begin(), entries_.end(),
                     [&](const Entry& e) { return e.key == key; });
}

std::optional<ConfigNode> ConfigMap::optional(std::string_view key) {
  check_known(key);
  Entry* e = find(key);
  if (!e) return std::nullopt;
  e->read = true;
  return node_.value(e->entry, child_path(key));
}

std::optional<ConfigNode> ConfigMap::required(std::string_view key, std::string_view expected) {
  std::optional<ConfigNode> value = optional(key);
  if (!value) report_missing(key, expected);
  return value;
}

void ConfigMap::report_missing(std::string_view key, std::string_view expected) {
  check_known(key);
  // A key that is there is not missing, whatever its value: a value that is
  // unusable (0 where a positive one is needed, an empty one) has its own
  // error at the value. Readers that ask "is a usable value there?" would
  // otherwise call `element_size: 0` missing (found by the scene fuzzer).
  if (valid_ && !contains(key))
    missing_.push_back(Missing{std::string(key), std::string(expected)});
}

void ConfigMap::read(std::string_view key, double& out, const QuantityKind& kind,
                     const Range& range) {
  if (auto v = optional(key))
    if (auto x = v->quantity(kind, range)) out = *x;
}

void ConfigMap::read_required(std::string_view key, double& out, const QuantityKind& kind,
                              const Range& range) {
  if (auto v = required(key, expectation(kind, range)))
    if (auto x = v->quantity(kind, range)) out = *x;
}

void ConfigMap::read(std::string_view key, bool& out) {
  if (auto v = optional(key))
    if (auto x = v->boolean()) out = *x;
}

void ConfigMap::read(std::string_view key, long& out, long min) {
  if (auto v = optional(key))
    if (auto x = v->integer(min)) out = *x;
}

void ConfigMap::read(std::string_view key, int& out, int min, int max) {
  if (auto v = optional(key))
    if (auto x = v->integer(min, max)) out = static_cast<int>(*x);
}

void ConfigMap::finish() {
  if (finished_) return;
  finished_ = true;
  Diagnostics& diagnostics = node_.diagnostics();
  std::vector<std::string> explained;  // missing keys that an unknown key misspells
  for (const Entry& e : entries_) {
    if (e.read) continue;
    const bool in_table =
        std::find(table_.keys.begin(), table_.keys.end(), e.key) != table_.keys.end();
    if (in_table) {
      diagnostics.error(e.key_location, child_path(e.key),
                        "found a key that has no effect here; expected it to be removed");
      continue;
    }
    std::string message = "unknown key '" + shorten(e.key) + "'";
    const std::string documented =
        table_.section.empty() ? e.key : std::string(table_.section) + "." + e.key;
    if (const std::string_view to = diagnostics.moved_to(documented); !to.empty()) {
      message += moved_note(table_.section, to);
    } else if (const auto m = closest_match(e.key, table_.keys)) {
      message += " (did you mean '" + *m + "'?)";
      explained.push_back(*m);
    }
    diagnostics.error(
        e.key_location, child_path(shorten(e.key)),
        message + "; expected one of: " + key_list(listed_.empty() ? table_.keys : listed_));
  }
  for (const Missing& m : missing_) {
    if (std::find(explained.begin(), explained.end(), m.key) != explained.end()) continue;
    diagnostics.error(node_.location(), child_path(m.key),
                      "key is missing; expected " + m.expected);
  }
}

}  // namespace fissure
