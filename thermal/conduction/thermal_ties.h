// The blocks' heat tied to a continuum interface (docs/architecture.md 5,
// "A discrete region inside the continuum"; docs/thermal.md): the exterior
// boundary edges of the block meshes that lie along an interface which takes
// heat_flow. The scheme is the mechanics' (rockmass/fields/interface_ties.h)
// for a scalar: on each tied mesh edge a heat flux q into the blocks, linear
// along the edge, flows out of the continuum (the `heat_flux_pieces` of
// continuum_interface_loads, rockmass/fields/interface_mortar.h); in a step
// the blocks take the heat flux
//   lambda + h (T_c(X) - T),
// lambda the flux the continuum last gave (turned), T_c its temperature at
// the edge point's place (its linear trace), and h the continuum's heat
// conductance at the interface (ContinuumInterface::impedance): the Robin
// term h int N_i N_j joins the conduction matrix as a convective edge's
// does, lambda + h T_c the load. After the step the blocks give the
// continuum q = M^-1 int N_j (lambda + h (T_c - T)) ds per edge. A fixed
// point has int N_j (T_c - T) ds = 0 on every tied edge (the temperatures
// continuous in the mortar's sense), and the heat that leaves one side
// enters the other at every pass.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/scene/exchanged_field.h"
#include "core/state/rock_mass.h"
#include "rockmass/fields/interface_mortar.h"
#include "rockmass/physical_quantities.h"
#include "thermal/conduction/conduction_matrices.h"
#include "thermal/conduction/thermal_mesh.h"

namespace fissure::thermal {

/// What the heat exchanges with ties, in the iterated scheme: the heat
/// flows it gives the continuum at each tied edge's ends (W/m).
inline constexpr ExchangedFieldKind kTieHeatFlows{"continuum_interface_loads.heat_flux",
                                                  &quantity::linear_power};

class ThermalTies {
 public:
  /// The exterior boundary edges of `mesh` along an interface which takes
  /// heat_flow, from its nodes' reference positions.
  static ThermalTies find(const ThermalMesh& mesh, const RockMass& state);
  bool empty() const { return mortar_.empty(); }

  /// The Robin terms of the tied edges, h int N_i N_j, as convective edges
  /// of the conduction matrices.
  void add_transfers(std::vector<EdgeTransfer>& convective) const;
  /// The step's load, int N_i (lambda + h T_c) ds at the tied edges' nodes'
  /// unknowns (W/m).
  void add_load(const RockMass& state, const std::vector<int>& node_dof,
                Eigen::VectorXd& load) const;
  /// What the Robin term takes out of the blocks at the temperatures `t`
  /// (per unknown), int h T ds over the tied edges (W/m): with the load,
  /// the heat the interface brings in.
  double robin_outflow(const RockMass& state, const std::vector<int>& node_dof,
                       const Eigen::VectorXd& t) const;
  /// Gives the continuum the heat fluxes of the step that ended with `t`.
  void give(RockMass& state, const std::vector<int>& node_dof, const Eigen::VectorXd& t) const;
  /// Gives it none (the start).
  void give_none(RockMass& state) const;

  /// The mortar: the exchanged values (kTieHeatFlows: its resultants) and
  /// what a checkpoint holds (its values).
  const InterfaceMortar<double>& mortar() const { return mortar_; }

 private:
  /// Per Gauss point of every piece: the callback f(k, node a, node b, t
  /// along the edge, weight, lambda, T_c, h).
  template <class Visit>
  void for_each_point(const RockMass& state, Visit&& visit) const;

  struct TiedEdge {
    int boundary_edge = -1;
    int a = -1, b = -1;  ///< its mesh nodes
    double h = 0;        ///< the continuum's conductance there, W/(m^2 K)
  };
  InterfaceMortar<double> mortar_{&ContinuumInterfaceLoad::heat_flux_pieces};
  std::vector<TiedEdge> edges_;  ///< per segment of mortar_
};

}  // namespace fissure::thermal
