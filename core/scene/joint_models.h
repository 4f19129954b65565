// The joints' constitutive models as core sees them (docs/scene-reference.md
// section 4): core reads a `joints[]` entry's name and the Coulomb keys every
// joint has; the laws themselves live below the physics (rockmass/joints/),
// which core does not know, so their module supplies the reader of the
// entry's `model` and the model's own keys, and the registry installs it
// with the scene sections (coupling/process_registry.cpp). Without one, an
// entry has the Coulomb keys alone.
#pragma once

#include <Eigen/Core>
#include <span>
#include <string_view>

#include "core/scene/config_map.h"
#include "core/scene/scene.h"

namespace fissure {

struct JointModelReader {
  /// The keys it reads ("joints[]" keys beside core's).
  const KeyTable* keys = nullptr;
  /// Reads them from the entry into `joint` (after core has read the
  /// Coulomb keys); problems go to the entry's diagnostics.
  void (*read)(ConfigMap& entry, JointProperties& joint) = nullptr;
};

/// Installs the reader (null: none).
void install_joint_model_reader(const JointModelReader* reader);
/// The installed reader, or null.
const JointModelReader* joint_model_reader();
/// The keys of a `joints[]` entry: core's and the installed reader's.
const KeyTable& joint_entry_keys();

/// The largest compression (Pa, compression positive) on any plane under
/// the plane stress [sxx, syy, sxy] (tension positive): minus the smaller
/// principal stress; 0 when none is compressive.
double largest_compression(const Eigen::Vector3d& stress);

/// Reports at `node` (an initial stress) when its largest compression
/// reaches the largest normal stress `joint`'s model holds for: the one
/// check of a joint's strength against the scene's stresses that can be
/// made before anything runs.
void check_joint_stress_limit(const ConfigNode& node, const Eigen::Vector3d& stress,
                              const JointProperties& joint);

}  // namespace fissure
