#include "tests/support/thermal_runs.h"

#include <fmt/format.h>
#include <Eigen/Dense>
#include <limits>

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
  return state.fields.get(thermal::kThermalState);
}
thermal::ThermalState& ThermalRun::thermal() {
  return state.fields.get(thermal::kThermalState);
}

double ThermalRun::temperature_at(const Vec2& p) const {
  const thermal::ThermalMesh& mesh = process->mesh();
  const std::vector<double>& t = thermal().temperature;
  double best = -std::numeric_limits<double>::infinity(), value = 0;
  for (const auto& tri : mesh.triangles) {
    const Vec2 &p0 = mesh.nodes[tri[0]], &p1 = mesh.nodes[tri[1]], &p2 = mesh.nodes[tri[2]];
    Eigen::Matrix2d j;
    j << (p1 - p0), (p2 - p0);
    const Vec2 st = j.inverse() * (p - p0);
    const Eigen::Vector3d w(1 - st.x() - st.y(), st.x(), st.y());
    if (w.minCoeff() > best) {
      best = w.minCoeff();
      value = w[0] * t[tri[0]] + w[1] * t[tri[1]] + w[2] * t[tri[2]];
    }
  }
  return best > -1e-9 ? value : std::numeric_limits<double>::quiet_NaN();
}

std::vector<Vec2> box(double x0, double y0, double x1, double y1) {
  return {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)};
}

}  // namespace fissure::testing
