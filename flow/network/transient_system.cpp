#include "flow/network/transient_system.h"

#include <algorithm>
#include <limits>

namespace fissure::flow {

std::vector<double> node_volumes(const FractureGraph& graph, std::span<const double> length,
                                 std::span<const double> aperture_a,
                                 std::span<const double> aperture_b) {
  std::vector<double> v(graph.n_nodes(), 0.0);
  for (int s = 0; s < graph.n_segments(); ++s) {
    const double half = 0.25 * length[s] * (aperture_a[s] + aperture_b[s]);
    v[graph.segments[s].node_a] += half;
    v[graph.segments[s].node_b] += half;
  }
  return v;
}

void TransientSystem::rhs(double t, Eigen::VectorXd& r) const {
  const NodeConditions nc = conditions(t);
  r = extra;
  for (int i = 0; i < n(); ++i) {
    const int v = network.node_of_unknown[i];
    r[i] += nc.source[v] + nc.exchange_conductance[v] * (nc.exchange_pressure[v] - offset[v]);
  }
  for (const Coupling& k : couplings)
    r[k.unknown] += k.c * (nc.fixed_pressure[k.node] - offset[k.node]);
}

double TransientSystem::explicit_limit() const {
  double limit = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n(); ++i) {
    const double tii = network.matrix.coeff(i, i);
    if (tii > 0) limit = std::min(limit, storage[i] / tii);
  }
  return limit;
}

void build_transient_system(const FractureGraph& graph, std::span<const double> conductance,
                            std::span<const double> storage_volume, const FluidProperties& fluid,
                            const Vec2& gravity, ConditionsAt conditions, double t0,
                            TransientSystem& sys) {
  const int n_nodes = graph.n_nodes();
  const NodeConditions nc0 = conditions(t0);
  sys.conditions = std::move(conditions);
  sys.offset.resize(n_nodes);
  for (int v = 0; v < n_nodes; ++v)
    sys.offset[v] = hydrostatic_offset(fluid, gravity, graph.nodes[v]);

  // Unknowns: free nodes on a conducting segment (they hold fluid).
  std::vector<char> include(n_nodes, 0);
  std::vector<int> segments;
  for (int s = 0; s < graph.n_segments(); ++s) {
    const FractureSegment& seg = graph.segments[s];
    if (conductance[s] <= 0 || seg.node_a == seg.node_b) continue;
    include[seg.node_a] = include[seg.node_b] = 1;
    segments.push_back(s);
  }
  number_unknowns(include, nc0, sys.network);
  std::vector<double> potential(n_nodes, 0.0);
  assemble_network(graph, conductance, segments, nc0, potential, sys.offset, sys.network);

  const int n = sys.n();
  sys.storage.resize(n);
  for (int i = 0; i < n; ++i)
    sys.storage[i] = storage_volume[sys.network.node_of_unknown[i]] / fluid.bulk_modulus;
  sys.extra.setZero(n);
  sys.couplings.clear();
  for (int s : segments) {
    const int a = graph.segments[s].node_a, b = graph.segments[s].node_b;
    const int ia = sys.network.unknown_of_node[a], ib = sys.network.unknown_of_node[b];
    if (ia >= 0 && ib < 0 && nc0.is_fixed(b)) sys.couplings.push_back({ia, b, conductance[s]});
    if (ib >= 0 && ia < 0 && nc0.is_fixed(a)) sys.couplings.push_back({ib, a, conductance[s]});
  }
}

}  // namespace fissure::flow
