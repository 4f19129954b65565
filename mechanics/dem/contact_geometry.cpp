#include "mechanics/dem/contact_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "core/geometry/box_grid.h"

namespace fissure::dem {

namespace {

/// Corners whose edges turn by less than 0.5 degree are straight.
const double kStraightCos = std::cos(0.5 * 3.14159265358979323846 / 180);

/// Whether `direction` (unit, out of the corner's arc) lies in the
/// directions its arc spans, with a margin of 1e-9 for the flush cases
/// (a corner's own edge along another block's face).
bool spans(const RoundedCorner& c, const Vec2& direction) {
  constexpr double kSlack = 1e-9;
  return cross(c.normal_before, direction) >= -kSlack &&
         cross(direction, c.normal_after) >= -kSlack;
}

}  // namespace

std::vector<RoundedCorner> rounded_corners(const Polygon& polygon, double rounding,
                                           bool every_vertex) {
  std::vector<RoundedCorner> corners;
  rounded_corners(polygon, rounding, corners, every_vertex);
  return corners;
}

void rounded_corners(const Polygon& polygon, double rounding, std::vector<RoundedCorner>& corners,
                     bool every_vertex) {
  corners.assign(polygon.n_vertices(), RoundedCorner{});
  for (int v = 0; v < polygon.n_vertices(); ++v) {
    const Vec2& x = polygon.vertices[v];
    const Vec2 to_prev = polygon.vertices[polygon.prev(v)] - x;
    const Vec2 to_next = polygon.vertices[polygon.next(v)] - x;
    RoundedCorner& c = corners[v];
    c.centre = x;
    const Vec2 u1 = to_prev.normalized(), u2 = to_next.normalized();
    // A point corner: the vertex itself, between its edges' normals.
    auto point_corner = [&] {
      if (!every_vertex) return;
      c.convex = true;
      c.normal_before = Vec2(-u1.y(), u1.x());
      c.normal_after = Vec2(u2.y(), -u2.x());
      c.tangent_before = c.tangent_after = x;
    };
    // Material on the left of every edge: a left turn at v is convex.
    const double turn = -to_prev.x() * to_next.y() + to_prev.y() * to_next.x();
    if (!(turn > 0)) {
      point_corner();
      continue;
    }
    const double d = std::min({rounding, 0.5 * to_prev.norm(), 0.5 * to_next.norm()});
    const double cos_angle = std::clamp(u1.dot(u2), -1.0, 1.0);  // the interior angle beta
    if (cos_angle < -kStraightCos) {                             // a point of a straight face
      point_corner();
      continue;
    }
    const double cos_half = std::sqrt(0.5 * (1 + cos_angle));
    const double tan_half = std::sqrt((1 - cos_angle) / (1 + cos_angle));
    c.convex = true;
    c.normal_before = Vec2(-u1.y(), u1.x());  // edge prev -> v runs along -u1
    c.normal_after = Vec2(u2.y(), -u2.x());
    c.tangent_before = x + d * u1;
    c.tangent_after = x + d * u2;
    c.tangent_length = d;
    c.radius = d * tan_half;
    c.centre = x + (u1 + u2).normalized() * (d / cos_half);
  }
}

namespace {

constexpr double kInterfaceCos = 0.98480775301220802;  // cos 10 deg

Vec2 outward_normal(const Vec2& along) {
  return Vec2(along.y(), -along.x());
}

/// Corner a of block i (arc ca) against edge e of block j: its geometry,
/// and whether the arc's centre lies over the edge's flat part.
ContactGeometry corner_on_edge(int i, int a, const RoundedCorner& ca, int j, int e,
                               const Polygon& pj, const std::vector<RoundedCorner>& cj,
                               bool* over_flat = nullptr) {
  const int f = pj.next(e);
  const Vec2 edge = pj.vertices[f] - pj.vertices[e];
  const double length = edge.norm();
  const Vec2 t = edge / length, n = outward_normal(t);
  const Vec2 rel = ca.centre - pj.vertices[e];
  const double along = rel.dot(t), distance = rel.dot(n);
  if (over_flat)
    *over_flat =
        length > 0 && along >= cj[e].tangent_length && along <= length - cj[f].tangent_length;
  ContactGeometry c;
  c.key = {i, a, j, e};
  c.normal = -n;
  if (spans(ca, c.normal)) {
    c.gap = distance - ca.radius;
    c.point = ca.centre + c.normal * (ca.radius + 0.5 * c.gap);
  } else {
    // The edge's normal is beyond the arc's span: the arc's end on that
    // side is the corner's point nearest the edge.
    const Vec2 end = cross(ca.normal_before, c.normal) < 0 ? ca.tangent_before : ca.tangent_after;
    c.gap = (end - pj.vertices[e]).dot(n);
    c.point = end + c.normal * (0.5 * c.gap);
  }
  return c;
}

/// Corner a of block i against corner b of block j, keyed from the block of
/// lower index.
ContactGeometry corner_on_corner(int i, int a, const RoundedCorner& ca, int j, int b,
                                 const RoundedCorner& cb) {
  if (i > j) return corner_on_corner(j, b, cb, i, a, ca);
  const Vec2 between = cb.centre - ca.centre;
  const double distance = between.norm();
  ContactGeometry c;
  c.key = {i, a, j, -1 - b};
  c.normal = distance > 0 ? Vec2(between / distance) : Vec2(0, 0);
  c.gap = distance - ca.radius - cb.radius;
  c.point = ca.centre + c.normal * (ca.radius + 0.5 * c.gap);
  return c;
}

/// The contacts of every convex corner of block i with block j. A corner
/// behind an edge's line by more than `depth` (the larger of the margin and
/// the rounding length: no contact is allowed to get so deep) is not in
/// contact with it: where a corner of i sits on a vertex of j, it lies
/// behind j's other edges' lines without being inside j (a nearly straight
/// corner's large arc would pass the arc centre's test).
void corner_contacts(int i, int j, PolygonRefs blocks,
                     const std::vector<std::vector<RoundedCorner>>& corners, double margin,
                     double depth, std::vector<ContactGeometry>& out) {
  const Polygon& pj = *blocks[j];
  const std::vector<RoundedCorner>& cj = corners[j];
  for (int a = 0; a < blocks[i]->n_vertices(); ++a) {
    const RoundedCorner& ca = corners[i][a];
    if (!ca.convex) continue;
    bool over_an_edge = false;
    for (int e = 0; e < pj.n_vertices(); ++e) {
      bool over_flat = false;
      const ContactGeometry c = corner_on_edge(i, a, ca, j, e, pj, cj, &over_flat);
      if (!over_flat || c.gap + ca.radius < -margin || c.gap < -depth || c.gap >= margin) continue;
      over_an_edge = true;
      out.push_back(c);
    }
    if (over_an_edge) continue;
    // The nearest rounded corner of j.
    int nearest = -1;
    double best = margin;
    for (int b = 0; b < pj.n_vertices(); ++b) {
      if (!cj[b].convex) continue;
      const double gap = (cj[b].centre - ca.centre).norm() - ca.radius - cj[b].radius;
      if (gap < best) {
        best = gap;
        nearest = b;
      }
    }
    if (nearest < 0 || !((cj[nearest].centre - ca.centre).norm() > 0)) continue;
    const Vec2 between = (cj[nearest].centre - ca.centre).normalized();
    if (!spans(ca, between) || !spans(cj[nearest], Vec2(-between))) continue;
    out.push_back(corner_on_corner(i, a, ca, j, nearest, cj[nearest]));
  }
}

/// Contact lengths: per interface (one block pair, normals within 10
/// degrees), half the distance to the neighbours along it, at least d.
void set_lengths(std::vector<ContactGeometry>& contacts, PolygonRefs blocks, double rounding) {
  std::map<std::pair<int, int>, std::vector<int>> pairs;
  for (int k = 0; k < static_cast<int>(contacts.size()); ++k) {
    const ContactKey& key = contacts[k].key;
    pairs[{std::min(key.block_i, key.block_j), std::max(key.block_i, key.block_j)}].push_back(k);
  }
  for (const auto& [pair, members] : pairs) {
    // Normals oriented from the pair's first block to its second.
    auto oriented = [&](int k) {
      return contacts[k].key.block_i == pair.first ? contacts[k].normal : Vec2(-contacts[k].normal);
    };
    std::vector<std::vector<int>> interfaces;
    std::vector<Vec2> directions;
    for (int k : members) {
      const Vec2 n = oriented(k);
      std::size_t m = 0;
      while (m < directions.size() && directions[m].normalized().dot(n) < kInterfaceCos) ++m;
      if (m == directions.size()) {
        interfaces.emplace_back();
        directions.push_back(Vec2::Zero());
      }
      interfaces[m].push_back(k);
      directions[m] += n;
    }
    for (std::size_t m = 0; m < interfaces.size(); ++m) {
      const Vec2 n = directions[m].normalized(), t(-n.y(), n.x());
      std::vector<std::pair<double, int>> along;
      // A contact is placed at its corner's vertex (block i's), not at its
      // arc: the interface of a brick then spans its whole width, and the
      // contacts of two flush corners are at one spot.
      for (int k : interfaces[m]) {
        const ContactKey& key = contacts[k].key;
        along.emplace_back(blocks[key.block_i]->vertices[key.corner].dot(t), k);
      }
      std::sort(along.begin(), along.end());
      // Contacts at one spot (closer than the rounding length: the two
      // corner-edge contacts of two flush corners, each corner on the other's
      // edge) share that spot's length, so that an interface's lengths add
      // up to its extent whatever the kind of its contacts.
      std::vector<std::pair<std::size_t, std::size_t>> spots;  // [first, last) of `along`
      for (std::size_t q = 0; q < along.size(); ++q)
        if (spots.empty() || along[q].first - along[spots.back().second - 1].first >= rounding)
          spots.emplace_back(q, q + 1);
        else
          spots.back().second = q + 1;
      auto position = [&](std::size_t s) {
        double sum = 0;
        for (std::size_t q = spots[s].first; q < spots[s].second; ++q) sum += along[q].first;
        return sum / static_cast<double>(spots[s].second - spots[s].first);
      };
      for (std::size_t s = 0; s < spots.size(); ++s) {
        double length = 0;
        if (s > 0) length += 0.5 * (position(s) - position(s - 1));
        if (s + 1 < spots.size()) length += 0.5 * (position(s + 1) - position(s));
        const auto count = static_cast<double>(spots[s].second - spots[s].first);
        for (std::size_t q = spots[s].first; q < spots[s].second; ++q)
          contacts[along[q].second].length = std::max(length, rounding) / count;
      }
    }
  }
}

}  // namespace

std::vector<ContactGeometry> find_contacts(PolygonRefs blocks, double rounding, double margin,
                                           std::span<const std::uint8_t> every_vertex) {
  std::vector<std::vector<RoundedCorner>> corners;
  std::vector<Box> boxes;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const Polygon* p = blocks[k];
    corners.push_back(rounded_corners(*p, rounding, !every_vertex.empty() && every_vertex[k]));
    Box b = bounding_box(*p);
    b.lo -= Vec2::Constant(0.5 * margin);
    b.hi += Vec2::Constant(0.5 * margin);
    boxes.push_back(b);
  }
  std::vector<ContactGeometry> contacts;
  const double depth = std::max(margin, rounding);
  BoxGrid grid;
  grid.build(boxes);
  grid.for_each_pair([&](int i, int j) {
    corner_contacts(i, j, blocks, corners, margin, depth, contacts);
    corner_contacts(j, i, blocks, corners, margin, depth, contacts);
  });
  std::sort(contacts.begin(), contacts.end(),
            [](const ContactGeometry& a, const ContactGeometry& b) { return a.key < b.key; });
  // A corner-corner contact found from both corners: once.
  contacts.erase(std::unique(contacts.begin(), contacts.end(),
                             [](const ContactGeometry& a, const ContactGeometry& b) {
                               return a.key == b.key;
                             }),
                 contacts.end());
  set_lengths(contacts, blocks, rounding);
  return contacts;
}

std::vector<ContactGeometry> find_contacts(const std::vector<Polygon>& blocks, double rounding,
                                           double margin) {
  return find_contacts(polygon_refs(blocks), rounding, margin);
}

void update_contact(ContactGeometry& c, PolygonRefs blocks,
                    std::span<const std::vector<RoundedCorner>> corners) {
  const ContactKey k = c.key;
  const double length = c.length;
  c = k.corner_corner()
          ? corner_on_corner(k.block_i, k.corner, corners[k.block_i][k.corner], k.block_j,
                             -1 - k.feature, corners[k.block_j][-1 - k.feature])
          : corner_on_edge(k.block_i, k.corner, corners[k.block_i][k.corner], k.block_j, k.feature,
                           *blocks[k.block_j], corners[k.block_j]);
  c.length = length;
}

void update_contacts(std::vector<ContactGeometry>& contacts, const std::vector<Polygon>& blocks,
                     double rounding) {
  std::vector<std::vector<RoundedCorner>> corners;
  for (const Polygon& p : blocks) corners.push_back(rounded_corners(p, rounding));
  const std::vector<const Polygon*> refs = polygon_refs(blocks);
  for (ContactGeometry& c : contacts) update_contact(c, refs, corners);
}

std::vector<const Polygon*> polygon_refs(const std::vector<Polygon>& polygons) {
  std::vector<const Polygon*> refs;
  refs.reserve(polygons.size());
  for (const Polygon& p : polygons) refs.push_back(&p);
  return refs;
}

}  // namespace fissure::dem
