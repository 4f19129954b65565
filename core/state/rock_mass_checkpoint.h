// The shared state's part of a checkpoint (core/io/checkpoint.h): what the
// processes change in the blocks and the material points, and the time.
// The scene gives the rest again at a restart (names, materials, which
// blocks are fixed); the fields are saved by the processes that write them.
#pragma once

#include "core/base/errors.h"
#include "core/state/rock_mass.h"

namespace fissure {

template <class Archive>
void checkpoint(Archive& a, RockMass& state) {
  const std::size_t blocks = state.blocks.size(), points = state.points.size();
  a("time", state.time);
  a.list("blocks", state.blocks, [](auto& e, auto& b) {
    e("vertices", b.polygon.vertices);
    e("loop_offsets", b.polygon.loop_offsets);
    e("initial_vertices", b.initial_vertices);
    e("area", b.section.area);
    e("centroid", b.section.centroid);
    e("Ixx", b.section.Ixx);
    e("Iyy", b.section.Iyy);
    e("Ixy", b.section.Ixy);
    e("initial_area", b.initial_area);
    e("velocity", b.velocity);
    e("stress", b.stress);
    e("strain", b.strain);
    e("rotation", b.rotation);
  });
  a.list("points", state.points, [](auto& e, auto& p) {
    e("block", p.block);
    e("initial", p.initial);
    e("current", p.current);
  });
  if constexpr (Archive::reading)
    FISSURE_CHECK(state.blocks.size() == blocks && state.points.size() == points, IoError,
                  "the checkpoint holds " << state.blocks.size() << " blocks and "
                                          << state.points.size() << " material points, the scene "
                                          << blocks << " and " << points);
}

}  // namespace fissure
