// The continuum's boundary conditions on the mesh (docs/continuum.md 4):
// which unknowns are prescribed (displacement components, pressures,
// temperatures) and which are tied (a rigid plate: one unknown for a
// component of all its nodes), and the loads (tractions, a plate's force,
// inflows of fluid and heat).
//
// Each field's full vector x (every node's value) is x = P y + x_D: y the
// free unknowns, P the prolongation (a plate's column has a 1 at each of its
// nodes), x_D the prescribed values. A system A x = b becomes
// P^T A P y = P^T (b - A x_D): symmetric when A is.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string_view>
#include <vector>

#include "continuum/poroelasticity/continuum_mesh.h"
#include "continuum/poroelasticity/continuum_settings.h"
#include "rockmass/fields/continuum_interface.h"

namespace fissure::continuum {

/// FieldNumbering::condition of an entry that is no unknown at all (the
/// midpoints of equal-order elements): held at 0.
inline constexpr int kUnused = -2;

struct FieldNumbering {
  std::vector<int> free_index;  ///< per full entry: its free unknown, or -1 (prescribed)
  int n_free = 0;
  Eigen::SparseMatrix<double> prolongation;  ///< P, full x free
  /// Per full entry: the condition that prescribes it, -1 (free) or kUnused.
  std::vector<int> condition;
  std::vector<double> value;  ///< per prescribed entry: its value before the history factor

  /// x_D at t: the prescribed values, 0 at free entries.
  Eigen::VectorXd prescribed(const std::vector<ContinuumCondition>& conditions, double t) const;
  /// The full vector P y + x_D.
  Eigen::VectorXd expand(const Eigen::VectorXd& y, const Eigen::VectorXd& prescribed) const;
  /// The free unknowns y of a full vector x (an iterative solver's first guess).
  Eigen::VectorXd free_part(const Eigen::VectorXd& x) const;
};

/// A numbering of n entries that are all free (P = I).
FieldNumbering free_numbering(int n);

struct ContinuumConstraints {
  FieldNumbering displacement, pressure, temperature;
  /// Per rigid-plate condition: its free displacement unknown.
  std::vector<std::pair<int, int>> plates;  ///< (condition, free index)

  /// Full load vectors at t: tractions and normal pressures (displacement
  /// unknowns), inflows of fluid (m^3/s per m, pressure unknowns) and of
  /// heat (W/m, temperature unknowns; with heat transfer's h T_inf).
  Eigen::VectorXd traction(const std::vector<ContinuumCondition>& conditions, double t) const;
  Eigen::VectorXd fluid_inflow(const std::vector<ContinuumCondition>& conditions, double t) const;
  Eigen::VectorXd heat_inflow(const std::vector<ContinuumCondition>& conditions, double t) const;
  /// The plates' forces at t, in the free displacement unknowns.
  Eigen::VectorXd plate_forces(const std::vector<ContinuumCondition>& conditions, double t) const;
  /// The heat transfer conditions' boundary matrix int_edge h N_i N_j (times
  /// 2 pi r when axisymmetric), full (vertex x vertex): the heat operator's
  /// share of h (T_inf - T), whose h T_inf is in heat_inflow. Empty without them.
  Eigen::SparseMatrix<double> heat_transfer;

  /// An interface's vertices (docs/continuum.md 4, "Interfaces"): the
  /// boundary's vertices in the order its edges meet them.
  std::vector<int> interface_vertices(std::string_view boundary) const;
  /// Adds to the full displacement load `f` the traction `traction` (Pa,
  /// one per vertex of `vertices`, linear along the edges) on the boundary:
  /// int N_a t W ds by the 3-point Gauss rule (exact: degree 4 at most).
  void add_interface_traction(std::string_view boundary, const std::vector<int>& vertices,
                              const std::vector<Vec2>& traction, Eigen::VectorXd& f) const;
  /// The same for tractions on pieces of `edges` (the interface's, in its
  /// published order), each linear along its piece.
  void add_interface_piece_traction(const std::vector<BoundaryEdge>& edges,
                                    const std::vector<TractionPiece>& pieces,
                                    Eigen::VectorXd& f) const;
  /// The nodal inflows (per vertex) of fluxes into the domain on pieces of
  /// `edges`, each linear along its piece: int N_a q ds with the edge's
  /// linear N (plane strain).
  void add_interface_piece_flux(const std::vector<BoundaryEdge>& edges,
                                const std::vector<HeatFluxPiece>& pieces, Eigen::VectorXd& f) const;
  /// Per vertex of `vertices`: int N_a W ds over the boundary (m, or m^2
  /// axisymmetric), its share of the boundary, which turns a nodal reaction
  /// into a flux per unit area.
  std::vector<double> vertex_measure(std::string_view boundary,
                                     const std::vector<int>& vertices) const;

  const ContinuumMesh* mesh = nullptr;
  bool axisymmetric = false;         ///< loads are totals over the ring (weight 2 pi r)
  bool linear_displacement = false;  ///< P1 displacement (the midpoints unused)
};

/// Numbers the unknowns under the scene's conditions. Throws fissure::Error
/// ("found ...; expected ...") when the displacement constraints leave a
/// rigid motion free (the problem would be singular).
ContinuumConstraints build_constraints(const ContinuumMesh& mesh,
                                       const std::vector<ContinuumCondition>& conditions,
                                       bool axisymmetric, bool linear_displacement = false);

}  // namespace fissure::continuum
