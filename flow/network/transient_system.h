// The semi-discrete transient network (theory.md 3.4, UDEC domain-pressure
// form made implicit):
//   S dp*/dt + T p* = r(t),   S_i = V_i / K_f,   V_i = sum_(segments at i) L e / 2,
//   r_i(t) = q_i(t) + sum_(fixed k) c_ik p*_k(t) + s_i,
// over the unknowns: free nodes with fluid volume (every node on a conducting
// segment; dead ends and isolated clusters stay in, storage regularizes them).
// s_i is an extra constant source, -dV_i/dt from aperture changes in the HM
// coupling. Built once per network; r(t) is cheap to evaluate at any t.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "flow/network/fluid.h"
#include "flow/network/network_system.h"
#include "rockmass/fracture_graph.h"

namespace fissure::flow {

/// Boundary conditions and sources at time t.
using ConditionsAt = std::function<NodeConditions(double t)>;

struct TransientSystem {
  NetworkSystem network;       ///< numbering and T (rhs unused)
  Eigen::VectorXd storage;     ///< S_i per unknown (m^2/Pa)
  Eigen::VectorXd extra;       ///< s_i per unknown (m^2/s)
  std::vector<double> offset;  ///< rho g.x per node: p = p* + offset
  /// Couplings of unknowns to fixed nodes: (unknown, node, c).
  struct Coupling {
    int unknown, node;
    double c;
  };
  std::vector<Coupling> couplings;
  ConditionsAt conditions;

  int n() const { return network.n_unknowns(); }
  /// r(t) over the unknowns.
  void rhs(double t, Eigen::VectorXd& r) const;
  /// Smallest S_i / T_ii: the explicit (forward Euler) fluid step limit,
  /// Gershgorin/positivity bound = dx^2 / 2D on a uniform chain (theory.md 3.4).
  double explicit_limit() const;
};

/// Builds the system. `storage_volume` is V_i per node (m^2). The set of
/// fixed nodes is taken from conditions(t0).
void build_transient_system(const FractureGraph& graph, std::span<const double> conductance,
                            std::span<const double> storage_volume, const FluidProperties& fluid,
                            const Vec2& gravity, ConditionsAt conditions, double t0,
                            TransientSystem& system);

/// Fluid volume per node (m^2 per unit thickness): half of each segment's
/// L (e_a + e_b) / 2 at either end; `length` per segment (m).
std::vector<double> node_volumes(const FractureGraph& graph, std::span<const double> length,
                                 std::span<const double> aperture_a,
                                 std::span<const double> aperture_b);

}  // namespace fissure::flow
