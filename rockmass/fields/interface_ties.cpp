#include "rockmass/fields/interface_ties.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "core/base/errors.h"

namespace fissure {

namespace {

/// The block's vertices at the start (its polygon before it first moved).
const std::vector<Vec2>& start_vertices(const Block& b) {
  return b.initial_vertices.size() == b.polygon.vertices.size() ? b.initial_vertices
                                                                : b.polygon.vertices;
}

/// The 3-point Gauss rule on [0, 1]: exact for the products of a linear
/// block displacement and the continuum's quadratic trace (degree 3).
constexpr double kGaussPoint = 0.3872983346207417;  // sqrt(0.6) / 2
constexpr std::array<double, 3> kGaussS = {0.5 - kGaussPoint, 0.5, 0.5 + kGaussPoint};
constexpr std::array<double, 3> kGaussW = {5.0 / 18, 8.0 / 18, 5.0 / 18};

/// The part of the block edge [a, b] along the continuum's edge [p, q]:
/// its ends' parameters on both, or nothing (not on the edge's line, or
/// overlapping it over no length).
std::optional<std::array<double, 4>> overlap(const Vec2& a, const Vec2& b, const Vec2& p,
                                             const Vec2& q, double tolerance) {
  const Vec2 pq = q - p;
  const double l2 = pq.squaredNorm();
  auto off_line = [&](const Vec2& x) {
    return std::abs(pq.x() * (x.y() - p.y()) - pq.y() * (x.x() - p.x())) / std::sqrt(l2);
  };
  if (off_line(a) > tolerance || off_line(b) > tolerance) return std::nullopt;
  const double sa = (a - p).dot(pq) / l2, sb = (b - p).dot(pq) / l2;
  const double s0 = std::max(0.0, std::min(sa, sb)), s1 = std::min(1.0, std::max(sa, sb));
  if ((s1 - s0) * std::sqrt(l2) <= tolerance) return std::nullopt;
  // The same ends on the block's edge, t = (s - sa) / (sb - sa).
  return std::array<double, 4>{s0, s1, (s0 - sa) / (sb - sa), (s1 - sa) / (sb - sa)};
}

}  // namespace

InterfaceTies InterfaceTies::find(const RockMass& state) {
  InterfaceTies out;
  const std::vector<ContinuumInterface>* interfaces = state.fields.find(kContinuumInterfaces);
  if (!interfaces) return out;
  for (const ContinuumInterface& i : *interfaces) {
    if (!i.takes.traction || i.edges.empty()) continue;
    const double tolerance = interface_tolerance(i);
    const int index = static_cast<int>(out.interfaces_.size());
    std::size_t found = 0;
    for (std::size_t b = 0; b < state.blocks.size(); ++b) {
      const Block& block = state.blocks[b];
      if (block.fixed) continue;
      const std::vector<Vec2>& x = start_vertices(block);
      // Its outer loop's edges (a region's outline never runs along a
      // block's hole).
      const int n = block.polygon.loop_offsets.size() > 1 ? block.polygon.loop_offsets[1]
                                                          : block.polygon.n_vertices();
      for (int v = 0; v < n; ++v) {
        const int w = (v + 1) % n;
        TiedEdge e{index, static_cast<int>(b), v, w, x[v], x[w], {}};
        for (std::size_t c = 0; c < i.edges.size(); ++c) {
          const auto piece =
              overlap(x[v], x[w], i.nodes[i.edges[c][0]], i.nodes[i.edges[c][1]], tolerance);
          if (piece)
            e.pieces.push_back(
                {static_cast<int>(c), (*piece)[0], (*piece)[1], (*piece)[2], (*piece)[3]});
        }
        // Tied when its pieces cover it.
        double covered = 0;
        for (const Piece& p : e.pieces) covered += std::abs(p.t1 - p.t0);
        if (e.pieces.empty() || std::abs(covered - 1) * (x[w] - x[v]).norm() > 1e3 * tolerance)
          continue;
        out.edges_.push_back(std::move(e));
        ++found;
      }
    }
    if (found == 0) continue;
    Tied tied;
    tied.name = i.name;
    for (const auto& [p, q] : i.edges) tied.length.push_back((i.nodes[q] - i.nodes[p]).norm());
    out.interfaces_.push_back(std::move(tied));
  }
  return out;
}

const ContinuumInterface& InterfaceTies::published(const RockMass& state, int interface) const {
  const ContinuumInterface* i =
      find_interface(state.fields.get(kContinuumInterfaces), interfaces_[interface].name);
  FISSURE_CHECK(i && i->midside_displacement.size() == i->edges.size(), std::logic_error,
                "interface '" << interfaces_[interface].name << "' has no displacement trace");
  return *i;
}

std::vector<TieSpring> InterfaceTies::springs(const RockMass& state) const {
  const auto* loads = state.fields.find(kContinuumInterfaceLoads);
  std::vector<TieSpring> out;
  for (const TiedEdge& e : edges_) {
    const ContinuumInterface& i = published(state, e.interface);
    const ContinuumInterfaceLoad* given = loads ? find_interface(*loads, i.name) : nullptr;
    const bool traction = given && given->edge_traction.size() == i.edges.size();
    const double length = (e.start_b - e.start_a).norm();
    for (const Piece& p : e.pieces)
      for (int g = 0; g < 3; ++g) {
        TieSpring s;
        s.block = e.block;
        s.a = e.a;
        s.b = e.b;
        s.t = p.t0 + kGaussS[g] * (p.t1 - p.t0);
        s.interface = e.interface;
        s.place = {p.edge, p.s0 + kGaussS[g] * (p.s1 - p.s0), 0};
        s.weight = kGaussW[g] * std::abs(p.t1 - p.t0) * length;
        const Vec2 start = (1 - s.t) * e.start_a + s.t * e.start_b;
        s.target = start + displacement_at(i, s.place);
        s.stiffness = s.weight * i.impedance.stiffness;
        if (traction) {
          const std::array<double, 2> n = linear_weights(s.place.s);
          const std::array<Vec2, 2>& t = given->edge_traction[p.edge];
          s.force = -s.weight * (n[0] * t[0] + n[1] * t[1]);
        } else {
          s.force = Vec2::Zero();
        }
        out.push_back(s);
      }
  }
  return out;
}

void InterfaceTies::give(RockMass& state,
                         const std::vector<std::vector<std::array<Vec2, 2>>>& g) const {
  auto& loads = state.fields.get_or_add(kContinuumInterfaceLoads);
  for (std::size_t k = 0; k < interfaces_.size(); ++k) {
    const Tied& i = interfaces_[k];
    ContinuumInterfaceLoad& l = interface_load(loads, i.name);
    if (l.edge_traction.size() != i.length.size())
      l.edge_traction.assign(i.length.size(), {Vec2::Zero(), Vec2::Zero()});
    // Per edge, M = l/6 [2 1; 1 2], M^-1 = 2/l [2 -1; -1 2].
    for (std::size_t e = 0; e < i.length.size(); ++e) {
      const double c = 2 / i.length[e];
      l.edge_traction[e][0] += c * (2 * g[k][e][0] - g[k][e][1]);
      l.edge_traction[e][1] += c * (2 * g[k][e][1] - g[k][e][0]);
    }
  }
}

void InterfaceTies::give_first_tractions(RockMass& state) const {
  std::vector<std::vector<std::array<Vec2, 2>>> g(interfaces_.size());
  for (std::size_t k = 0; k < interfaces_.size(); ++k)
    g[k].assign(interfaces_[k].length.size(), {Vec2::Zero(), Vec2::Zero()});
  for (const TiedEdge& e : edges_) {
    // The block's stress on its edge, sigma n (outward n of a
    // counter-clockwise loop), is held by the continuum, which bears -sigma n.
    const Vec2 d = e.start_b - e.start_a;
    const Vec2 n = Vec2(d.y(), -d.x()) / d.norm();
    const Vector3& s = state.blocks[e.block].stress;
    const Vec2 on_continuum = -Vec2(s(0) * n.x() + s(2) * n.y(), s(2) * n.x() + s(1) * n.y());
    for (const Piece& p : e.pieces) {
      const double length = std::abs(p.t1 - p.t0) * d.norm();
      // int N_j over the piece: the mean of N_j at its ends times its length.
      g[e.interface][p.edge][0] += on_continuum * length * (2 - p.s0 - p.s1) / 2;
      g[e.interface][p.edge][1] += on_continuum * length * (p.s0 + p.s1) / 2;
    }
  }
  // From nothing: the tractions are M^-1 g.
  auto* loads = state.fields.find(kContinuumInterfaceLoads);
  if (loads)
    for (const Tied& i : interfaces_)
      if (ContinuumInterfaceLoad* l = find_interface(*loads, i.name)) l->edge_traction.clear();
  give(state, g);
}

void InterfaceTies::give_tractions(RockMass& state, const std::vector<TieSpring>& springs) const {
  // g_j = sum over the points of N_j w p (X + u_c - x): the spring part of
  // the blocks' traction, projected; the continuum bears it turned.
  std::vector<std::vector<std::array<Vec2, 2>>> g(interfaces_.size());
  for (std::size_t k = 0; k < interfaces_.size(); ++k)
    g[k].assign(interfaces_[k].length.size(), {Vec2::Zero(), Vec2::Zero()});
  for (const TieSpring& s : springs) {
    const std::array<double, 2> n = linear_weights(s.place.s);
    const Vec2 pull = -s.stiffness * (s.target - s.position(state));
    g[s.interface][s.place.edge][0] += n[0] * pull;
    g[s.interface][s.place.edge][1] += n[1] * pull;
  }
  give(state, g);
}

}  // namespace fissure
