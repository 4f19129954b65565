// A fracture graph from straight fracture traces (a DFN or explicit
// fractures) clipped to an axis-aligned box: nodes at trace ends, at
// intersections and where traces leave the box; segments between them
// (FractureGraph, rockmass/fracture_graph.h). The box's sides are the named
// boundaries "left", "right", "bottom", "top" (the nodes on them).
// Traces carry no block faces (BlockFace::block = -1 on both sides).
#pragma once

#include <span>
#include <vector>

#include "core/geometry/polygon.h"
#include "core/geometry/segment_clip.h"
#include "rockmass/fracture_graph.h"

namespace fissure::flow {

struct Trace {
  Vec2 a = Vec2::Zero(), b = Vec2::Zero();
  double aperture = 0;  ///< e0 (m)
  int fracture = -1;
  int joint_set = -1;
};

struct TraceNetworkStatistics {
  int clipped_away = 0;        ///< traces outside the box (or shorter than the tolerance inside)
  int intersections = 0;       ///< crossing and touching pairs
  int collinear_overlaps = 0;  ///< overlapping collinear pairs (not joined)
  int merged_nodes = 0;        ///< candidate nodes merged because closer than the tolerance
};

/// Builds the graph. Points closer than `tolerance` (m) are one node; a trace
/// end within `tolerance` of another trace is joined to it (T-junction).
FractureGraph build_trace_network(std::span<const Trace> traces, const Box& domain,
                                  double tolerance, TraceNetworkStatistics* statistics = nullptr);

}  // namespace fissure::flow
