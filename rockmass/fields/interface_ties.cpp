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
  // lambda at each tied edge's pieces: what the continuum carries, turned.
  const std::vector<std::array<Vec2, 2>> carried = carried_tractions(state);
  std::vector<TieSpring> out;
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    const TiedEdge& e = edges_[k];
    const ContinuumInterface& i = published(state, e.interface);
    const double length = (e.start_b - e.start_a).norm();
    for (const Piece& p : e.pieces)
      for (int g = 0; g < 3; ++g) {
        TieSpring s;
        s.block = e.block;
        s.a = e.a;
        s.b = e.b;
        s.t = p.t0 + kGaussS[g] * (p.t1 - p.t0);
        s.edge = static_cast<int>(k);
        s.weight = kGaussW[g] * std::abs(p.t1 - p.t0) * length;
        const Vec2 start = (1 - s.t) * e.start_a + s.t * e.start_b;
        s.target = start + displacement_at(i, {p.edge, p.s0 + kGaussS[g] * (p.s1 - p.s0), 0});
        s.stiffness = s.weight * i.impedance.stiffness;
        s.force = s.weight * ((1 - s.t) * carried[k][0] + s.t * carried[k][1]);
        out.push_back(s);
      }
  }
  return out;
}

std::vector<std::array<Vec2, 2>> InterfaceTies::carried_tractions(const RockMass& state) const {
  // Each tied edge's pieces follow one another in the loads, as give()
  // writes them; the edge's traction is linear, so its first piece's ends
  // give its ends' values (extrapolated along the edge).
  std::vector<std::array<Vec2, 2>> tau(edges_.size(), {Vec2::Zero(), Vec2::Zero()});
  const auto* loads = state.fields.find(kContinuumInterfaceLoads);
  if (!loads) return tau;
  std::vector<const ContinuumInterfaceLoad*> given(interfaces_.size(), nullptr);
  std::vector<std::size_t> expected(interfaces_.size(), 0), next(interfaces_.size(), 0);
  for (const TiedEdge& e : edges_) expected[e.interface] += e.pieces.size();
  for (std::size_t k = 0; k < interfaces_.size(); ++k) {
    given[k] = find_interface(*loads, interfaces_[k].name);
    if (given[k] && given[k]->traction_pieces.size() != expected[k]) given[k] = nullptr;
  }
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    const TiedEdge& e = edges_[k];
    const ContinuumInterfaceLoad* l = given[e.interface];
    std::size_t& n = next[e.interface];
    if (!l) continue;
    // The longest piece fixes the line best.
    std::size_t best = 0;
    for (std::size_t q = 1; q < e.pieces.size(); ++q)
      if (std::abs(e.pieces[q].t1 - e.pieces[q].t0) >
          std::abs(e.pieces[best].t1 - e.pieces[best].t0))
        best = q;
    const TractionPiece& piece = l->traction_pieces[n + best];
    const double t0 = e.pieces[best].t0, t1 = e.pieces[best].t1;
    const Vec2 slope = (piece.t1 - piece.t0) / (t1 - t0);
    tau[k] = {-(piece.t0 - t0 * slope), -(piece.t0 + (1 - t0) * slope)};
    n += e.pieces.size();
  }
  return tau;
}

void InterfaceTies::give(RockMass& state, const std::vector<std::array<Vec2, 2>>& tau) const {
  auto& loads = state.fields.get_or_add(kContinuumInterfaceLoads);
  for (const Tied& i : interfaces_) interface_load(loads, i.name).traction_pieces.clear();
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    const TiedEdge& e = edges_[k];
    ContinuumInterfaceLoad& l = *find_interface(loads, interfaces_[e.interface].name);
    for (const Piece& p : e.pieces) {
      // The piece's ends in the continuum edge's direction (s0 < s1).
      const Vec2 at0 = (1 - p.t0) * tau[k][0] + p.t0 * tau[k][1];
      const Vec2 at1 = (1 - p.t1) * tau[k][0] + p.t1 * tau[k][1];
      l.traction_pieces.push_back({p.edge, p.s0, p.s1, -at0, -at1});
    }
  }
}

void InterfaceTies::give_first_tractions(RockMass& state) const {
  std::vector<std::array<Vec2, 2>> tau(edges_.size());
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    const TiedEdge& e = edges_[k];
    // The block's stress on its edge, sigma n (outward n of a
    // counter-clockwise loop), which the continuum holds.
    const Vec2 d = e.start_b - e.start_a;
    const Vec2 n = Vec2(d.y(), -d.x()) / d.norm();
    const Vector3& s = state.blocks[e.block].stress;
    const Vec2 on_block(s(0) * n.x() + s(2) * n.y(), s(2) * n.x() + s(1) * n.y());
    tau[k] = {on_block, on_block};
  }
  give(state, tau);
}

void InterfaceTies::give_tractions(RockMass& state, const std::vector<TieSpring>& springs) const {
  // Per tied edge, g_j = sum over its points of N_j w (lambda + p (X + u_c
  // - x)), N_0 = 1 - t, N_1 = t; tau = M^-1 g with M = L/6 [2 1; 1 2].
  std::vector<std::array<Vec2, 2>> g(edges_.size(), {Vec2::Zero(), Vec2::Zero()});
  for (const TieSpring& s : springs) {
    const Vec2 f = s.force + s.stiffness * (s.target - s.position(state));
    g[s.edge][0] += (1 - s.t) * f;
    g[s.edge][1] += s.t * f;
  }
  std::vector<std::array<Vec2, 2>> tau(edges_.size());
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    const double c = 2 / (edges_[k].start_b - edges_[k].start_a).norm();
    tau[k] = {c * (2 * g[k][0] - g[k][1]), c * (2 * g[k][1] - g[k][0])};
  }
  give(state, tau);
}

}  // namespace fissure

namespace fissure {

std::vector<double> InterfaceTies::given_forces(const RockMass& state) const {
  // f = M tau per edge, M = L/6 [2 1; 1 2]; the continuum carries -tau.
  const std::vector<std::array<Vec2, 2>> tau = carried_tractions(state);
  std::vector<double> f;
  f.reserve(4 * edges_.size());
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    const double l = (edges_[k].start_b - edges_[k].start_a).norm();
    const Vec2 f0 = -l / 6 * (2 * tau[k][0] + tau[k][1]), f1 = -l / 6 * (tau[k][0] + 2 * tau[k][1]);
    f.insert(f.end(), {f0.x(), f0.y(), f1.x(), f1.y()});
  }
  return f;
}

void InterfaceTies::set_given_forces(RockMass& state, std::span<const double> f) const {
  FISSURE_CHECK(f.size() == 4 * edges_.size(), std::logic_error,
                f.size() << " tie forces for " << edges_.size() << " tied edges");
  std::vector<std::array<Vec2, 2>> tau(edges_.size());
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    const double c = 2 / (edges_[k].start_b - edges_[k].start_a).norm();
    const Vec2 f0(f[4 * k], f[4 * k + 1]), f1(f[4 * k + 2], f[4 * k + 3]);
    // On the blocks: tau = M^-1 (-f).
    tau[k] = {-c * (2 * f0 - f1), -c * (2 * f1 - f0)};
  }
  give(state, tau);
}

}  // namespace fissure
