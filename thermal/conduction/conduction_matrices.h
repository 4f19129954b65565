// The P1 finite-element matrices of block conduction (theory.md 4.1) on the
// blocks' reference geometry, in the unknowns' numbering (node_dof: perfect
// contact gives the nodes of two faces one unknown):
//   conductance  K = sum_e A grad N^T lambda grad N
//                  + joint faces h_c int (N_i - N_j)(N_i - N_j) ds
//                  + convective boundaries h int N N ds;
//   capacity     M = sum_e rho c A / 12 (1 + delta_rs) (consistent), or its
//                  row sums rho c A / 3 (lumped).
// Boundary and joint terms are lumped (L / 2 per node) with lumped capacity,
// consistent (L / 6 [2 1; 1 2]) otherwise.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "thermal/conduction/thermal_mesh.h"

namespace fissure::thermal {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// Per triangle: its conductivity (xx, yy, xy) and volumetric capacity.
struct ElementProperties {
  std::vector<Eigen::Vector3d> conductivity;
  std::vector<double> capacity;
};

/// A mesh edge with a transfer coefficient h (W/(m^2 K)): a convective
/// boundary (to a fixed exterior) or a joint face (to its partner edge).
struct EdgeTransfer {
  int edge = -1;  ///< ThermalMesh::boundary_edges index
  double h = 0;
};

struct ConductionMatrices {
  SparseMatrix conductance;  ///< n_dofs x n_dofs
  SparseMatrix capacity;     ///< n_dofs x n_dofs (diagonal when lumped)
  /// Per node, its lumped capacity rho c A / 3 summed over its triangles
  /// (J/K per metre): the stored energy is sum_i C_i T_i.
  std::vector<double> node_capacity;
};

/// The weights w of a boundary edge of length L: int N_a N_b ds = w(a, b).
Eigen::Matrix2d edge_mass(double length, bool lumped);

ConductionMatrices conduction_matrices(const ThermalMesh& mesh, const ElementProperties& props,
                                       const std::vector<int>& node_dof, int n_dofs, bool lumped,
                                       const std::vector<EdgeTransfer>& joints,
                                       const std::vector<EdgeTransfer>& convective);

}  // namespace fissure::thermal
