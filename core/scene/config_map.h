// Reads the keys of one YAML map and reports, when it goes out of scope, every
// key nobody read: "unknown key 'denisty' (did you mean 'density'?); expected
// one of: name, density, young_modulus, poisson_ratio". Each map's keys come
// from a KeyTable (scene_keys.h), the same tables that list the documented
// keys, so the parser cannot read a key the documentation does not know.
#pragma once

#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/scene/config_node.h"

namespace fissure {

/// The keys one map in a scene may hold. `section` is the map's documented
/// path: "" for the document, "materials[]" for each item of `materials`,
/// "section.part" for a nested map.
struct KeyTable {
  std::string_view section;
  std::span<const std::string_view> keys;
};

/// A key that a module's section took over from a shared map, or that was
/// renamed: `from` is its old documented path ("materials[].KEY"), `to` its
/// new one. An old scene that still has it gets the unknown-key error with
/// "moved to `to`", or, renamed within its map, "renamed: did you mean
/// 'NEW'?".
struct MovedKey {
  std::string_view from;
  std::string_view to;
};

/// Every key of the tables as its documented path ("section.key", or "key"
/// for the document's own map), for the tests that check the docs.
std::vector<std::string> documented_keys(std::span<const KeyTable* const> tables);

class ConfigMap {
 public:
  /// A node that is neither a map nor empty is reported (and reads as empty).
  ConfigMap(const ConfigNode& node, const KeyTable& table);
  ~ConfigMap() { finish(); }
  ConfigMap(const ConfigMap&) = delete;
  ConfigMap& operator=(const ConfigMap&) = delete;

  const ConfigNode& node() const { return node_; }
  /// False when the node was not a map (its keys are then not reported missing).
  bool valid() const { return valid_; }
  /// Whether `key` is present; does not count as reading it.
  bool contains(std::string_view key) const;

  /// The value of `key`, marked as read; nothing when absent.
  std::optional<ConfigNode> optional(std::string_view key);
  /// Same; when absent, reports "key is missing; expected `expected`".
  std::optional<ConfigNode> required(std::string_view key, std::string_view expected);
  /// Reports `key` missing (for keys that are required only in some
  /// scenes); nothing when the key is there (its value has its own error).
  void report_missing(std::string_view key, std::string_view expected);

  // Shortcuts: `out` is set when the key is present and valid, and keeps its
  // default otherwise.
  void read(std::string_view key, double& out, const QuantityKind& kind,
            const Range& range = Range::any());
  void read_required(std::string_view key, double& out, const QuantityKind& kind,
                     const Range& range = Range::any());
  void read(std::string_view key, bool& out);
  void read(std::string_view key, long& out, long min);
  void read(std::string_view key, int& out, int min, int max = std::numeric_limits<int>::max());

  /// The keys an unknown key's message lists (default: the table's): a map
  /// whose keys depend on one of its values (a joint's `model`) lists the
  /// keys that value allows. `keys` must outlive the map.
  void list_keys(std::span<const std::string_view> keys) { listed_ = keys; }

  /// Reports the keys nobody read, and the missing required keys (a missing
  /// key that an unknown key is a misspelling of is reported once, as the
  /// misspelling). Called by the destructor; idempotent.
  void finish();

 private:
  struct Entry {
    std::string key;
    std::size_t entry;  // in node_'s entries
    SourceLocation key_location;
    bool read = false;
  };
  struct Missing {
    std::string key;
    std::string expected;
  };

  std::string child_path(std::string_view key) const;
  Entry* find(std::string_view key);
  void check_known(std::string_view key) const;

  ConfigNode node_;
  KeyTable table_;
  std::span<const std::string_view> listed_;  ///< empty: table_.keys
  bool valid_ = true;
  bool finished_ = false;
  std::vector<Entry> entries_;
  std::vector<Missing> missing_;
};

}  // namespace fissure
