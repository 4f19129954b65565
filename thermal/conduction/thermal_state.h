// What the thermal process carries from step to step: its inner state,
// held by ThermalProcess and saved and restored with its save()/restore()
// (a checkpoint, and the coordinator's rollback of a coupling step, as every
// process's inner state: coupling/step_rollback.cpp). Read by the thermal
// output (results, monitors, summary.json); the other processes read only
// what the process publishes in the shared state: kBlockThermalStrain
// (rockmass/fields/block_thermal_strain.h) and kFractureFluidTemperature
// (rockmass/fields/fracture_temperature.h).
#pragma once

#include <vector>

namespace fissure::thermal {

/// The energy terms (J per metre of thickness) since the start.
/// The balance is the one the time scheme conserves (docs/thermal.md 5):
/// per step, summing every row, a0 dE_{n+1} - a2 dE_n = dt Q_{n+1} with
/// dE = sum C_i dT_i and Q the sources' and boundaries' power at t_{n+1}.
/// So stored + bdf2_correction (the BDF2 difference summed over the steps)
/// equals supplied + boundary to round-off; with backward Euler the
/// correction is 0.
struct EnergyBalance {
  double stored = 0;  ///< sum C_i (T_i - T_i(0))
  /// Sum over the steps of (a0 - 1) dE_{n+1} - a2 dE_n: what BDF2's
  /// difference adds to the stored change (0 with backward Euler).
  double bdf2_correction = 0;
  double supplied = 0;  ///< by the sources
  double boundary = 0;  ///< into the rock through its boundaries
  double last_step_stored = 0, last_step_bdf2_correction = 0, last_step_supplied = 0,
         last_step_boundary = 0;
  /// The fracture water (thermal.convection): stored in it (and its BDF2
  /// correction), carried in and out of the network by it, and given by it
  /// to the blocks' walls.
  struct Fluid {
    double stored = 0, bdf2_correction = 0, advected_in = 0, advected_out = 0, exchanged = 0;
    double carried() const { return stored + bdf2_correction - advected_in + advected_out; }
  } fluid, last_step_fluid;
  /// Rock and water: what they store against what comes in (the exchange
  /// between them cancels).
  double residual() const {
    return stored + bdf2_correction - supplied - boundary + fluid.carried();
  }
  double last_step_residual() const {
    return last_step_stored + last_step_bdf2_correction - last_step_supplied - last_step_boundary +
           last_step_fluid.carried();
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

}  // namespace fissure::thermal
