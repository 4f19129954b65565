// The thermal process's inner state in checkpoints (core/io/checkpoint.h):
// temperatures, the previous step (BDF2), the fluid, the energy balance and
// the counters.
#include "core/base/errors.h"
#include "core/io/checkpoint.h"
#include "thermal/conduction/thermal_process.h"

namespace fissure::thermal {

template <class Archive>
void ThermalProcess::checkpoint(Archive& a, RockMass& state) {
  ThermalState& s = state.fields.get_or_add(kThermalState);
  a("temperature", s.temperature);
  a("previous_temperature", s.previous_temperature);
  a("previous_dt", s.previous_dt);
  a("closed", s.closed);
  a("next_dt", s.next_dt);
  a("last_max_change", s.last_max_change);
  EnergyBalance& b = s.balance;
  a("stored", b.stored);
  a("supplied", b.supplied);
  a("boundary", b.boundary);
  a("last_step_stored", b.last_step_stored);
  a("last_step_supplied", b.last_step_supplied);
  a("last_step_boundary", b.last_step_boundary);
  if (fluid_) {
    a("fluid_temperature", s.fluid_temperature);
    a("previous_fluid_temperature", s.previous_fluid_temperature);
    for (auto* f : {&b.fluid, &b.last_step_fluid}) {
      auto part = a.section(f == &b.fluid ? "fluid" : "last_step_fluid");
      part("stored", f->stored);
      part("advected_in", f->advected_in);
      part("advected_out", f->advected_out);
      part("exchanged", f->exchanged);
    }
  }
  a("steps", counters_.steps);
  a("rejected_steps", counters_.rejected_steps);
  a("smallest_step", counters_.smallest_step);
  a("largest_step", counters_.largest_step);
  a("largest_change", counters_.largest_change);
  a("system_builds", counters_.system_builds);
  a("step_seconds", counters_.step_seconds);
  solver_.checkpoint_counters(a);
  // The coefficient of the solver's matrix, which a restart's first step
  // takes (advance); older checkpoints lack it.
  if constexpr (Archive::reading) {
    if (a.has("matrix_coefficient")) a("matrix_coefficient", restored_coefficient_);
  } else {
    a("matrix_coefficient", matrix_coefficient_);
  }
}

void ThermalProcess::save(CheckpointWriter& out, const RockMass& state) const {
  const_cast<ThermalProcess*>(this)->checkpoint(out, const_cast<RockMass&>(state));
}

void ThermalProcess::restore(CheckpointReader& in, RockMass& state) {
  checkpoint(in, state);
  const ThermalState& s = state.fields.get(kThermalState);
  FISSURE_CHECK(static_cast<int>(s.temperature.size()) == mesh_.n_nodes() &&
                    s.previous_temperature.size() == s.temperature.size() &&
                    s.closed.size() == mesh_.boundary_edges.size(),
                IoError,
                "the checkpoint's thermal mesh ("
                    << s.temperature.size() << " nodes) is not the scene's (" << mesh_.n_nodes()
                    << " nodes)");
  FISSURE_CHECK(!fluid_ || !fluid_->built() ||
                    static_cast<int>(s.fluid_temperature.size()) == fluid_->n_nodes(),
                IoError,
                "the checkpoint's fracture water (" << s.fluid_temperature.size()
                                                    << " fluid nodes) is not the scene's ("
                                                    << fluid_->n_nodes() << " fluid nodes)");
  publish(state);
}

}  // namespace fissure::thermal
