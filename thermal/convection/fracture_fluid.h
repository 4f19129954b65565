// The fracture water's energy balance (theory.md 4.2, docs/thermal.md 7) as
// rows and columns of the thermal step's linear system, so that the water
// and the blocks are solved together, implicitly, in one system per step:
//
//   C_f (a0 T_f - a1 T_f0 + a2 T_f-1) / dt          storage, C_f = rho_f c_f e L
//   + sum over pieces rho_f c_f |Q| T_upwind          advection (upwind: an
//                                                     M-matrix, no oscillation)
//   + rho_f c_f (water leaving the network) T_f - (water entering) T_in
//   + sum over walls int h (T_f - T_w) phi ds = 0,    h = Nu lambda_f / (2 e)
//
// and every wall node k of the blocks receives int h (T_f - T_w) psi_k ds,
// the same integrals with the wall's own P1 trace psi (lumped: the
// trapezoidal rule, consistent: two-point Gauss, as the capacity), so the
// heat the water gives is exactly the heat the walls get. With
// `nusselt: wall_temperature` (h -> infinity) each fluid node and the wall
// nodes at its place are one unknown, and the water's rows are added to it.
// Q is the flow's flux per segment (m^2/s, node_a -> node_b), e its mean
// hydraulic aperture; water enters or leaves the network where the fluxes
// of a graph node do not balance (the flow's boundaries and wells), at the
// inlet temperature of its boundary or, without an inlet, the initial
// temperature at that place.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <string>
#include <vector>

#include "core/base/bdf2.h"
#include "rockmass/fields/fracture_flow.h"
#include "rockmass/fracture_graph.h"
#include "thermal/conduction/thermal_mesh.h"
#include "thermal/convection/convection_settings.h"
#include "thermal/convection/fracture_fluid_grid.h"

namespace fissure::thermal {

/// The energy of the water over one step (J per metre of thickness).
struct FluidStepEnergy {
  double stored = 0;  ///< sum C_f (T1 - T0)
  /// What the BDF2 difference adds to `stored`: (a0 - 1) stored - a2 sum
  /// C_f (T0 - T-1); 0 with backward Euler (docs/thermal.md 5).
  double bdf2_correction = 0;
  double advected_in = 0;   ///< carried in by the water entering the network
  double advected_out = 0;  ///< carried out by the water leaving it
  double exchanged = 0;     ///< given to the walls of the blocks
};

class FractureFluid {
 public:
  using Triplet = Eigen::Triplet<double>;

  FractureFluid(FractureConvection settings, bool lumped)
      : c_(std::move(settings)), lumped_(lumped) {}

  const FractureConvection& settings() const { return c_; }
  bool built() const { return built_; }
  const FluidGrid& grid() const { return grid_; }
  int n_nodes() const { return grid_.n_nodes(); }

  /// The grid on the walls of `mesh`, and the inlet temperatures (per graph
  /// node: an inlet's, or initial(x)). Throws SceneError for an inlet on a
  /// boundary without fracture nodes, or unmatched walls in the
  /// wall-temperature limit.
  void build(const FractureGraph& graph, const ThermalMesh& mesh, double tolerance,
             const std::function<double(const Vec2&)>& initial);
  /// Wall-temperature limit: per fluid node, the wall mesh nodes it is one
  /// unknown with (empty otherwise).
  const std::vector<std::vector<int>>& merged_walls() const { return merged_; }

  /// Its unknowns: a fluid node on a wall in the wall-temperature limit is
  /// the wall's unknown (node_dof of its first wall node); the others
  /// follow the blocks' n_rock unknowns. Nodes on no piece have none (-1).
  /// Returns the total.
  int number(const std::vector<int>& node_dof, int n_rock);
  /// Per fluid node: its unknown, or -1.
  const std::vector<int>& dof() const { return dof_; }

  /// The coefficients of the flow `flow` on `graph`; false when they are
  /// the ones of the last call (the matrix stays).
  bool set_flow(const FractureGraph& graph, const FractureFlowState& flow);
  /// Its matrix entries for the step coefficient a0 / dt (in the coupled
  /// numbering; node_dof maps the wall nodes).
  void add_matrix(double coefficient, const std::vector<int>& node_dof,
                  std::vector<Triplet>& entries) const;
  /// Its right-hand side: storage C_f (a1 T0 - a2 T-1) / dt, the water
  /// entering at its temperature.
  void add_rhs(double a1_over_dt, double a2_over_dt, const std::vector<double>& t0,
               const std::vector<double>& tm, Eigen::VectorXd& rhs) const;
  /// Per fluid node, its value in the solution `x` (its own t0 where it
  /// has no unknown).
  std::vector<double> node_values(const Eigen::VectorXd& x, const std::vector<double>& t0) const;
  /// The energy terms of a step of dt from t0 to t1 (per fluid node), with
  /// the step's time difference `a` (core/base/bdf2.h) and the water at the
  /// step before, tm, and the wall temperatures of the rock nodes.
  FluidStepEnergy energy(double dt, const Bdf2Coefficients& a, const std::vector<double>& tm,
                         const std::vector<double>& t0, const std::vector<double>& t1,
                         const std::vector<double>& rock_node_t1) const;
  /// Per graph segment: the water's mean temperature along it.
  std::vector<double> segment_means(const FractureGraph& graph, const std::vector<double>& t) const;
  /// Segments with no block face on either side (traces of the flow's own
  /// network, fractures inside a block): their water exchanges no heat.
  int segments_without_walls() const { return segments_without_walls_; }
  /// The largest |Q| of the last flow (m^2/s), for the summary.
  double largest_flux() const { return largest_flux_; }

 private:
  /// Quadrature on a piece: parameters and weights (as fractions of its length).
  struct Point {
    double t, w;
  };
  std::vector<Point> quadrature() const;

  FractureConvection c_;
  bool lumped_ = true;
  bool built_ = false;
  FluidGrid grid_;
  std::vector<std::vector<int>> merged_;
  std::vector<double> inlet_temperature_;  ///< per fluid node (graph nodes)
  std::vector<int> dof_;
  // The last flow's coefficients.
  std::vector<double> flux_, aperture_a_, aperture_b_;  ///< as given (to see a change)
  std::vector<double> capacity_;                        ///< per fluid node, C_f (J/(K m))
  std::vector<double> inflow_;  ///< per fluid node, water entering from outside (m^2/s)
  std::vector<double> h_;       ///< per segment, W/(m^2 K); 0 in the wall-temperature limit
  double largest_flux_ = 0;
  int segments_without_walls_ = 0;
};

}  // namespace fissure::thermal
