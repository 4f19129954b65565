// A small hand-made rock mass for the output tests (core/io): a fixed base,
// a concave L-shaped block and a square ring (a block with a hole), one
// monitor on the ring, and a motion whose every number is an exact binary
// fraction, so values read back from the files can be compared with ==.
#pragma once

#include <vector>

#include "core/state/rock_mass.h"
#include "rockmass/fields/contacts.h"

namespace fissure::test {

/// Frame k is at t = 0.25 k; the L moves by k (0.125, -0.25), the ring by
/// k (0.0625, 0.5); frame k has k % 4 contacts.
inline double frame_time(int k) {
  return 0.25 * k;
}
inline Vec2 ell_shift(int k) {
  return k * Vec2(0.125, -0.25);
}
inline Vec2 ring_shift(int k) {
  return k * Vec2(0.0625, 0.5);
}

inline std::vector<Monitor> output_test_monitors() {
  Monitor top;
  top.name = "top";
  top.point = Vec2(3, 2.75);
  top.block = 2;
  Monitor still;
  still.name = "still";
  still.point = Vec2(-1, 5);
  still.block = -1;
  return {top, still};
}

inline Block make_output_test_block(const std::string& name, Polygon polygon) {
  Block b;
  b.name = name;
  b.polygon = std::move(polygon);
  b.initial_vertices = b.polygon.vertices;
  b.edge_joint.assign(b.polygon.vertices.size(), 0);
  b.section = section_properties(b.polygon);
  return b;
}

/// The state at t = 0.
inline RockMass output_test_state() {
  RockMass s;
  s.materials.push_back(Material{"granite", 2700, 5e10, 0.25});
  s.joints.push_back(JointProperties{"joint", 0.5, 0, 0});

  Block base = make_output_test_block("base", Polygon({{0, 0}, {4, 0}, {4, 1}, {0, 1}}));
  base.fixed = true;
  s.blocks.push_back(base);

  // Concave: an L with its re-entrant corner at (1, 1.5).
  s.blocks.push_back(
      make_output_test_block("ell", Polygon({{0, 1}, {2, 1}, {2, 1.5}, {1, 1.5}, {1, 3}, {0, 3}})));

  // A 2 x 2 square with a 1 x 1 hole (clockwise) in its middle: centroid (3, 2).
  Polygon ring({{2, 1}, {4, 1}, {4, 3}, {2, 3}});
  const std::vector<Vec2> hole{{2.5, 1.5}, {2.5, 2.5}, {3.5, 2.5}, {3.5, 1.5}};
  ring.add_loop(hole);
  s.blocks.push_back(make_output_test_block("ring", ring));

  for (const Monitor& m : output_test_monitors())
    s.points.push_back(MaterialPoint{m.block, m.point, m.point});
  s.first_fixed_point = s.first_load_point = static_cast<int>(s.points.size());
  return s;
}

inline void move_block(Block& b, const Vec2& shift) {
  for (std::size_t v = 0; v < b.polygon.vertices.size(); ++v)
    b.polygon.vertices[v] = b.initial_vertices[v] + shift;
  b.section = section_properties(b.polygon);
}

/// Sets `s` (from output_test_state) to frame k.
inline void set_output_test_frame(RockMass& s, int k) {
  s.time = frame_time(k);
  move_block(s.blocks[1], ell_shift(k));
  move_block(s.blocks[2], ring_shift(k));
  s.points[0].current = s.points[0].initial + ring_shift(k);

  // The L translates at (1, -2) m/s; the ring turns at 0.25 rad/s about its
  // centroid while moving at (0.5, 0) m/s.
  s.blocks[1].velocity << 1, -2, 0, 0, 0, 0;
  s.blocks[2].velocity << 0.5, 0, 0.25, 0, 0, 0;
  for (int b = 0; b < 3; ++b)
    s.blocks[b].stress = Vector3(-1e6 * (b + 1) - k, 2.5e5 * k, 100.0 * b + k);

  const ContactRecord all[3] = {
      {1, 0, Vec2(0.5, 1), Vec2(0, 1), ContactState::Locked, -1e-4 * k, 1e5 * k, -3.5},
      {2, 0, Vec2(3, 1), Vec2(0, 1), ContactState::Sliding, 2e-5, 0, 1.25},
      {2, 1, Vec2(2, 2), Vec2(-1, 0), ContactState::Open, 0.0625, 0, 0}};
  s.fields.get_or_add(kContacts).assign(all, all + k % 4);
}

}  // namespace fissure::test
