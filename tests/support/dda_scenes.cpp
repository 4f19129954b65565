#include "tests/support/dda_scenes.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "mechanics/dda/dda_settings.h"

namespace fissure::testing {

namespace {
constexpr double deg = std::numbers::pi / 180;
}

Polygon rectangle(double w, double h, double angle, const Vec2& offset) {
  const double c = std::cos(angle), s = std::sin(angle);
  std::vector<Vec2> v;
  for (const Vec2& p : {Vec2(0, 0), Vec2(w, 0), Vec2(w, h), Vec2(0, h)})
    v.push_back(offset + Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y()));
  return Polygon(std::move(v));
}

Scene base_scene(double young_modulus, double friction_deg, double g) {
  Scene s;
  s.name = "test";
  s.physics = {"mechanics"};
  s.gravity = Vec2(0, -g);
  s.materials.push_back({"rock", 2700, young_modulus, 0.25});
  s.joints.push_back({"joint", friction_deg * deg, 0, 0});
  mechanics_controls(s).plane = PlaneMode::Strain;
  s.output.hdf5 = false;
  return s;
}

BlockSpec block(const std::string& name, Polygon polygon, bool fixed) {
  BlockSpec b;
  b.name = name;
  b.polygon = std::move(polygon);
  b.fixed = fixed;
  return b;
}

Scene incline_scene(double slope_deg, double friction_deg, double dt, double penalty,
                    double end_time, double width, double height) {
  Scene s = base_scene(10e9, friction_deg);
  const double a = slope_deg * deg;
  // Slab along the slope, its top surface through the origin; block near the top end.
  s.blocks.push_back(
      block("base",
            rectangle(14, 1, a, Vec2(std::sin(a), -std::cos(a)) + Vec2(-std::cos(a), -std::sin(a))),
            true));
  const Vec2 start = Vec2(std::cos(a), std::sin(a)) * 9.0;
  s.blocks.push_back(block("block", rectangle(width, height, a, start)));
  const double x = width / 2, y = height / 2;
  s.monitors.push_back(
      {"block", start + Vec2(x * std::cos(a) - y * std::sin(a), x * std::sin(a) + y * std::cos(a)),
       1});
  mechanics_controls(s).dda.max_time_step = dt;
  mechanics_controls(s).dda.penalty = penalty;
  s.time.end_time = end_time;
  return s;
}

Scene brick_wall_scene(int courses, int bricks, double w, double h, double friction_deg, double dt,
                       double penalty, double end_time) {
  Scene s = base_scene(10e9, friction_deg);
  const double length = bricks * w;
  s.blocks.push_back(block("base", rectangle(length + 2, 1, 0, Vec2(-1, -1)), true));
  for (int c = 0; c < courses; ++c) {
    const double y = c * h;
    std::vector<std::pair<double, double>> spans;  // (x0, width)
    if (c % 2 == 0) {
      for (int b = 0; b < bricks; ++b) spans.emplace_back(b * w, w);
    } else {
      spans.emplace_back(0, w / 2);
      for (int b = 0; b < bricks - 1; ++b) spans.emplace_back(w / 2 + b * w, w);
      spans.emplace_back(length - w / 2, w / 2);
    }
    for (const auto& [x0, bw] : spans)
      s.blocks.push_back(block("brick_" + std::to_string(c) + "_" + std::to_string(s.blocks.size()),
                               rectangle(bw, h, 0, Vec2(x0, y))));
  }
  // Middle brick of the top course.
  const int n_top = (courses - 1) % 2 == 0 ? bricks : bricks + 1;
  const int top = static_cast<int>(s.blocks.size()) - n_top + n_top / 2;
  const SectionProperties sp = section_properties(s.blocks[top].polygon);
  s.monitors.push_back({"top", sp.centroid, top});
  mechanics_controls(s).dda.max_time_step = dt;
  mechanics_controls(s).dda.penalty = penalty;
  s.time.end_time = end_time;
  return s;
}

void use_augmented_lagrangian(Scene& s, double tolerance) {
  DdaControls& dda = mechanics_controls(s).dda;
  dda.contact_method = ContactMethod::AugmentedLagrangian;
  dda.penetration_tolerance = tolerance;
}

Scene block_pile_scene(int nx, int ny, double a, double gap, double dt, double end_time) {
  Scene s = base_scene(10e9, 30);
  const double width = nx * (a + gap);
  s.blocks.push_back(block("floor", rectangle(width + 2 * a, a, 0, Vec2(-a, -a)), true));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      s.blocks.push_back(
          block(fmt::format("b{}", s.blocks.size()),
                rectangle(a, a, 0, Vec2(i * (a + gap) + gap / 2, gap + j * (a + gap)))));
  mechanics_controls(s).dda.max_time_step = dt;
  mechanics_controls(s).dda.max_displacement_ratio = 0.01;
  s.time.end_time = end_time;
  return s;
}

Scene block_above_base_scene(double gap, double dt) {
  Scene s = base_scene(10e9, 30, 9.81);
  s.blocks.push_back(block("base", rectangle(3, 1, 0, Vec2(-1, -1)), true));
  s.blocks.push_back(block("block", rectangle(1, 0.5, 0, Vec2(0, gap))));
  mechanics_controls(s).dda.max_time_step = dt;
  mechanics_controls(s).dda.velocity_carry_over = 0;
  return s;
}

}  // namespace fissure::testing
