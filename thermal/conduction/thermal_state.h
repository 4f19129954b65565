// What the thermal process carries from step to step, kept in the shared
// state (RockMass::fields) so that the coordinator's snapshot of a coupling
// step (a retry, an iterated scheme) takes it back with everything else.
// Read by the thermal output (results, monitors); the other processes read
// kBlockThermalStrain (rockmass/fields/block_thermal_strain.h).
#pragma once

#include <vector>

#include "core/base/named_values.h"

namespace fissure::thermal {

/// The energy terms (J per metre of thickness) since the start.
struct EnergyBalance {
  double stored = 0;    ///< sum C_i (T_i - T_i(0))
  double supplied = 0;  ///< by the sources
  double boundary = 0;  ///< into the rock through its boundaries
  double last_step_stored = 0, last_step_supplied = 0, last_step_boundary = 0;
  /// The fracture water (thermal.convection): stored in it, carried in and
  /// out of the network by it, and given by it to the blocks' walls.
  struct Fluid {
    double stored = 0, advected_in = 0, advected_out = 0, exchanged = 0;
    double carried() const { return stored - advected_in + advected_out; }
  } fluid, last_step_fluid;
  /// Rock and water: what they store against what comes in (the exchange
  /// between them cancels).
  double residual() const { return stored - supplied - boundary + fluid.carried(); }
  double last_step_residual() const {
    return last_step_stored - last_step_supplied - last_step_boundary + last_step_fluid.carried();
  }
};

struct ThermalState {
  std::vector<double> temperature;           ///< per mesh node, degC
  std::vector<double> previous_temperature;  ///< at the step before (BDF2)
  double previous_dt = 0;                    ///< 0: none (BDF2 starts with backward Euler)
  std::vector<char> closed;                  ///< per mesh boundary edge: a closed joint face
  /// The adaptive step (thermal.max_temperature_change): the step proposed
  /// next (0: thermal.time_step), and the largest nodal |dT| of the last
  /// accepted step (K, fixed temperatures excluded).
  double next_dt = 0;
  double last_max_change = 0;
  /// The fracture water (thermal.convection): per node of the fluid grid
  /// (thermal/convection/fracture_fluid_grid.h), degC, and at the step before.
  std::vector<double> fluid_temperature, previous_fluid_temperature;
  EnergyBalance balance;
  /// Per block: its mean temperature minus its stress-free reference (the
  /// mean initial temperature), K. Derived from `temperature` (not
  /// checkpointed: restore recomputes it); the free thermal strain published
  /// for the mechanics is alpha_T times this.
  std::vector<double> block_temperature_change;
};

inline constexpr Key<ThermalState> kThermalState{"thermal_state"};

}  // namespace fissure::thermal
