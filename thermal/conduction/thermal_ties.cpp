#include "thermal/conduction/thermal_ties.h"

#include <array>
#include <cmath>

#include "core/base/errors.h"

namespace fissure::thermal {

namespace {
/// The 2-point Gauss rule on [0, 1]: exact for the products of two linear
/// functions along a piece.
constexpr double kGaussPoint = 0.28867513459481287;  // 1 / (2 sqrt 3)
constexpr std::array<double, 2> kGaussS = {0.5 - kGaussPoint, 0.5 + kGaussPoint};
}  // namespace

ThermalTies ThermalTies::find(const ThermalMesh& mesh, const RockMass& state) {
  ThermalTies out;
  const std::vector<ContinuumInterface>* interfaces = state.fields.find(kContinuumInterfaces);
  if (!interfaces) return out;
  for (const ContinuumInterface& i : *interfaces) {
    if (!i.takes.heat_flow || i.edges.empty()) continue;
    for (std::size_t e = 0; e < mesh.boundary_edges.size(); ++e) {
      const BoundaryEdge& edge = mesh.boundary_edges[e];
      if (edge.partner >= 0) continue;  // a joint face between two blocks
      if (out.mortar_.add(i, mesh.nodes[edge.a], mesh.nodes[edge.b], edge.a, edge.b))
        out.edges_.push_back({static_cast<int>(e), edge.a, edge.b, i.impedance.heat});
    }
  }
  if (!out.mortar_.empty()) out.mortar_.finish();
  return out;
}

void ThermalTies::add_transfers(std::vector<EdgeTransfer>& convective) const {
  for (const TiedEdge& e : edges_) convective.push_back({e.boundary_edge, e.h});
}

template <class Visit>
void ThermalTies::for_each_point(const RockMass& state, Visit&& visit) const {
  const std::vector<double> lambda = mortar_.carried(state);
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    const auto& segment = mortar_.segment(k);
    const ContinuumInterface& i = mortar_.published(state, segment.interface);
    FISSURE_CHECK(i.temperature.size() == i.nodes.size(), std::logic_error,
                  "interface '" << i.name << "' has no temperature trace");
    for (const SegmentPiece& p : segment.pieces)
      for (const double g : kGaussS) {
        const double t = p.t0 + g * (p.t1 - p.t0);
        const double w = 0.5 * std::abs(p.t1 - p.t0) * segment.length();
        const double t_c = temperature_at(i, {p.edge, p.s0 + g * (p.s1 - p.s0), 0});
        visit(k, t, w, (1 - t) * lambda[segment.node_a] + t * lambda[segment.node_b], t_c,
              edges_[k].h);
      }
  }
}

void ThermalTies::add_load(const RockMass& state, const std::vector<int>& node_dof,
                           Eigen::VectorXd& load) const {
  for_each_point(state,
                 [&](std::size_t k, double t, double w, double lambda, double t_c, double h) {
                   const double q = w * (lambda + h * t_c);
                   load[node_dof[edges_[k].a]] += (1 - t) * q;
                   load[node_dof[edges_[k].b]] += t * q;
                 });
}

double ThermalTies::robin_outflow(const RockMass& state, const std::vector<int>& node_dof,
                                  const Eigen::VectorXd& temperature) const {
  double out = 0;
  for_each_point(state, [&](std::size_t k, double t, double w, double, double, double h) {
    out += w * h *
           ((1 - t) * temperature[node_dof[edges_[k].a]] + t * temperature[node_dof[edges_[k].b]]);
  });
  return out;
}

void ThermalTies::give(RockMass& state, const std::vector<int>& node_dof,
                       const Eigen::VectorXd& temperature) const {
  std::vector<double> g(mortar_.n_nodes(), 0.0);
  for_each_point(
      state, [&](std::size_t k, double t, double w, double lambda, double t_c, double h) {
        const double tb =
            (1 - t) * temperature[node_dof[edges_[k].a]] + t * temperature[node_dof[edges_[k].b]];
        const double q = w * (lambda + h * (t_c - tb));
        g[mortar_.segment(k).node_a] += (1 - t) * q;
        g[mortar_.segment(k).node_b] += t * q;
      });
  mortar_.give(state, mortar_.project(g));
}

void ThermalTies::give_none(RockMass& state) const {
  mortar_.give(state, std::vector<double>(mortar_.n_nodes(), 0.0));
}

}  // namespace fissure::thermal
