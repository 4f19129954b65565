// Equivalent permeability of one square domain (theory.md 3.7 steps 2-3,
// after Min, Jing et al. 2004): every boundary node gets the linear pressure
// p = p0 - G.x (so P1 and P2 on opposite sides and a linear pressure on the
// lateral sides), once with G along x and once along y. The mean flux is
//   q_bar = (1/A) sum_b x_b Q_b     (Q_b outward boundary flows),
// exact for divergence-free flow. Then k_ij = -mu q_bar_i / (dp/dx_j). Both
// load cases share the matrix (same fixed nodes): one factorization, two
// solves. Dead ends and clusters that touch no side carry no flow and are
// left out (network_reduction.h).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "rockmass/fracture_graph.h"

namespace fissure::flow {

struct DomainPermeability {
  /// k in the domain's frame (m^2): column j is the response to a gradient
  /// along axis j, so k(0,0) = kxx, k(1,0) = kyx, k(0,1) = kxy, k(1,1) = kyy.
  Eigen::Matrix2d k = Eigen::Matrix2d::Zero();
  int n_nodes = 0, n_segments = 0, n_unknowns = 0;
  bool connected = false;  ///< some fracture path joins two different sides
};

/// `size` is the side of the square [-size/2, size/2]^2 the graph is in.
/// Apertures are the segments' e0. Viscosity in Pa s; the result does not
/// depend on it or on the pressure drop (linear problem), which is size x |G|.
DomainPermeability domain_permeability(const FractureGraph& graph, double size, double viscosity,
                                       double pressure_drop = 1e6);

/// The same with the apertures at each segment's ends (m; the cubic law of
/// a linearly varying aperture, apertures.h): a deformed network's
/// (docs/upscaling.md).
DomainPermeability domain_permeability(const FractureGraph& graph, double size, double viscosity,
                                       double pressure_drop, const std::vector<double>& aperture_a,
                                       const std::vector<double>& aperture_b);

}  // namespace fissure::flow
