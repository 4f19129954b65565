#include "flow/hm/hm_apertures.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace fissure::flow {

namespace {

long long face_key(int block, int edge) {
  return (static_cast<long long>(block) << 32) | static_cast<unsigned>(edge);
}

/// A contact point within this fraction of a segment's length beyond its ends
/// still loads it (a vertex at a junction may have slid a little).
constexpr double kEndReach = 0.05;

}  // namespace

void hm_apertures(const FractureGraph& g, const std::vector<SegmentWalls>& walls,
                  const std::vector<ContactRecord>& contacts, const FractureApertureLaws& laws,
                  std::vector<double>& e_a, std::vector<double>& e_b, WallState* ws) {
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
  for (int s = 0; s < m; ++s)
    if (walls[s].mechanical) {
      segments_of_face.emplace(face_key(g.segments[s].left.block, g.segments[s].left.edge), s);
      segments_of_face.emplace(face_key(g.segments[s].right.block, g.segments[s].right.edge), s);
    }
  std::vector<double> force(m, 0.0), moment(m, 0.0);
  std::vector<std::pair<int, double>> hits;
  for (const ContactRecord& c : contacts) {
    if (c.normal_force <= 0 || c.edge < 0) continue;
    hits.clear();
    const auto range = segments_of_face.equal_range(face_key(c.block_j, c.edge));
    for (auto it = range.first; it != range.second; ++it) {
      const int s = it->second;
      const FractureSegment& seg = g.segments[s];
      const bool j_left = seg.left.block == c.block_j && seg.left.edge == c.edge;
      const int other = j_left ? seg.right.block : seg.left.block;
      if (other != c.block_i) continue;
      // Position along the segment on block j's wall.
      const Vec2 a = j_left ? walls[s].left_a : walls[s].right_a;
      const Vec2 b = j_left ? walls[s].left_b : walls[s].right_b;
      const double t = (c.point - a).dot(b - a) / (b - a).squaredNorm();
      if (t < -kEndReach || t > 1 + kEndReach) continue;
      hits.emplace_back(s, std::clamp(t, 0.0, 1.0));
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
    w.opening_a[s] = da.dot(n), w.opening_b[s] = db.dot(n);
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
