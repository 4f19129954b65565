// Names of the items of one scene list (materials, joints, blocks): checks
// that they are unique and resolves references to them, with "did you mean".
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/scene/config_node.h"

namespace fissure {

class NameRegistry {
 public:
  /// `what` names one item in messages: "material".
  explicit NameRegistry(std::string what) : what_(std::move(what)) {}

  /// Adds the name of the next item (index = number added so far). A name
  /// already taken is reported at `node`.
  void add(const std::string& name, const ConfigNode& node);
  /// Adds a placeholder for an item whose name could not be read; references
  /// to unknown names are then not reported (they may mean that item).
  void add_unreadable();

  int size() const { return static_cast<int>(names_.size()); }
  const std::vector<std::string>& names() const { return names_; }
  /// Index of `name`, or -1.
  int find(std::string_view name) const;

  /// Reads a reference to an item at `node`: its index, or nothing after
  /// reporting "found 'granit' (did you mean 'granite'?); expected the name
  /// of a material: granite, sandstone".
  std::optional<int> resolve(const ConfigNode& node) const;

 private:
  std::string what_;
  std::vector<std::string> names_;
  std::vector<SourceLocation> where_;
  /// First index of each name: generated rock masses add 1e4..1e5 blocks.
  std::unordered_map<std::string, int> index_;
  bool complete_ = true;
};

}  // namespace fissure
