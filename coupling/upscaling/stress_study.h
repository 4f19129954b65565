// The REV study under stress (`fissure rev` with a `mechanics` section;
// docs/upscaling.md; Min, Rutqvist, Tsang and Jing 2004): the geometric
// study's domains, sizes and realizations, solved once per stress state by
// the stress stage (stressed_domain.h). Each state is given as the total
// stress and the pore pressure; the domains carry the effective stress
// sigma' = sigma + p I (tension +), the square aligned with its principal
// axes, and the tensor is reported in the study's frame.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "core/scene/config_node.h"
#include "coupling/upscaling/scene_rock_mass_source.h"
#include "coupling/upscaling/stressed_domain.h"
#include "flow/rev/rev_study.h"

namespace fissure {

/// One stress state of the study.
struct StressState {
  Eigen::Vector3d stress = Eigen::Vector3d::Zero();  ///< total sxx, syy, sxy (Pa, tension +)
  std::string location;  ///< "file:line:column: mechanics.stresses[i]", for messages
  int index = 0;         ///< i: its place in mechanics.stresses (the outputs' `state`)
};

/// The effective principal stresses of a state (Pa, compression +; sigma_1
/// >= sigma_3) and sigma_1's direction from x (rad, in [0, pi)).
struct PrincipalStress {
  double sigma_1 = 0, sigma_3 = 0, angle = 0;
  double mean() const { return 0.5 * (sigma_1 + sigma_3); }
  /// sigma_1 / sigma_3 (infinite when sigma_3 <= 0).
  double ratio() const;
};
PrincipalStress effective_principal(const Eigen::Vector3d& stress, double pore_pressure);

/// The `mechanics` section of a study.
struct StressStudyConfig {
  std::vector<StressState> states;
  double pore_pressure = 0;  ///< Pa
  /// flow.hm's law (the fractures whose joint has no model).
  flow::HmApertureLaw aperture_law;
  /// The compliance's stress increment (Pa; `compliance.increment`); 0: no
  /// compliance.
  double compliance_increment = 0;
  std::string location;  ///< of the section, for messages
};

/// Reads the section (problems on its nodes).
void read_stress_study(const ConfigNode& node, StressStudyConfig& config);
/// Its keys with their documented paths, for the documentation test.
std::vector<std::string> stress_study_keys();

/// The study's settings checked against its rock-mass scene: its block
/// process solves an update to rest (the DEM with dem.solve_ratio), the
/// joints whose model limits the normal stress (Barton-Bandis's JCS) hold
/// every state, the network turns only in quarter turns. Throws SceneError.
/// Returns the scene the domains are cut with (no blocks, monitors or
/// loads; gravity off; the block process alone).
std::shared_ptr<const Scene> stress_stage_scene(const flow::RevStudyConfig& study,
                                                const StressStudyConfig& config,
                                                const Scene& rock_mass_scene);

struct StressStateResult {
  StressState state;
  PrincipalStress principal;
  flow::RevStudyResult rev;
};

/// Every state's study (rank 0 holds the results).
std::vector<StressStateResult> run_stress_study(const flow::RevStudyConfig& study,
                                                const StressStudyConfig& config,
                                                const SceneRockMassSource& source,
                                                const flow::ParallelContext& parallel);

/// The mechanics of a state's squares of one size (the first rotation):
/// means over them.
struct SizeMechanics {
  double slip = 0, slip_std = 0, equilibrium = 0, blocks = 0, cycles = 0, seconds = 0;
  /// Of the squares whose compliance was measured: the moduli along
  /// sigma_1 and sigma_3 (1/C11, 1/C22, Pa), -C21/C11, and the shear
  /// modulus 1/C33 (Pa) in the principal frame.
  int measured = 0;
  double e1 = 0, e1_std = 0, e3 = 0, e3_std = 0, nu = 0, g13 = 0, g13_std = 0;
};
SizeMechanics size_mechanics(const flow::RevStudyResult& result, int size_index);

/// stress_states.csv, stress_domains.csv and stress.json in `outdir`.
void write_stress_study(const std::vector<StressStateResult>& results, const std::string& outdir);

}  // namespace fissure
