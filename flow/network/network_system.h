// Node-balance assembly (theory.md 3.3, Jing eqs. 16-20 in pressure form):
//   sum_j c_ij (p*_i - p*_j) = q_i   at every free node i,
// with p* = p - rho_f g.x the flow potential. Fixed-pressure neighbours move
// to the right-hand side: q_i += c_ik p*_k. The matrix T (T_ii = sum_j c_ij,
// T_ij = -c_ij) is a symmetric M-matrix, SPD when every component holds a
// fixed node (network_reduction.h guarantees it) or when a storage diagonal is
// added (transient).
#pragma once

#include <span>
#include <vector>

#include "flow/network/node_conditions.h"
#include "flow/network/spd_solver.h"
#include "rockmass/fracture_graph.h"

namespace fissure::flow {

struct NetworkSystem {
  std::vector<int> unknown_of_node;  ///< -1: not an unknown (fixed, or left out)
  std::vector<int> node_of_unknown;
  SparseMatrix matrix;  ///< T over the unknowns, both triangles stored
  Eigen::VectorXd rhs;  ///< sources + fixed neighbours' c p*
  int n_unknowns() const { return static_cast<int>(node_of_unknown.size()); }
};

/// Numbers the unknowns: nodes with include[v] that are not fixed, in node order.
void number_unknowns(std::span<const char> include, const NodeConditions& conditions,
                     NetworkSystem& system);

/// Assembles T and the right-hand side over `segments` for the numbered
/// unknowns. `potential` holds p* at the fixed nodes (other entries unused);
/// `offset` p - p* per node, for the outside pressures of exchanging nodes
/// (empty: none, or 0).
void assemble_network(const FractureGraph& graph, std::span<const double> conductance,
                      std::span<const int> segments, const NodeConditions& conditions,
                      std::span<const double> potential, std::span<const double> offset,
                      NetworkSystem& system);

}  // namespace fissure::flow
