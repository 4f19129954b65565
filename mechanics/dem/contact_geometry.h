// Where rigid blocks touch in the explicit DEM (docs/theory.md, "Explicit
// DEM"; Cundall 1988, Itasca's UDEC): every convex corner of a block is
// rounded by an arc tangent to its two edges at a distance d (the rounding
// length) from the corner, so that a corner meeting a corner has a
// well-defined normal and the contact force turns smoothly as a corner
// slides past another. Contacts are of two kinds:
//  * corner-edge: a rounded corner of block i in front of the flat part of
//    an edge of block j (the part between its corners' tangent points);
//    normal: the edge's inward normal, gap: the arc's distance to the edge;
//  * corner-corner: a rounded corner of i in the region of a rounded corner
//    of j (beyond the flat parts of both of j's edges there); normal along
//    the line of the two arc centres, gap: their distance less both radii.
// Reflex (concave) corners are not rounded: the edges' flat parts reach
// them, and a corner of another block in that concave corner touches both.
// Nor are corners within 0.5 degree of straight (a vertex where a fracture
// meets a face): they are points of a face, not corners. On a deformable
// (zoned) block every boundary node is a contact point, as in UDEC: there
// such vertices are point corners (an arc of radius 0, on the vertex, whose
// contacts take the vertex's distance from the other block's edge). A corner faces an
// edge with its arc while the edge's normal lies in the directions the arc
// spans (between its edges' normals); beyond them, with the arc's end (its
// tangent point), so that the gap is the block's true distance from the
// edge and changes continuously as the block turns. Corner-corner contacts
// are made only where the line of the arc centres lies in both arcs' spans.
// A contact is listed while its gap is within `margin` (so that contacts
// are in place before the blocks touch; detection is repeated only after a
// block moved by a fraction of the margin).
// Contact length (the share of the interface a contact carries, to turn the
// joint's stresses into forces): the contacts of one pair of blocks whose
// normals agree within 10 degrees form an interface; each gets half the
// distance to its neighbours along it (a corner-edge contact counted at its
// corner's vertex), so that a brick on a base carries
// its weight on two contacts of half its width each. A contact alone on its
// interface (a wedge's tip on a face) gets the rounding length d.
// Broad phase: a uniform grid over the blocks' boxes widened by the margin
// (core/geometry/box_grid.h): O(N) candidate pairs for N blocks.
#pragma once

#include <compare>
#include <cstdint>
#include <span>
#include <vector>

#include "core/geometry/polygon.h"

namespace fissure::dem {

/// A corner's arc: its centre and radius (0 for a reflex corner, whose
/// "centre" is the vertex itself).
struct RoundedCorner {
  Vec2 centre = Vec2::Zero();
  double radius = 0;
  double tangent_length = 0;  ///< the tangent points' distance from the vertex (0: reflex)
  bool convex = false;
  /// The outward normals of the edges before and after the vertex: the arc
  /// spans the directions between them, and a contact of the corner must
  /// leave its arc in one of those (a corner that is nearly straight has a
  /// large arc centred deep in the block, whose full circle would reach far
  /// beyond the block's faces).
  Vec2 normal_before = Vec2::Zero(), normal_after = Vec2::Zero();
  /// The arc's ends: its tangent points on the edges before and after.
  Vec2 tangent_before = Vec2::Zero(), tangent_after = Vec2::Zero();
};

/// The arcs of every vertex of `polygon` for the rounding length d (the
/// tangent points' distance from the corner); d is reduced where an edge is
/// shorter than 2 d (each end then keeps half of the edge). `every_vertex`:
/// the vertices that are not convex corners are point corners (a zoned
/// block's boundary nodes), not left out.
std::vector<RoundedCorner> rounded_corners(const Polygon& polygon, double rounding,
                                           bool every_vertex = false);
/// The same into `corners`, whose storage is reused (every cycle of a DEM).
void rounded_corners(const Polygon& polygon, double rounding, std::vector<RoundedCorner>& corners,
                     bool every_vertex = false);

/// The blocks' polygons, by block index, where they are: a DEM's blocks
/// hold theirs among their other state, and copying every polygon every
/// cycle would cost more than the contacts' update itself.
using PolygonRefs = std::span<const Polygon* const>;
/// The references of polygons held in one list.
std::vector<const Polygon*> polygon_refs(const std::vector<Polygon>& polygons);

/// A contact's identity: corner `corner` of block i against edge `feature`
/// (the edge from vertex `feature` to the next) of block j, or against
/// corner -1 - feature of block j.
struct ContactKey {
  int block_i = -1, corner = -1, block_j = -1, feature = 0;
  auto operator<=>(const ContactKey&) const = default;
  bool corner_corner() const { return feature < 0; }
};

struct ContactGeometry {
  ContactKey key;
  Vec2 point = Vec2::Zero();   ///< midway between the two surfaces
  Vec2 normal = Vec2::Zero();  ///< unit, from block i to block j
  double gap = 0;              ///< m: > 0 apart, < 0 overlapping
  double length = 0;           ///< m: the contact's share of its interface
};

/// Every contact between `blocks` whose gap is below `margin`, ordered by
/// key (a corner-corner contact once, from the block of lower index).
/// `every_vertex[b]` (empty: none): block b's vertices are all contact
/// points (rounded_corners).
std::vector<ContactGeometry> find_contacts(PolygonRefs blocks, double rounding, double margin,
                                           std::span<const std::uint8_t> every_vertex = {});
std::vector<ContactGeometry> find_contacts(const std::vector<Polygon>& blocks, double rounding,
                                           double margin);

/// The gap, normal and point of a known contact (found by find_contacts on
/// an earlier geometry) at the blocks' current geometry, from their rounded
/// corners (`corners[b]`: rounded_corners of block b), keeping its key and
/// length: O(1), for the steps between two detections.
void update_contact(ContactGeometry& contact, PolygonRefs blocks,
                    std::span<const std::vector<RoundedCorner>> corners);
/// update_contact of each contact, for polygons held in one list.
void update_contacts(std::vector<ContactGeometry>& contacts, const std::vector<Polygon>& blocks,
                     double rounding);

}  // namespace fissure::dem
