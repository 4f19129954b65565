#include "thermal/convection/fracture_fluid.h"

#include <fmt/format.h>

#include <cmath>

#include "core/base/errors.h"

namespace fissure::thermal {

void FractureFluid::build(const FractureGraph& graph, const ThermalMesh& mesh, double tolerance,
                          const std::function<double(const Vec2&)>& initial) {
  grid_ = build_fluid_grid(graph, mesh, tolerance);
  merged_.assign(grid_.n_nodes(), {});
  if (c_.wall_temperature) merged_ = wall_nodes_at_fluid_nodes(grid_, graph, c_.path);
  inlet_temperature_.assign(grid_.n_nodes(), 0.0);
  for (int i = 0; i < grid_.n_nodes(); ++i) inlet_temperature_[i] = initial(grid_.positions[i]);
  for (const FluidInlet& inlet : c_.inlets) {
    const auto it = graph.boundary_nodes.find(inlet.boundary);
    if (it == graph.boundary_nodes.end() || it->second.empty()) {
      std::string names;
      for (const auto& [name, nodes] : graph.boundary_nodes)
        if (!nodes.empty()) names += (names.empty() ? "" : ", ") + name;
      throw SceneError(fmt::format(
          "{}: found boundary '{}', which has no node of the fracture network; expected one of: {}",
          inlet.path, inlet.boundary, names));
    }
    for (const int v : it->second)
      inlet_temperature_[grid_.fluid_node_of_graph[v]] = inlet.temperature;
  }
  segments_without_walls_ = 0;
  for (int s = 0; s < graph.n_segments(); ++s) {
    bool walls = false;
    for (int k = grid_.first_piece[s]; k < grid_.first_piece[s + 1]; ++k)
      walls = walls || grid_.pieces[k].walls[0].exists() || grid_.pieces[k].walls[1].exists();
    segments_without_walls_ += walls ? 0 : 1;
  }
  flux_.clear();
  built_ = true;
}

int FractureFluid::number(const std::vector<int>& node_dof, int n_rock) {
  std::vector<char> on_piece(grid_.n_nodes(), 0);
  for (const FluidPiece& p : grid_.pieces) on_piece[p.from] = on_piece[p.to] = 1;
  dof_.assign(grid_.n_nodes(), -1);
  int n = n_rock;
  for (int i = 0; i < grid_.n_nodes(); ++i) {
    if (!on_piece[i]) continue;
    dof_[i] = merged_[i].empty() ? n++ : node_dof[merged_[i].front()];
  }
  return n;
}

bool FractureFluid::set_flow(const FractureGraph& graph, const FractureFlowState& flow) {
  FISSURE_CHECK(static_cast<int>(flow.flux.size()) == graph.n_segments() &&
                    flow.aperture_a.size() == flow.flux.size() &&
                    flow.aperture_b.size() == flow.flux.size() &&
                    static_cast<int>(grid_.first_piece.size()) == graph.n_segments() + 1,
                SolverError,
                c_.path << ": the fracture network changed (" << graph.n_segments()
                        << " segments, the fluid grid was built on " << grid_.first_piece.size() - 1
                        << "); the fracture convection follows the network it started on");
  if (flow.flux == flux_ && flow.aperture_a == aperture_a_ && flow.aperture_b == aperture_b_)
    return false;
  flux_ = flow.flux;
  aperture_a_ = flow.aperture_a;
  aperture_b_ = flow.aperture_b;
  const double rho_c = c_.volumetric_heat();
  capacity_.assign(grid_.n_nodes(), 0.0);
  inflow_.assign(grid_.n_nodes(), 0.0);
  h_.assign(graph.n_segments(), 0.0);
  largest_flux_ = 0;
  for (int s = 0; s < graph.n_segments(); ++s) {
    const double e = 0.5 * (flow.aperture_a[s] + flow.aperture_b[s]);
    if (!c_.wall_temperature && e > 0) h_[s] = c_.nusselt * c_.conductivity / (2 * e);
    for (int k = grid_.first_piece[s]; k < grid_.first_piece[s + 1]; ++k) {
      const FluidPiece& p = grid_.pieces[k];
      capacity_[p.from] += 0.5 * rho_c * e * p.length;
      capacity_[p.to] += 0.5 * rho_c * e * p.length;
    }
    if (grid_.first_piece[s] == grid_.first_piece[s + 1]) continue;  // no piece
    // Water the segment takes from node_a and gives to node_b: what does
    // not balance at a node comes from (or goes to) outside the network.
    const FractureSegment& seg = graph.segments[s];
    inflow_[grid_.fluid_node_of_graph[seg.node_a]] += flow.flux[s];
    inflow_[grid_.fluid_node_of_graph[seg.node_b]] -= flow.flux[s];
    largest_flux_ = std::max(largest_flux_, std::abs(flow.flux[s]));
  }
  return true;
}

std::vector<FractureFluid::Point> FractureFluid::quadrature() const {
  if (lumped_) return {{0, 0.5}, {1, 0.5}};
  const double d = 0.5 / std::sqrt(3.0);
  return {{0.5 - d, 0.5}, {0.5 + d, 0.5}};
}

void FractureFluid::add_matrix(double coefficient, const std::vector<int>& node_dof,
                               std::vector<Triplet>& entries) const {
  const double rho_c = c_.volumetric_heat();
  for (int i = 0; i < grid_.n_nodes(); ++i) {
    if (dof_[i] < 0) continue;
    entries.emplace_back(dof_[i], dof_[i], coefficient * capacity_[i]);
    if (inflow_[i] < 0) entries.emplace_back(dof_[i], dof_[i], -rho_c * inflow_[i]);
  }
  const std::vector<Point> points = quadrature();
  for (const FluidPiece& p : grid_.pieces) {
    // Upwind: the piece carries rho_f c_f |Q| T_up from its upstream node
    // to its downstream one.
    const double q = flux_[p.segment];
    const int up = dof_[q >= 0 ? p.from : p.to], down = dof_[q >= 0 ? p.to : p.from];
    entries.emplace_back(up, up, rho_c * std::abs(q));
    entries.emplace_back(down, up, -rho_c * std::abs(q));
    const double h = h_[p.segment];
    if (!(h > 0)) continue;
    const int fluid[2] = {dof_[p.from], dof_[p.to]};
    for (const WallTrace& w : p.walls) {
      if (!w.exists()) continue;
      const int wall[2] = {node_dof[w.nodes[0]], node_dof[w.nodes[1]]};
      for (const Point& x : points) {
        const double c = h * x.w * p.length;
        const double phi[2] = {1 - x.t, x.t};
        double psi[2];
        for (int k = 0; k < 2; ++k) psi[k] = (1 - x.t) * w.at_from[k] + x.t * w.at_to[k];
        // h (T_f - T_w): + to the water's rows, - to the walls'.
        for (int r = 0; r < 2; ++r)
          for (int s = 0; s < 2; ++s) {
            entries.emplace_back(fluid[r], fluid[s], c * phi[r] * phi[s]);
            entries.emplace_back(fluid[r], wall[s], -c * phi[r] * psi[s]);
            entries.emplace_back(wall[r], wall[s], c * psi[r] * psi[s]);
            entries.emplace_back(wall[r], fluid[s], -c * psi[r] * phi[s]);
          }
      }
    }
  }
}

void FractureFluid::add_rhs(double a1_over_dt, double a2_over_dt, const std::vector<double>& t0,
                            const std::vector<double>& tm, Eigen::VectorXd& rhs) const {
  const double rho_c = c_.volumetric_heat();
  for (int i = 0; i < grid_.n_nodes(); ++i) {
    if (dof_[i] < 0) continue;
    rhs[dof_[i]] += capacity_[i] * (a1_over_dt * t0[i] - a2_over_dt * tm[i]);
    if (inflow_[i] > 0) rhs[dof_[i]] += rho_c * inflow_[i] * inlet_temperature_[i];
  }
}

std::vector<double> FractureFluid::node_values(const Eigen::VectorXd& x,
                                               const std::vector<double>& t0) const {
  std::vector<double> t(grid_.n_nodes());
  for (int i = 0; i < grid_.n_nodes(); ++i) t[i] = dof_[i] >= 0 ? x[dof_[i]] : t0[i];
  return t;
}

FluidStepEnergy FractureFluid::energy(double dt, const Bdf2Coefficients& a,
                                      const std::vector<double>& tm, const std::vector<double>& t0,
                                      const std::vector<double>& t1,
                                      const std::vector<double>& rock_node_t1) const {
  const double rho_c = c_.volumetric_heat();
  FluidStepEnergy e;
  double stored_before = 0;  // sum C_f (T0 - T-1), the step before's
  for (int i = 0; i < grid_.n_nodes(); ++i) {
    if (dof_[i] < 0) continue;
    e.stored += capacity_[i] * (t1[i] - t0[i]);
    if (a.a2 != 0) stored_before += capacity_[i] * (t0[i] - tm[i]);
    if (inflow_[i] > 0) e.advected_in += dt * rho_c * inflow_[i] * inlet_temperature_[i];
    if (inflow_[i] < 0) e.advected_out -= dt * rho_c * inflow_[i] * t1[i];
  }
  // The BDF2 difference of the stored heat, a0 dE1 - a2 dE0 (a0 - a1 + a2
  // = 0), is what the water's rows balance (docs/thermal.md 5).
  e.bdf2_correction = (a.a0 - 1) * e.stored - a.a2 * stored_before;
  if (c_.wall_temperature) {
    // The water's rows are part of its walls' rows: what it gives them is
    // what its own balance leaves.
    e.exchanged = e.advected_in - e.advected_out - e.stored - e.bdf2_correction;
    return e;
  }
  const std::vector<Point> points = quadrature();
  for (const FluidPiece& p : grid_.pieces) {
    const double h = h_[p.segment];
    if (!(h > 0)) continue;
    for (const WallTrace& w : p.walls) {
      if (!w.exists()) continue;
      for (const Point& x : points) {
        const double tf = (1 - x.t) * t1[p.from] + x.t * t1[p.to];
        double tw = 0;
        for (int k = 0; k < 2; ++k)
          tw += ((1 - x.t) * w.at_from[k] + x.t * w.at_to[k]) * rock_node_t1[w.nodes[k]];
        e.exchanged += dt * h * x.w * p.length * (tf - tw);
      }
    }
  }
  return e;
}

std::vector<double> FractureFluid::segment_means(const FractureGraph& graph,
                                                 const std::vector<double>& t) const {
  std::vector<double> mean(graph.n_segments());
  for (int s = 0; s < graph.n_segments(); ++s) {
    const int first = grid_.first_piece[s], last = grid_.first_piece[s + 1];
    if (first == last) {
      const FractureSegment& seg = graph.segments[s];
      mean[s] = 0.5 * (t[grid_.fluid_node_of_graph[seg.node_a]] +
                       t[grid_.fluid_node_of_graph[seg.node_b]]);
      continue;
    }
    double sum = 0, length = 0;
    for (int k = first; k < last; ++k) {
      const FluidPiece& p = grid_.pieces[k];
      sum += 0.5 * p.length * (t[p.from] + t[p.to]);
      length += p.length;
    }
    mean[s] = sum / length;
  }
  return mean;
}

}  // namespace fissure::thermal
