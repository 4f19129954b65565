#include "tests/support/continuum_runs.h"

#include <algorithm>

#include "coupling/process_registry.h"

namespace fissure::testing {

Scene continuum_scene(const std::string& config) {
  return read_scene(std::string(FISSURE_SOURCE_DIR "/configs/") + config);
}

ContinuumRun::ContinuumRun(const Scene& scene)
    : process_(scene), state_(RockMass::from_scene(scene)) {
  process_.initialize(state_);
}

void ContinuumRun::advance_to(double t, double dt) {
  while (t_ < t * (1 - 1e-12)) {
    const double step = std::min(dt, t - t_);
    process_.advance(state_, t_, step);
    t_ += step;
  }
}

continuum::PointValues ContinuumRun::at(const Vec2& x) const {
  const continuum::ContinuumMesh::Place place = process_.mesh().locate(x);
  return process_.values_in(place.triangle, place.weights);
}

}  // namespace fissure::testing
