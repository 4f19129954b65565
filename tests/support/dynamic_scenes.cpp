#include "tests/support/dynamic_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include <fmt/format.h>

#include "coupling/process_registry.h"

namespace fissure::testing {

namespace {

/// Writes `s` as a csv record (t, x, y) to `file`.
void write_record(const std::string& file, const MotionSamples& s) {
  std::ofstream out(file);
  out << "t,x,y\n";
  for (std::size_t k = 0; k < s.t.size(); ++k)
    out << fmt::format("{:.17g},{:.17g},{:.17g}\n", s.t[k], s.x[k], s.y.empty() ? 0.0 : s.y[k]);
  EXPECT_TRUE(out.good()) << "cannot write " << file;
}

}  // namespace

double shear_wave_speed(double modulus, double poisson_ratio, double density) {
  return std::sqrt(modulus / (2 * (1 + poisson_ratio)) / density);
}

Scene layer_on_viscous_base(const LayerSpec& spec, const MotionSamples& outcrop_velocity,
                            const std::string& dir) {
  const std::string record = dir + "/outcrop_velocity.csv";
  write_record(record, outcrop_velocity);
  const double h = spec.height / spec.layers, w = spec.width;
  std::string blocks;
  for (int i = 0; i < spec.layers; ++i)
    blocks += fmt::format(
        "  - {{name: b{}, material: soil, vertices: [[0, {:.17g}], [{:.17g}, "
        "{:.17g}], [{:.17g}, {:.17g}], [0, {:.17g}]]}}\n",
        i, i * h, w, i * h, w, (i + 1) * h, (i + 1) * h);
  // Glued joints: cohesion and tension far above any wave's stress.
  const std::string text = fmt::format(
      R"(name: layer_on_viscous_base
physics: [mechanics]
gravity: [0, 0]
materials:
  - {{name: soil, density: {0}, young_modulus: {1}, poisson_ratio: {2}}}
  - {{name: bedrock, density: {0}, young_modulus: {3}, poisson_ratio: {2}}}
joints:
  - {{name: glued, friction_angle: 45, cohesion: 1 GPa, tensile_strength: 1 GPa}}
blocks:
{4}monitors:
  - {{name: top, point: [{5}, {6}], block: b{7}}}
mechanics:
  dda:
    time_step: {8}
    penalty: {9}
    damping_ratio: 0
  ground_motion:
    file: {10}
    quantity: velocity
  viscous_boundaries:
    - {{line: [[0, 0], [{11}, 0]], material: bedrock, free_field: true}}
time:
  end: {12}
output:
  interval: {13}
  hdf5: false
)",
      spec.density, spec.soil_modulus, spec.poisson_ratio, spec.bedrock_modulus, blocks, w / 2,
      spec.height - 1e-3 * h, spec.layers - 1, spec.time_step, spec.penalty, record, w, spec.end,
      spec.output_interval);
  return read_scene_text(text, dir + "/layer_on_viscous_base.yaml");
}

Scene block_on_shaken_plane(const ShakenBlockSpec& spec, const MotionSamples& base_acceleration,
                            const std::string& dir) {
  const std::string record = dir + "/base_acceleration.csv";
  write_record(record, base_acceleration);
  const double a = spec.slope * std::numbers::pi / 180;
  const Vec2 d(std::cos(a), std::sin(a)), n(-std::sin(a), std::cos(a));
  const auto point = [](const Vec2& p) { return fmt::format("[{:.17g}, {:.17g}]", p.x(), p.y()); };
  const double length = 20, depth = 2;
  const std::string base =
      fmt::format("[{}, {}, {}, {}]", point(-length * d - depth * n), point(length * d - depth * n),
                  point(length * d), point(-length * d));
  const std::string block = fmt::format("[{}, {}, {}, {}]", point(-0.5 * d), point(0.5 * d),
                                        point(0.5 * d + 0.5 * n), point(-0.5 * d + 0.5 * n));
  const std::string text = fmt::format(
      R"(name: block_on_shaken_plane
physics: [mechanics]
gravity: [0, -9.81]
materials:
  - {{name: rock, density: 2700, young_modulus: 10 GPa, poisson_ratio: 0.25}}
joints:
  - {{name: plane, friction_angle: {0}}}
blocks:
  - {{name: base, vertices: {1}, fixed: true}}
  - {{name: block, vertices: {2}}}
monitors:
  - {{name: block, point: {3}, block: block}}
  - {{name: base, point: {4}, block: base}}
mechanics:
  dda:
    time_step: {5}
    penalty: {6}
    damping_ratio: 0
  ground_motion:
    file: {7}
    baseline_correction: false
time:
  end: {8}
output:
  interval: {9}
  hdf5: false
)",
      spec.friction_angle, base, block, point(0.25 * n), point(-1.0 * n), spec.time_step,
      spec.penalty, record, spec.end, spec.output_interval);
  return read_scene_text(text, dir + "/block_on_shaken_plane.yaml");
}

}  // namespace fissure::testing
