// The fluid pressure at a point, read off the fracture network for the
// monitors (monitors.csv column m.p, summary.json; docs/output.md): the
// pressure of the nearest fracture segment, linear between its two nodes,
// provided that segment lies within the search distance. The rock matrix is
// impermeable (docs/flow.md), so a point away from every fracture has no
// pressure: NaN.
#pragma once

#include "core/state/rock_mass.h"
#include "rockmass/fracture_graph.h"

namespace fissure {

/// The search distance as a fraction of the network's size (the larger side
/// of the bounding box of its nodes): 1 mm in a 1 m model, 6 cm in a 60 m
/// one. Large against round-off and the small block motions of a coupled
/// run, small against joint spacings.
inline constexpr double kPressureSearchFraction = 1e-3;

/// The nearest segment to a point and where along it the point projects.
struct SegmentProjection {
  int segment = -1;  ///< -1: the graph has no segments
  double s = 0;      ///< 0 at node_a, 1 at node_b
  double distance = 0;
};

/// The first of the nearest segments (in segment order) to x.
SegmentProjection nearest_segment(const FractureGraph& graph, const Vec2& x);

/// kPressureSearchFraction x the network's size (m).
double pressure_search_distance(const FractureGraph& graph);

/// The pressure (Pa) at x from the shared fields fracture_flow and
/// fracture_graph; NaN when there is no flow state or no segment within the
/// search distance.
double fracture_pressure_at(const RockMass& state, const Vec2& x);

}  // namespace fissure
