#include "rockmass/fields/interface_ties.h"

#include <array>
#include <cmath>

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

}  // namespace

InterfaceTies InterfaceTies::find(const RockMass& state) {
  InterfaceTies out;
  const std::vector<ContinuumInterface>* interfaces = state.fields.find(kContinuumInterfaces);
  if (!interfaces) return out;
  for (const ContinuumInterface& i : *interfaces) {
    if (!i.takes.traction || i.edges.empty()) continue;
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
        // A block's vertices, named by block and vertex.
        const long key = static_cast<long>(b) << 20;
        if (out.mortar_.add(i, x[v], x[w], key + v, key + w))
          out.edges_.push_back({static_cast<int>(b), v, w});
      }
    }
  }
  if (!out.mortar_.empty()) out.mortar_.finish();
  return out;
}

std::vector<TieSpring> InterfaceTies::springs(const RockMass& state) const {
  // lambda: what the continuum carries, turned.
  const std::vector<Vec2> carried = mortar_.carried(state);
  std::vector<TieSpring> out;
  for (std::size_t k = 0; k < mortar_.size(); ++k) {
    const auto& segment = mortar_.segment(k);
    const ContinuumInterface& i = mortar_.published(state, segment.interface);
    FISSURE_CHECK(i.midside_displacement.size() == i.edges.size(), std::logic_error,
                  "interface '" << i.name << "' has no displacement trace");
    const double length = segment.length();
    for (const SegmentPiece& p : segment.pieces)
      for (int g = 0; g < 3; ++g) {
        TieSpring s;
        s.block = edges_[k].block;
        s.a = edges_[k].a;
        s.b = edges_[k].b;
        s.t = p.t0 + kGaussS[g] * (p.t1 - p.t0);
        s.edge = static_cast<int>(k);
        s.weight = kGaussW[g] * std::abs(p.t1 - p.t0) * length;
        const Vec2 start = (1 - s.t) * segment.a + s.t * segment.b;
        s.target = start + displacement_at(i, {p.edge, p.s0 + kGaussS[g] * (p.s1 - p.s0), 0});
        s.stiffness = s.weight * i.impedance.stiffness;
        s.force = s.weight * ((1 - s.t) * carried[segment.node_a] + s.t * carried[segment.node_b]);
        out.push_back(s);
      }
  }
  return out;
}

std::vector<ExchangedField> InterfaceTies::exchanged_values(const RockMass& state) const {
  if (empty()) return {};
  return {{&kTieTractions, mortar_.given_resultants(state)}};
}

void InterfaceTies::set_exchanged_values(RockMass& state,
                                         std::span<const ExchangedField> values) const {
  if (empty() || values.empty() || values[0].values.size() != mortar_.n_values()) return;
  mortar_.set_given_resultants(state, values[0].values);
}

void InterfaceTies::give_first_tractions(RockMass& state) const {
  // The block's stress on each tied edge, sigma n (outward n of a
  // counter-clockwise loop), which the continuum holds, projected: exact
  // on an edge between two others of the same block (a vertex's two edges
  // of one block see one stress), the mean where a block's edge meets
  // another block's.
  std::vector<Vec2> g(mortar_.n_nodes(), Vec2::Zero());
  for (std::size_t k = 0; k < mortar_.size(); ++k) {
    const auto& segment = mortar_.segment(k);
    const Vec2 d = segment.b - segment.a;
    const Vec2 n = Vec2(d.y(), -d.x()) / d.norm();
    const Vector3& s = state.blocks[edges_[k].block].stress;
    const Vec2 on_block(s(0) * n.x() + s(2) * n.y(), s(2) * n.x() + s(1) * n.y());
    g[segment.node_a] += on_block * d.norm() / 2;
    g[segment.node_b] += on_block * d.norm() / 2;
  }
  mortar_.give(state, mortar_.project(g));
}

void InterfaceTies::give_tractions(RockMass& state, const std::vector<TieSpring>& springs) const {
  std::vector<Vec2> at;
  at.reserve(springs.size());
  for (const TieSpring& s : springs) at.push_back(s.position(state));
  give_tractions(state, springs, at);
}

void InterfaceTies::give_tractions(RockMass& state, const std::vector<TieSpring>& springs,
                                   const std::vector<Vec2>& at) const {
  // Per tied edge, g_j = sum over its points of N_j w (lambda + p (X + u_c
  // - x)), N_0 = 1 - t, N_1 = t; tau = M^-1 g.
  std::vector<Vec2> g(mortar_.n_nodes(), Vec2::Zero());
  for (std::size_t k = 0; k < springs.size(); ++k) {
    const TieSpring& s = springs[k];
    const Vec2 f = s.force + s.stiffness * (s.target - at[k]);
    const auto& segment = mortar_.segment(s.edge);
    g[segment.node_a] += (1 - s.t) * f;
    g[segment.node_b] += s.t * f;
  }
  mortar_.give(state, mortar_.project(g));
}

}  // namespace fissure
