#include "flow/hm/hm_apertures.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace fissure::flow {

namespace {

long long face_key(int block, int edge) {
  return (static_cast<long long>(block) << 32) | static_cast<unsigned>(edge);
}

/// The unordered pair of two blocks.
long long pair_key(int a, int b) {
  return face_key(std::min(a, b), std::max(a, b));
}

/// A contact point within this fraction of a segment's length beyond its ends
/// still loads it (a vertex at a junction may have slid a little).
constexpr double kEndReach = 0.05;

}  // namespace

void hm_apertures(const FractureGraph& g, const std::vector<SegmentWalls>& walls,
                  const std::vector<ContactRecord>& contacts, const FractureApertureLaws& laws,
                  std::vector<double>& e_a, std::vector<double>& e_b, WallState* ws,
                  const std::vector<double>& reference_closure) {
  const int m = g.n_segments();
  e_a.resize(m);
  e_b.resize(m);
  WallState local;
  WallState& w = ws ? *ws : local;
  for (auto* v : {&w.opening_a, &w.opening_b, &w.stress_a, &w.stress_b, &w.shear_a, &w.shear_b,
                  &w.compliance_a, &w.compliance_b})
    v->assign(m, 0.0);

  // 1. Contact forces -> resultant F and moment M (about end a) per segment.
  std::unordered_multimap<long long, int> segments_of_face;
  // Corner-corner contacts (the DEM's, where blocks meet at a fracture
  // crossing) name no edge: they load the segments between their two
  // blocks whose span they lie in.
  std::unordered_multimap<long long, int> segments_of_pair;
  for (int s = 0; s < m; ++s)
    if (walls[s].mechanical) {
      const FractureSegment& seg = g.segments[s];
      segments_of_face.emplace(face_key(seg.left.block, seg.left.edge), s);
      segments_of_face.emplace(face_key(seg.right.block, seg.right.edge), s);
      segments_of_pair.emplace(pair_key(seg.left.block, seg.right.block), s);
    }
  std::vector<double> force(m, 0.0), moment(m, 0.0);
  std::vector<std::pair<int, double>> hits;
  // A hit: the contact's position t along segment s (on the wall a -> b).
  auto hit = [&](int s, const Vec2& point, const Vec2& a, const Vec2& b) {
    const double t = (point - a).dot(b - a) / (b - a).squaredNorm();
    if (t >= -kEndReach && t <= 1 + kEndReach) hits.emplace_back(s, std::clamp(t, 0.0, 1.0));
  };
  for (const ContactRecord& c : contacts) {
    if (c.normal_force <= 0) continue;
    hits.clear();
    if (c.edge < 0) {
      const auto range = segments_of_pair.equal_range(pair_key(c.block_i, c.block_j));
      for (auto it = range.first; it != range.second; ++it)
        hit(it->second, c.point, walls[it->second].left_a, walls[it->second].left_b);
    } else {
      const auto range = segments_of_face.equal_range(face_key(c.block_j, c.edge));
      for (auto it = range.first; it != range.second; ++it) {
        const int s = it->second;
        const FractureSegment& seg = g.segments[s];
        const bool j_left = seg.left.block == c.block_j && seg.left.edge == c.edge;
        const int other = j_left ? seg.right.block : seg.left.block;
        if (other != c.block_i) continue;
        // Position along the segment on block j's wall.
        hit(s, c.point, j_left ? walls[s].left_a : walls[s].right_a,
            j_left ? walls[s].left_b : walls[s].right_b);
      }
    }
    for (const auto& [s, t] : hits) {
      const double f = c.normal_force / static_cast<double>(hits.size());
      force[s] += f;
      moment[s] += f * t;
    }
  }

  // 2. Apertures at both ends, by the law of the fracture's joint.
  for (int s = 0; s < m; ++s) {
    const double e0 = g.segments[s].aperture;
    const SegmentWalls& wall = walls[s];
    const FractureApertureLaw& law = laws.of_segment(s);
    if (!wall.mechanical) {
      e_a[s] = e_b[s] = law.unloaded(e0);
      continue;
    }
    const Vec2 along = wall.left_b - wall.left_a;
    const double length = along.norm();
    const Vec2 t = along / length;
    const Vec2 n(t.y(), -t.x());  // from the left wall towards the right one
    const Vec2 da = wall.right_a - wall.left_a, db = wall.right_b - wall.left_b;
    const double offset = reference_closure.empty() ? 0 : reference_closure[s];
    w.opening_a[s] = da.dot(n) - offset, w.opening_b[s] = db.dot(n) - offset;
    w.shear_a[s] = da.dot(t), w.shear_b[s] = db.dot(t);
    // Linear sigma with resultant F and moment M t-weighted: integral of sigma
    // = F, integral of sigma s/L = M (theory: two end forces Fa, Fb give
    // sigma_a = (4 Fa - 2 Fb) / L).
    const double sigma_b = (6 * moment[s] - 2 * force[s]) / length;
    const double sigma_a = 2 * force[s] / length - sigma_b;
    w.stress_a[s] = std::max(0.0, sigma_a), w.stress_b[s] = std::max(0.0, sigma_b);
    const double reference_length = g.length(s);
    const EndAperture a =
        law.at({w.opening_a[s], w.stress_a[s], w.shear_a[s]}, e0, reference_length);
    const EndAperture b =
        law.at({w.opening_b[s], w.stress_b[s], w.shear_b[s]}, e0, reference_length);
    e_a[s] = a.aperture, w.compliance_a[s] = a.compliance;
    e_b[s] = b.aperture, w.compliance_b[s] = b.compliance;
  }
}

void hm_apertures(const FractureGraph& g, const std::vector<SegmentWalls>& walls,
                  const std::vector<ContactRecord>& contacts, const HmApertureLaw& law,
                  std::vector<double>& e_a, std::vector<double>& e_b, WallState* ws) {
  hm_apertures(g, walls, contacts, FractureApertureLaws(law), e_a, e_b, ws);
}

}  // namespace fissure::flow
