#include "mechanics/dda/contact_detection.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

#include "core/base/errors.h"
#include "core/geometry/box_grid.h"
#include "core/geometry/polygon_checks.h"
#include "core/geometry/segment_predicates.h"
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
// Penetrations shallower than this fraction of the contact range are taken as
// they are (round-off of touching blocks).
constexpr double kPenetrationCheck = 1e-6;
// A deeper one is a penetration only when the vertex lies in the edge's block
// and the depth is below this fraction of the smaller block's size
// (sqrt(area)): the penalty keeps real penetrations far below it.
constexpr double kPenetrationLimit = 0.25;

enum class Corner : unsigned char { Convex, Flat, Reflex };

/// The geometry detection needs, computed once per call for all blocks and
/// flattened over a global vertex numbering: corner type of every vertex,
/// unit direction and length of every edge v -> next(v).
struct FlatGeometry {
  std::vector<int> first;  ///< first global vertex of each block
  std::vector<Corner> corner;
  std::vector<Vec2> direction;  ///< unit direction of edge v -> next(v)
  std::vector<double> length;
  std::vector<int> prev;   ///< global index of the previous vertex on the loop
  std::vector<int> owner;  ///< block of each global vertex

  explicit FlatGeometry(const RockMass& state) {
    first.reserve(state.blocks.size() + 1);
    int n = 0;
    for (const Block& b : state.blocks) {
      first.push_back(n);
      n += b.polygon.n_vertices();
    }
    first.push_back(n);
    corner.resize(n);
    direction.resize(n);
    length.resize(n);
    prev.resize(n);
    owner.resize(n);
    for (std::size_t b = 0; b < state.blocks.size(); ++b) {
      const Polygon& p = state.blocks[b].polygon;
      for (int v = 0; v < p.n_vertices(); ++v) {
        const Vec2 d = p.vertices[p.next(v)] - p.vertices[v];
        length[first[b] + v] = d.norm();
        direction[first[b] + v] = d / length[first[b] + v];
        prev[first[b] + v] = first[b] + p.prev(v);
        owner[first[b] + v] = static_cast<int>(b);
      }
      for (int v = 0; v < p.n_vertices(); ++v) {
        const int g = first[b] + v;
        const Vec2& in = direction[prev[g]];
        const Vec2& out = direction[g];
        const double s = cross(in, out);
        corner[g] = s > kAngleSine    ? Corner::Convex
                    : s < -kAngleSine ? Corner::Reflex
                    : in.dot(out) > 0 ? Corner::Flat
                                      : Corner::Convex;
      }
    }
  }

  /// Outward (right-hand) unit normal of edge g: block material is on the left.
  Vec2 normal(int g) const { return Vec2(direction[g].y(), -direction[g].x()); }

  /// The vertex's angle lies on the outer side of a line with outward normal n.
  bool angle_fits(int g, const Vec2& n) const {
    return -direction[prev[g]].dot(n) >= -kAngleSine && direction[g].dot(n) >= -kAngleSine;
  }
};

const ContactKey& key_of(const DdaContact& c) {
  return c.key;
}
const ContactKey& key_of(const ContactKey& k) {
  return k;
}

/// Where a list of contacts grouped by vertex, in vertex order, keeps each
/// vertex's contacts: those of global vertex g are [start[g], start[g + 1]).
/// A lookup scans the vertex's few contacts instead of binary-searching the
/// whole list, whose probes each missed the cache (a third of detection's
/// time on the settled 1,000-brick wall). The list may grow after indexing;
/// only the entries indexed are searched.
template <class Contact>
class ContactsByVertex {
 public:
  ContactsByVertex(const std::vector<Contact>& grouped, const FlatGeometry& geo)
      : list_(grouped), first_(geo.first), start_(geo.first.back() + 1, 0) {
    [[maybe_unused]] int last = 0;
    for (const Contact& c : grouped) {
      const int g = vertex_of(key_of(c));
      FISSURE_ASSERT(g >= last);  // grouped in vertex order
      last = g;
      ++start_[g + 1];
    }
    for (std::size_t g = 1; g < start_.size(); ++g) start_[g] += start_[g - 1];
  }

  /// The listed contact with key k, if any.
  const Contact* find(const ContactKey& k) const {
    const int g = vertex_of(k);
    for (int a = start_[g]; a < start_[g + 1]; ++a)
      if (key_of(list_[a]) == k) return &list_[a];
    return nullptr;
  }

 private:
  int vertex_of(const ContactKey& k) const {
    FISSURE_ASSERT(k.block_i + 1 < static_cast<int>(first_.size()) &&
                   first_[k.block_i] + k.vertex < first_[k.block_i + 1]);
    return first_[k.block_i] + k.vertex;
  }

  const std::vector<Contact>& list_;
  const std::vector<int>& first_;  ///< first global vertex of each block
  std::vector<int> start_;
};

struct VertexId {
  int block, vertex;
};

class Detector {
 public:
  Detector(const RockMass& state, double range, const std::vector<DdaContact>& previous)
      : state_(state),
        geo_(state),
        range_(range),
        end_zone_(kEndZone * range),
        previous_by_vertex_(previous, geo_) {}

  std::vector<ContactKey> run(DetectionCounters& counters);

  /// The previous step's contact with key k, if any.
  const DdaContact* previous_contact(const ContactKey& k) const {
    return previous_by_vertex_.find(k);
  }

 private:
  const Polygon& poly(int b) const { return state_.blocks[b].polygon; }
  int global(int b, int v) const { return geo_.first[b] + v; }
  bool both_fixed(int i, int j) const { return state_.blocks[i].fixed && state_.blocks[j].fixed; }
  bool existed(const ContactKey& k) const { return previous_contact(k) != nullptr; }
  /// k was found as a vertex-edge contact (step 2 of run).
  bool found(const ContactKey& k) const { return vertex_edge_->find(k) != nullptr; }
  void query_vertex(int i, int v, const BoxGrid& grid);
  void resolve_vertex_pair(const VertexId& p, const VertexId& q);
  bool has_vertex_edge(const VertexId& p, const VertexId& q) const;
  /// A vertex of block i at p, at signed distance d from edge e of block j
  /// (d < 0: behind its line), can touch that edge: in front of it, or
  /// behind it in a penetration that penalty springs allow. That is shallow
  /// against both blocks' sizes, has the vertex in block j (within the
  /// depth), and has it nearer to e than to any edge of j but e's two
  /// neighbours. The contact range is set by the model's size, so a small
  /// block's vertex can lie behind the line of an edge it is nowhere near:
  /// across a thin block, or on another part of the block's boundary (a
  /// corner two blocks share, a T-junction). Taken as penetrations, such
  /// pairs put springs of centimetres on blocks at rest (issue 22: DFN rock
  /// masses failed at step 0; docs/dda.md section 2). "In block j" means
  /// inside it to round-off: a vertex outside j beside one of its corners
  /// can lie behind the line of j's far edge by more than j is thick (fuzz
  /// case 4143: a vertex 1.9 mm beside the corner of a 1 m sliver, 3 cm
  /// behind its long edge, was taken as penetrating it, and the spring
  /// crushed the 1 cm block the vertex belonged to in the first step).
  bool can_touch(int i, const Vec2& p, double d, int j, int e) const {
    const double shallow = kPenetrationCheck * range_;
    if (d >= -shallow) return true;
    const double size =
        std::sqrt(std::min(state_.blocks[i].section.area, state_.blocks[j].section.area));
    const Polygon& pj = poly(j);
    if (-d > kPenetrationLimit * size || locate_point(pj, p, shallow) < 0) return false;
    const double to_e = point_segment_distance(p, pj.vertices[e], pj.vertices[pj.next(e)]);
    for (int k = 0; k < pj.n_vertices(); ++k) {
      if (k == e || k == pj.next(e) || k == pj.prev(e)) continue;
      if (point_segment_distance(p, pj.vertices[k], pj.vertices[pj.next(k)]) < to_e - shallow)
        return false;
    }
    return true;
  }

  const RockMass& state_;
  const FlatGeometry geo_;
  double range_, end_zone_;
  const ContactsByVertex<DdaContact> previous_by_vertex_;  ///< last step's, sorted by key
  std::vector<std::array<int, 2>> edges_;                  ///< (block, start vertex)
  /// Vertex-edge contacts, grouped by vertex (queried in vertex order), then
  /// the vertex pairs' entrance contacts.
  std::vector<ContactKey> found_;
  std::optional<ContactsByVertex<ContactKey>> vertex_edge_;  ///< index of found_'s vertex-edge part
  /// Vertex pairs (x < y) as global vertex numbers x * 2^32 + y: sorting
  /// them orders them as (VertexId, VertexId) pairs would, at a third of
  /// the cost (the sort was 4 % of a shaken cliff's run).
  std::vector<std::uint64_t> vertex_pairs_;
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
    const int ge = global(j, e);
    const Vec2& a = poly(j).vertices[e];
    const Vec2 n = geo_.normal(ge);
    const double d = (p - a).dot(n);
    if (std::abs(d) > range_ || !can_touch(i, p, d, j, e)) return;
    const double s = (p - a).dot(geo_.direction[ge]);
    const double l = geo_.length[ge];
    if (s > end_zone_ && s < l - end_zone_) {
      if (geo_.angle_fits(global(i, v), n)) found_.push_back({i, v, j, e});
      return;
    }
    const int qv = s <= end_zone_ ? e : poly(j).next(e);
    if ((p - poly(j).vertices[qv]).norm() < range_ + end_zone_) {
      const auto x = static_cast<std::uint64_t>(global(i, v));
      const auto y = static_cast<std::uint64_t>(global(j, qv));
      vertex_pairs_.push_back(x < y ? x << 32 | y : y << 32 | x);
    }
  });
}

/// p already touches one of q's two edges inside the edge.
bool Detector::has_vertex_edge(const VertexId& p, const VertexId& q) const {
  return found({p.block, p.vertex, q.block, q.vertex}) ||
         found({p.block, p.vertex, q.block, poly(q.block).prev(q.vertex)});
}

void Detector::resolve_vertex_pair(const VertexId& p, const VertexId& q) {
  if (has_vertex_edge(p, q) || has_vertex_edge(q, p)) return;
  const Corner cp = geo_.corner[global(p.block, p.vertex)];
  const Corner cq = geo_.corner[global(q.block, q.vertex)];
  if (cp == Corner::Reflex && cq == Corner::Reflex) return;

  struct Candidate {
    ContactKey key;
    bool fits, inside, existed;
    double gap;
  };
  std::array<Candidate, 4> candidates;
  int n_candidates = 0;
  // Vertex `a` onto the two edges at vertex `b`.
  auto add = [&](const VertexId& a, const VertexId& b) {
    const Polygon& pb = poly(b.block);
    const Vec2& x = poly(a.block).vertices[a.vertex];
    for (const int e : {b.vertex, pb.prev(b.vertex)}) {
      const int ge = global(b.block, e);
      const Vec2 n = geo_.normal(ge);
      const double s = (x - pb.vertices[e]).dot(geo_.direction[ge]);
      const double tol = 1e-3 * range_;
      const ContactKey key{a.block, a.vertex, b.block, e};
      const double gap = (x - pb.vertices[e]).dot(n);
      if (!can_touch(a.block, x, gap, b.block, e)) continue;
      candidates[n_candidates++] = {key, geo_.angle_fits(global(a.block, a.vertex), n),
                                    s >= -tol && s <= geo_.length[ge] + tol, existed(key), gap};
    }
  };
  if (cp != Corner::Reflex) add(p, q);
  if (cq != Corner::Reflex) add(q, p);
  if (n_candidates == 0) return;
  const auto first = candidates.begin(), last = candidates.begin() + n_candidates;

  // A convex vertex in a concave corner touches both edges of the corner.
  if (cp == Corner::Reflex || cq == Corner::Reflex) {
    for (auto c = first; c != last; ++c)
      if (c->fits) found_.push_back(c->key);
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
  const Candidate* best = &*std::min_element(first, last, better);
  for (auto c = first; c != last; ++c)
    if (c->existed && rank(*c) == rank(*best) && c->gap >= best->gap - kTieFraction * range_)
      best = &*c;
  found_.push_back(best->key);
}

std::vector<ContactKey> Detector::run(DetectionCounters& counters) {
  // 1. Broad phase: boxes of all edges, grown by half the range.
  std::vector<Box> boxes;
  boxes.reserve(geo_.first.back());
  edges_.reserve(geo_.first.back());
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
      if (geo_.corner[global(i, v)] != Corner::Reflex) query_vertex(i, v, grid);
  counters.vertex_edge += static_cast<long>(found_.size());
  vertex_edge_.emplace(found_, geo_);

  // 3. Vertex pairs (each once), resolved to an entrance edge. Pairs of a
  //    reflex vertex are only found from the convex side.
  std::sort(vertex_pairs_.begin(), vertex_pairs_.end());
  vertex_pairs_.erase(std::unique(vertex_pairs_.begin(), vertex_pairs_.end()), vertex_pairs_.end());
  counters.vertex_vertex += static_cast<long>(vertex_pairs_.size());
  for (const std::uint64_t pair : vertex_pairs_) {
    const int x = static_cast<int>(pair >> 32), y = static_cast<int>(pair & 0xffffffffu);
    resolve_vertex_pair({geo_.owner[x], x - geo_.first[geo_.owner[x]]},
                        {geo_.owner[y], y - geo_.first[geo_.owner[y]]});
  }

  // 4. Unique keys in a deterministic order.
  std::sort(found_.begin(), found_.end());
  found_.erase(std::unique(found_.begin(), found_.end()), found_.end());
  return std::move(found_);
}

}  // namespace

std::vector<DdaContact> detect_contacts(const RockMass& state, double range,
                                        const std::vector<DdaContact>& previous, bool first_step,
                                        DetectionCounters* counters) {
  DetectionCounters local;
  FISSURE_ASSERT(sorted_by_key(previous));
  Detector detector(state, range, previous);
  const std::vector<ContactKey> keys = detector.run(counters ? *counters : local);

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
    for (const int e : {key.edge, bj.polygon.next(key.edge), bj.polygon.prev(key.edge)})
      if ((before = detector.previous_contact({key.block_i, key.vertex, key.block_j, e}))) break;
    if (before) {
      c.state = before->state;
      c.bonded = before->bonded;
      c.normal_force = before->normal_force;
      c.shear_force = before->shear_force;
      c.slip_sign = before->slip_sign;
      c.normal_multiplier = before->normal_multiplier;
      c.law = before->law;
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
