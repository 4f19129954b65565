#include "core/scene/joint_models.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/scene/scene_keys.h"

namespace fissure {

namespace {

const JointModelReader*& installed() {
  static const JointModelReader* reader = nullptr;
  return reader;
}

/// core's keys, then the reader's (the storage of joint_entry_keys()).
std::vector<std::string_view>& entry_keys() {
  static std::vector<std::string_view> keys;
  return keys;
}

}  // namespace

void install_joint_model_reader(const JointModelReader* reader) {
  installed() = reader;
  std::vector<std::string_view>& keys = entry_keys();
  keys.assign(scene_keys::joint.keys.begin(), scene_keys::joint.keys.end());
  if (reader) keys.insert(keys.end(), reader->keys->keys.begin(), reader->keys->keys.end());
}

const JointModelReader* joint_model_reader() {
  return installed();
}

const KeyTable& joint_entry_keys() {
  static KeyTable table{scene_keys::joint.section, {}};
  if (entry_keys().empty()) install_joint_model_reader(installed());
  table.keys = entry_keys();
  return table;
}

double largest_compression(const Eigen::Vector3d& stress) {
  const double mean = (stress[0] + stress[1]) / 2;
  const double radius = std::hypot((stress[0] - stress[1]) / 2, stress[2]);
  return std::max(0.0, -(mean - radius));
}

void check_joint_stress_limit(const ConfigNode& node, const Eigen::Vector3d& stress,
                              const JointProperties& joint) {
  const double compression = largest_compression(stress);
  if (compression < joint.largest_normal_stress) return;
  node.error(fmt::format(
      "found {} with a largest compression of {:.4g} MPa, not below joint '{}''s {} ({:.4g} "
      "MPa, the largest normal stress its model holds for); expected a larger {} or a smaller "
      "initial stress",
      node.found(), compression / 1e6, joint.name, joint.largest_normal_stress_key,
      joint.largest_normal_stress / 1e6, joint.largest_normal_stress_key));
}

}  // namespace fissure
