#include "tests/support/thermal_runs.h"

#include <fmt/format.h>
#include <Eigen/Dense>
#include <limits>
#include <stdexcept>

#include "coupling/coordinator.h"

namespace fissure::testing {

Scene thermal_scene(const std::vector<std::vector<Vec2>>& blocks, const ThermalControls& controls,
                    const ThermalMaterial& material) {
  Scene scene;
  scene.name = "thermal_test";
  scene.physics = {"thermal"};
  scene.gravity = Eigen::Vector2d::Zero();
  scene.materials.push_back({"rock", 2700, 10e9, 0.25});
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    BlockSpec spec;
    spec.name = fmt::format("b{}", b);
    spec.polygon = Polygon(blocks[b]);
    scene.blocks.push_back(spec);
  }
  ThermalControls& c = thermal_controls(scene);
  c = controls;
  c.materials = {material};
  return scene;
}

ThermalRun::ThermalRun(const Scene& s)
    : scene(s),
      state(RockMass::from_scene(scene)),
      process(std::make_unique<thermal::ThermalProcess>(scene)) {
  process->initialize(state);
}

void ThermalRun::run(double dt, int steps) {
  for (int k = 0; k < steps; ++k) {
    process->advance(state, state.time, dt);
    state.time += dt;
  }
}

const thermal::ThermalState& ThermalRun::thermal() const {
  return process->inner_state();
}

double ThermalRun::temperature_at(const Vec2& p) const {
  const thermal::ThermalMesh& mesh = process->mesh();
  const thermal::ThermalMesh::Place place = mesh.locate(p, -1);
  if (place.triangle < 0 || place.weights.minCoeff() < -1e-9)
    return std::numeric_limits<double>::quiet_NaN();
  const std::vector<double>& t = thermal().temperature;
  const auto& tri = mesh.triangles[place.triangle];
  return place.weights.dot(Eigen::Vector3d(t[tri[0]], t[tri[1]], t[tri[2]]));
}

const thermal::ThermalState& thermal_state(const RunResult& run) {
  const Process* p = run.coordinator ? run.coordinator->process("thermal") : nullptr;
  const auto* thermal = dynamic_cast<const thermal::ThermalProcess*>(p);
  if (!thermal) throw std::logic_error("the run has no thermal process");
  return thermal->inner_state();
}

std::vector<Vec2> box(double x0, double y0, double x1, double y1) {
  return {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)};
}

ThermalControls line_source_controls(double h, double h_source, double grading, double initial) {
  ThermalControls c;
  c.element_size = h;
  c.source_element_size = h_source;
  c.size_grading = grading;
  c.initial_temperature = initial;
  c.scheme = ThermalControls::Scheme::Bdf2;
  HeatSource heater;
  heater.name = "heater";
  heater.points = {Vec2(0, 0)};
  heater.power = 1000;
  heater.path = "line source";
  c.sources = {heater};
  return c;
}

}  // namespace fissure::testing
