// Contact detection ("entrance", theory.md 1.6).
//  * Broad phase: a uniform grid over all block edges (core/geometry/box_grid),
//    queried with every vertex: O(N) for N vertices, no all-pairs loop.
//  * Narrow phase: a vertex whose projection falls inside an edge (away from
//    its ends) and within the contact range is a vertex-edge contact if the
//    vertex's angle fits on the outer side of the edge. A vertex near a vertex
//    of another block is a vertex-vertex contact, registered as vertex-edge on
//    the entrance edge: among the four edges at the two vertices, those whose
//    line leaves the other vertex's angle outside; of these the one used in the
//    previous step if any (so that a locked contact keeps its identity and
//    state), else the one with the least penetration. A convex vertex in a
//    concave corner touches both of its edges.
//  * Persistent state (open/sliding/locked, stored contact point, bond) is
//    carried over from the previous step's contact with the same vertex and
//    edge, or with the neighbouring edge when the vertex has passed a corner.
#pragma once

#include <vector>

#include "core/state/rock_mass.h"
#include "mechanics/dda/dda_contact.h"

namespace fissure::dda {

struct DetectionCounters {
  long vertex_edge = 0;    ///< found by projection inside an edge
  long vertex_vertex = 0;  ///< vertex pairs resolved by the entrance rule
};

/// `range`: the contact distance (2.5 g2 w). `first_step`: contacts closed at
/// the start of the run get the joint's cohesion and tensile strength (bonded).
std::vector<DdaContact> detect_contacts(const RockMass& state, double range,
                                        const std::vector<DdaContact>& previous, bool first_step,
                                        DetectionCounters* counters = nullptr);

}  // namespace fissure::dda
