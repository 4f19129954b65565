// Runs of the continuum process driven directly (no output files), for the
// verification tests and the benchmarks: a scene of configs/ with its
// controls changed, advanced in fixed steps, and the fields at a point.
#pragma once

#include <string>

#include "continuum/poroelasticity/continuum_process.h"
#include "core/scene/scene.h"
#include "core/state/rock_mass.h"

namespace fissure::testing {

/// A scene file of configs/ ("continuum_mandel.yaml"), read.
Scene continuum_scene(const std::string& config);

class ContinuumRun {
 public:
  explicit ContinuumRun(const Scene& scene);
  /// Steps of dt until t (the last one shortened to land on it).
  void advance_to(double t, double dt);
  continuum::PointValues at(const Vec2& x) const;
  double time() const { return t_; }
  const continuum::ContinuumProcess& process() const { return process_; }

 private:
  continuum::ContinuumProcess process_;
  RockMass state_;
  double t_ = 0;
};

}  // namespace fissure::testing
