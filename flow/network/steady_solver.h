// Steady flow on a fracture network (theory.md 3.3): reduce (dead ends,
// isolated clusters), assemble T p* = q, solve, fill back, and evaluate the
// segment fluxes and the boundary inflows.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "core/geometry/vec2.h"
#include "flow/network/fluid.h"
#include "flow/network/network_reduction.h"
#include "flow/network/network_system.h"
#include "flow/network/node_conditions.h"
#include "flow/network/spd_solver.h"
#include "rockmass/fracture_graph.h"

namespace fissure::flow {

struct NetworkSolution {
  std::vector<double> pressure;  ///< p per node (Pa)
  std::vector<double> flux;      ///< per segment, node_a -> node_b (m^2/s per unit thickness)
  /// Per node, the rate entering the network there from outside (m^2/s): what
  /// the boundary supplies at a fixed-pressure node (< 0: outflow), the source
  /// at a free node.
  std::vector<double> inflow;
  int n_unknowns = 0;
  int n_dead_end_nodes = 0;
  int n_isolated_nodes = 0;  ///< nodes of clusters no fixed pressure reaches
  int n_components = 0;      ///< components with a fixed-pressure node
  /// Largest node-balance residual over the largest segment flux.
  double balance_error = 0;
  NetworkTopology topology;
  /// Wall time of the phases (s): reduction (dead ends, clusters), assembly
  /// of T and q, linear solve (analysis when the pattern changed,
  /// factorization or preconditioner set-up, solve), the rest (fill back,
  /// fluxes, balance). Reported by benchmarks/flow_steady.
  struct Seconds {
    double reduction = 0, assembly = 0, solve = 0, post = 0;
  } seconds;
};

/// Flux of every segment from potentials: q = c (p*_a - p*_b).
void segment_fluxes(const FractureGraph& graph, std::span<const double> conductance,
                    std::span<const double> potential, std::vector<double>& flux);

/// Per node inflow from outside and the balance residual, from segment fluxes.
void node_inflows(const FractureGraph& graph, std::span<const double> flux,
                  std::vector<double>& inflow);

class SteadySolver {
 public:
  explicit SteadySolver(const LinearSolverControls& controls, bool allow_petsc = true)
      : controls_(controls), allow_petsc_(allow_petsc) {}

  /// Solves for the pressures. `previous` (size n_nodes or empty) are kept at
  /// isolated nodes (0 when empty). Throws SolverError when fluid is injected
  /// into a cluster that no fixed pressure reaches (no steady state).
  NetworkSolution solve(const FractureGraph& graph, std::span<const double> conductance,
                        const NodeConditions& conditions, const FluidProperties& fluid,
                        const Vec2& gravity, std::span<const double> previous = {});

  nlohmann::json statistics() const;
  double seconds() const { return seconds_; }
  /// Its counters and its linear solver's (core/io/checkpoint.h), so that a
  /// restarted run counts as the uninterrupted one (but for the pattern's
  /// analysis, which a restart does again); it keeps nothing else from one
  /// solve to the next but the analysed pattern. A checkpoint without the
  /// linear solver's counts (written before they were kept) leaves them.
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a) {
    a("solves", self.solves_);
    a("seconds", self.seconds_);
    if constexpr (Archive::reading)
      if (!a.has("linear_solver_counts")) return;
    std::vector<std::string> names;
    std::vector<double> counts;
    self.linear_solver_counts(names, counts);
    a("linear_solver_counted", names);
    a("linear_solver_counts", counts);
    if constexpr (Archive::reading) self.restore_linear_solver_counts(names, counts);
  }

 private:
  LinearSolverControls controls_;
  bool allow_petsc_;
  std::unique_ptr<SpdSolver> solver_;
  std::vector<int> pattern_;  ///< unknown numbering + segments of the analysed pattern
  /// The linear solver's statistics with the counts of before a restore.
  nlohmann::json linear_solver_statistics() const;
  /// Its counts (the numbers of linear_solver_statistics) by name.
  void linear_solver_counts(std::vector<std::string>& names, std::vector<double>& counts) const;
  void restore_linear_solver_counts(const std::vector<std::string>& names,
                                    const std::vector<double>& counts);

  long solves_ = 0;
  double seconds_ = 0;
  /// The linear solver's counts before the last restore, less its own then.
  nlohmann::json linear_solver_before_ = nlohmann::json::object();
};

}  // namespace fissure::flow
