#include "mechanics/dda/contact_detection.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "core/geometry/box_grid.h"
#include "mechanics/dda/contact_springs.h"

namespace fissure::dda {

namespace {

// Edge directions within this angle (sine) of an edge line count as lying on
// it in the angle test; corners flatter than this are "flat", not convex.
constexpr double kAngleSine = 0.02;  // ~1.1 degrees
// Projections closer than this fraction of the contact range to an edge end
// are vertex-vertex situations, resolved by the entrance rule.
constexpr double kEndZone = 0.1;
// Entrance edges whose gaps differ by less than this fraction of the contact
// range are ties.
constexpr double kTieFraction = 0.01;

enum class Corner { Convex, Flat, Reflex };

Corner corner_type(const Polygon& p, int v) {
  const Vec2& x = p.vertices[v];
  const Vec2 in = x - p.vertices[p.prev(v)];
  const Vec2 out = p.vertices[p.next(v)] - x;
  const double s = cross(in, out) / (in.norm() * out.norm());
  if (s > kAngleSine) return Corner::Convex;
  if (s < -kAngleSine) return Corner::Reflex;
  return in.dot(out) > 0 ? Corner::Flat : Corner::Convex;
}

/// Edge e -> next(e) of a polygon; block material on its left.
struct Edge {
  Vec2 a, b;
  double length;
  Vec2 normal;  ///< outward (right-hand) unit normal
};

Edge edge_of(const Polygon& p, int e) {
  Edge g{p.vertices[e], p.vertices[p.next(e)], 0, Vec2::Zero()};
  const Vec2 d = g.b - g.a;
  g.length = d.norm();
  g.normal = Vec2(d.y(), -d.x()) / g.length;
  return g;
}

/// The vertex's angle lies on the outer side of a line with outward normal n.
bool angle_fits(const Polygon& p, int v, const Vec2& n) {
  const Vec2& x = p.vertices[v];
  const Vec2 a = p.vertices[p.prev(v)] - x, b = p.vertices[p.next(v)] - x;
  return a.dot(n) >= -kAngleSine * a.norm() && b.dot(n) >= -kAngleSine * b.norm();
}

struct VertexId {
  int block, vertex;
  auto operator<=>(const VertexId&) const = default;
};

class Detector {
 public:
  Detector(const RockMass& state, double range, const std::vector<DdaContact>& previous)
      : state_(state), range_(range), end_zone_(kEndZone * range) {
    for (const DdaContact& c : previous) previous_.emplace(c.key, &c);
  }

  std::vector<ContactKey> run(DetectionCounters& counters);
  const std::unordered_map<ContactKey, const DdaContact*, ContactKeyHash>& previous() const {
    return previous_;
  }

 private:
  const Polygon& poly(int b) const { return state_.blocks[b].polygon; }
  bool both_fixed(int i, int j) const { return state_.blocks[i].fixed && state_.blocks[j].fixed; }
  void query_vertex(int i, int v, const BoxGrid& grid);
  void resolve_vertex_pair(const VertexId& p, const VertexId& q);
  bool has_vertex_edge(const VertexId& p, const VertexId& q) const;

  const RockMass& state_;
  double range_, end_zone_;
  std::unordered_map<ContactKey, const DdaContact*, ContactKeyHash> previous_;
  std::vector<std::array<int, 2>> edges_;  // (block, start vertex)
  std::vector<ContactKey> found_;
  std::unordered_set<ContactKey, ContactKeyHash> found_set_;
  std::vector<std::pair<VertexId, VertexId>> vertex_pairs_;
};

void Detector::query_vertex(int i, int v, const BoxGrid& grid) {
  const Vec2& p = poly(i).vertices[v];
  Box q;
  q.extend(p);
  q.lo.array() -= range_ / 2;
  q.hi.array() += range_ / 2;
  grid.for_each_overlapping(q, [&](int k) {
    const auto [j, e] = edges_[k];
    if (j == i || both_fixed(i, j)) return;
    const Edge edge = edge_of(poly(j), e);
    const double d = (p - edge.a).dot(edge.normal);
    if (std::abs(d) > range_) return;
    const double s = (p - edge.a).dot(edge.b - edge.a) / edge.length;
    if (s > end_zone_ && s < edge.length - end_zone_) {
      if (angle_fits(poly(i), v, edge.normal)) found_.push_back({i, v, j, e});
      return;
    }
    const int qv = s <= end_zone_ ? e : poly(j).next(e);
    if ((p - poly(j).vertices[qv]).norm() < range_ + end_zone_) {
      VertexId a{i, v}, b{j, qv};
      if (b < a) std::swap(a, b);
      vertex_pairs_.emplace_back(a, b);
    }
  });
}

/// p already touches one of q's two edges inside the edge.
bool Detector::has_vertex_edge(const VertexId& p, const VertexId& q) const {
  const Polygon& pq = poly(q.block);
  return found_set_.count({p.block, p.vertex, q.block, q.vertex}) ||
         found_set_.count({p.block, p.vertex, q.block, pq.prev(q.vertex)});
}

void Detector::resolve_vertex_pair(const VertexId& p, const VertexId& q) {
  if (has_vertex_edge(p, q) || has_vertex_edge(q, p)) return;
  const Corner cp = corner_type(poly(p.block), p.vertex);
  const Corner cq = corner_type(poly(q.block), q.vertex);
  if (cp == Corner::Reflex && cq == Corner::Reflex) return;

  struct Candidate {
    ContactKey key;
    bool fits, inside, existed;
    double gap;
  };
  std::vector<Candidate> candidates;
  // Vertex `a` onto the two edges at vertex `b`.
  auto add = [&](const VertexId& a, const VertexId& b) {
    const Polygon& pb = poly(b.block);
    for (const int e : {b.vertex, pb.prev(b.vertex)}) {
      const Edge edge = edge_of(pb, e);
      const Vec2& x = poly(a.block).vertices[a.vertex];
      const double s = (x - edge.a).dot(edge.b - edge.a) / edge.length;
      const double tol = 1e-3 * range_;
      const ContactKey key{a.block, a.vertex, b.block, e};
      candidates.push_back({key, angle_fits(poly(a.block), a.vertex, edge.normal),
                            s >= -tol && s <= edge.length + tol, previous_.count(key) > 0,
                            (x - edge.a).dot(edge.normal)});
    }
  };
  if (cp != Corner::Reflex) add(p, q);
  if (cq != Corner::Reflex) add(q, p);

  // A convex vertex in a concave corner touches both edges of the corner.
  if (cp == Corner::Reflex || cq == Corner::Reflex) {
    for (const Candidate& c : candidates)
      if (c.fits) found_.push_back(c.key);
    return;
  }
  // Entrance edge: fits, then the vertex projects onto the edge, then least
  // penetration. Among candidates within a tie tolerance of the best gap, the
  // one used in the previous step is kept (two coincident corners of touching
  // blocks otherwise swap edges on round-off and lose the contact's history);
  // a previous choice that is clearly worse is dropped (a corner passing
  // beside another would otherwise keep "penetrating" an edge's extension).
  const auto rank = [](const Candidate& x) { return std::make_pair(x.fits, x.inside); };
  const auto better = [&](const Candidate& x, const Candidate& y) {
    if (rank(x) != rank(y)) return rank(x) > rank(y);
    return x.gap > y.gap;
  };
  const Candidate* best = &*std::min_element(candidates.begin(), candidates.end(), better);
  for (const Candidate& c : candidates)
    if (c.existed && rank(c) == rank(*best) && c.gap >= best->gap - kTieFraction * range_) best = &c;
  found_.push_back(best->key);
}

std::vector<ContactKey> Detector::run(DetectionCounters& counters) {
  // 1. Broad phase: boxes of all edges, grown by half the range.
  std::vector<Box> boxes;
  for (int j = 0; j < static_cast<int>(state_.blocks.size()); ++j) {
    const Polygon& p = poly(j);
    for (int e = 0; e < p.n_vertices(); ++e) {
      Box b;
      b.extend(p.vertices[e]);
      b.extend(p.vertices[p.next(e)]);
      b.lo.array() -= range_ / 2;
      b.hi.array() += range_ / 2;
      boxes.push_back(b);
      edges_.push_back({j, e});
    }
  }
  BoxGrid grid;
  grid.build(boxes);

  // 2. Every convex or flat vertex against nearby edges of other blocks.
  for (int i = 0; i < static_cast<int>(state_.blocks.size()); ++i)
    for (int v = 0; v < poly(i).n_vertices(); ++v)
      if (corner_type(poly(i), v) != Corner::Reflex) query_vertex(i, v, grid);
  counters.vertex_edge += static_cast<long>(found_.size());
  found_set_.insert(found_.begin(), found_.end());

  // 3. Vertex pairs (each once), resolved to an entrance edge. Pairs of a
  //    reflex vertex are only found from the convex side.
  std::sort(vertex_pairs_.begin(), vertex_pairs_.end());
  vertex_pairs_.erase(std::unique(vertex_pairs_.begin(), vertex_pairs_.end()),
                      vertex_pairs_.end());
  counters.vertex_vertex += static_cast<long>(vertex_pairs_.size());
  for (const auto& [p, q] : vertex_pairs_) resolve_vertex_pair(p, q);

  // 4. Unique keys in a deterministic order.
  std::sort(found_.begin(), found_.end(), [](const ContactKey& a, const ContactKey& b) {
    return std::tie(a.block_i, a.vertex, a.block_j, a.edge) <
           std::tie(b.block_i, b.vertex, b.block_j, b.edge);
  });
  found_.erase(std::unique(found_.begin(), found_.end()), found_.end());
  return std::move(found_);
}

}  // namespace

std::vector<DdaContact> detect_contacts(const RockMass& state, double range,
                                        const std::vector<DdaContact>& previous, bool first_step,
                                        DetectionCounters* counters) {
  DetectionCounters local;
  Detector detector(state, range, previous);
  const std::vector<ContactKey> keys = detector.run(counters ? *counters : local);
  const auto& old = detector.previous();

  std::vector<DdaContact> contacts;
  contacts.reserve(keys.size());
  for (const ContactKey& key : keys) {
    DdaContact c;
    c.key = key;
    const Block& bj = state.blocks[key.block_j];
    c.joint = bj.edge_joint[key.edge];
    // Same vertex and edge as last step, or the neighbouring edge when the
    // vertex has passed a corner: keep the contact's history.
    const DdaContact* before = nullptr;
    for (const int e : {key.edge, bj.polygon.next(key.edge), bj.polygon.prev(key.edge)}) {
      const auto it = old.find({key.block_i, key.vertex, key.block_j, e});
      if (it != old.end()) {
        before = it->second;
        break;
      }
    }
    if (before) {
      c.state = before->state;
      c.bonded = before->bonded;
      c.normal_force = before->normal_force;
      c.shear_force = before->shear_force;
      c.slip_sign = before->slip_sign;
    }
    if (!before) {
      // A new contact starts locked if it is closed, else open. At the start of
      // the run, closed contacts carry the joint's cohesion and tensile strength.
      prepare_contact(c, state);
      c.state = c.gap0 <= 0 ? ContactState::Locked : ContactState::Open;
      const JointProperties& joint = state.joints[c.joint];
      c.bonded = first_step && c.gap0 <= 1e-6 * range &&
                 (joint.cohesion > 0 || joint.tensile_strength > 0);
      if (c.bonded) c.state = ContactState::Locked;
    }
    prepare_contact(c, state);
    contacts.push_back(c);
  }
  return contacts;
}

}  // namespace fissure::dda
