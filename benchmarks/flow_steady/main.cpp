// Steady network flow cost (issue 4, "Benchmarks"; docs/performance.md
// "flow_steady"): DFNs of two families (P21 = 2 1/m each, power-law trace
// lengths 1-20 m, log-normal apertures; the rock-mass generator) in squares
// sized so that the networks hold about 1e3, 1e4, 1e5 (and 1e6, direct only)
// segments; pressure 1 MPa on the left side, 0 on the right. Each network is
// solved by every back end of flow/network/spd_solver.h: direct (CHOLMOD),
// pcg (Eigen, Jacobi) and petsc (CG + BoomerAMG on the diagonally scaled
// system). Reported per solve:
// reduction (dead ends, isolated clusters), assembly, linear solve (first
// solve: analysis + factorization + solve; repeat: same pattern, new values,
// as in a coupled run) and the rest (fill back, fluxes, balance), the best of
// three runs, on one core (BLAS threads pinned to 1). Each back end's
// pressures are compared with the direct solution.
//
// The network of configs/flow_dfn_steady.yaml is also run through the
// coordinator and written to network.csv / network_segments.csv for the
// picture of docs/flow.md (plot.py).
//
// Usage: bench_flow_steady [OUTPUT.csv] [LARGEST_TARGET=1000000]
// PETSc options for the petsc back end may be given in PETSC_OPTIONS
// (prefix flow_, e.g. "-flow_pc_type gamg").
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "core/base/stopwatch.h"
#include "coupling/process_registry.h"
#include "flow/cubic_law/flow_controls.h"
#include "flow/network/apertures.h"
#include "flow/network/steady_solver.h"
#include "flow/network/trace_network.h"
#include "flow/rev/rev_dfn_source.h"
#include "rockmass/fields/fracture_flow.h"
#include "rockmass/generate_rock_mass.h"
#include "tests/support/run_scene.h"

using namespace fissure;
using namespace fissure::flow;

namespace {

struct Case {
  long target;  ///< segments wanted
  double size;  ///< side of the square (m), found by trial for the target
};

/// Two families (P21 = 2 1/m each, axial von Mises kappa = 6.25, i.e. a
/// spread of about 0.2 rad; lengths l^-2.5 on [1, 20] m; log-normal
/// apertures of median 50 um and log10 standard deviation 0.25), drawn by the
/// rock-mass DFN generator over the square of side `size`.
FractureGraph dfn_network(double size) {
  std::vector<DfnFamilySpec> families;
  for (double angle : {0.35, 1.9}) {
    DfnFamilySpec f;
    f.density_kind = DfnFamilySpec::Density::P21;
    f.density = 2;
    f.orientation.type = DistributionSpec::Type::VonMises;
    f.orientation.mean = angle;
    f.orientation.kappa = 6.25;
    f.length.type = DistributionSpec::Type::TruncatedPowerLaw;
    f.length.exponent = 2.5;
    f.length.min = 1;
    f.length.max = 20;
    f.aperture.type = DistributionSpec::Type::LogNormal;
    f.aperture.mean = 59.0e-6;
    f.aperture.std = 37.0e-6;
    families.push_back(f);
  }
  Box box;
  box.lo = Vec2(-size / 2, -size / 2);
  box.hi = Vec2(size / 2, size / 2);
  return build_trace_network(draw_dfn_traces(families, box, 42, 0), box, 1e-9 * size);
}

struct Row {
  int nodes = 0, segments = 0, unknowns = 0;
  NetworkSolution::Seconds t;
  double total = 0, difference = 0;
  long iterations = 0;
};

/// Solves g with one back end: [0] the first solve (pattern analysed),
/// [1] a second solve on the same solver (pattern reused), each the best of
/// three. `pressure` receives the solution.
std::array<Row, 2> run(const FractureGraph& g, LinearSolverControls::Type type,
                       const std::vector<double>& reference, std::vector<double>& pressure) {
  std::vector<double> c(g.n_segments());
  for (int s = 0; s < g.n_segments(); ++s)
    c[s] = segment_conductance(g.segments[s].aperture, g.segments[s].aperture, g.length(s), 1e-3);
  NodeConditions bc(g.n_nodes());
  for (int v : g.boundary_nodes.at("left")) bc.fixed_pressure[v] = 1e6;
  for (int v : g.boundary_nodes.at("right")) bc.fixed_pressure[v] = 0;
  LinearSolverControls controls;
  controls.type = type;
  controls.relative_tolerance = 1e-10;
  controls.max_iterations = 100000;
  std::array<Row, 2> best;
  for (int repeat = 0; repeat < 3; ++repeat) {
    SteadySolver solver(controls);
    long iterations_before = 0;
    for (int k = 0; k < 2; ++k) {
      const Stopwatch clock;
      const NetworkSolution sol = solver.solve(g, c, bc, FluidProperties{}, Vec2::Zero());
      const double total = clock.seconds();
      Row& r = best[k];
      if (repeat == 0 || total < r.total) {
        r.t = sol.seconds;
        r.total = total;
      }
      r.nodes = g.n_nodes();
      r.segments = g.n_segments();
      r.unknowns = sol.n_unknowns;
      const auto stats = solver.statistics();
      if (stats.contains("linear_solver") && stats["linear_solver"].contains("iterations")) {
        const long it = stats["linear_solver"]["iterations"].get<long>();
        r.iterations = it - iterations_before;
        iterations_before = it;
      }
      pressure = sol.pressure;
      if (!reference.empty()) {
        double d = 0;
        for (int v = 0; v < g.n_nodes(); ++v)
          d = std::max(d, std::abs(sol.pressure[v] - reference[v]) / 1e6);
        r.difference = d;
      }
    }
  }
  return best;
}

void write_config_network(const std::string& dir) {
  // configs/flow_dfn_steady.yaml through the coordinator: nodes with their
  // pressure and head, segments with aperture and flux (docs/flow.md figure).
  const Scene scene = read_scene(std::string(FISSURE_SOURCE_DIR "/configs/flow_dfn_steady.yaml"));
  const testing::RunResult r = testing::run_scene(scene, "bench_flow_steady");
  const FractureGraph& g = r.state.fields.get(kFractureGraph);
  const FractureFlowState& flow = r.state.fields.get(kFractureFlow);
  std::ofstream nodes(dir + "/network.csv");
  nodes << "x,y,pressure,head\n";
  const double rho_g = flow_controls(scene).fluid.density * 9.81;
  for (int v = 0; v < g.n_nodes(); ++v)
    nodes << g.nodes[v].x() << ',' << g.nodes[v].y() << ',' << flow.pressure[v] << ','
          << flow.pressure[v] / rho_g + g.nodes[v].y() << '\n';
  std::ofstream segs(dir + "/network_segments.csv");
  segs << "a,b,aperture,flux\n";
  for (int k = 0; k < g.n_segments(); ++k)
    segs << g.segments[k].node_a << ',' << g.segments[k].node_b << ',' << flow.aperture_a[k] << ','
         << flow.flux[k] << '\n';
  std::printf("configs/flow_dfn_steady.yaml: %d nodes, %d segments, %s in %.3f s\n", g.n_nodes(),
              g.n_segments(), r.summary.status.c_str(), r.summary.wall_seconds);
}

}  // namespace

int main(int argc, char** argv) {
  // One core: no BLAS threads inside CHOLMOD's supernodal factorization.
  setenv("OPENBLAS_NUM_THREADS", "1", 1);
  setenv("OMP_NUM_THREADS", "1", 1);
  const std::string dir = FISSURE_SOURCE_DIR "/benchmarks/flow_steady";
  const std::string csv = argc > 1 ? argv[1] : dir + "/results.csv";
  // Sides giving ~1e3, 1e4, 1e5 segments at this density (~7.8 segments per m^2).
  // 1e6 segments with the direct solver only (the iterative ones take minutes).
  const std::vector<Case> cases = {{1000, 11.3}, {10000, 35.8}, {100000, 113}, {1000000, 357}};
  const std::vector<std::pair<const char*, LinearSolverControls::Type>> solvers = {
      {"direct", LinearSolverControls::Type::Direct},
      {"pcg", LinearSolverControls::Type::Pcg},
      {"petsc", LinearSolverControls::Type::Petsc}};

  std::ofstream out(csv);
  out << "target,nodes,segments,unknowns,solver,solve_kind,build_s,reduction_s,assembly_s,"
         "linear_s,post_s,total_s,iterations,max_difference\n";
  std::printf("%8s %8s %8s %8s %-7s %-6s %9s %9s %9s %9s %9s %6s %9s\n", "target", "nodes",
              "segments", "unknowns", "solver", "solve", "build", "reduce", "assemble", "linear",
              "total", "iters", "diff");
  const long largest = argc > 2 ? std::atol(argv[2]) : 1000000;
  for (const Case& c : cases) {
    if (c.target > largest) continue;
    const Stopwatch clock;
    const FractureGraph g = dfn_network(c.size);
    const double build = clock.seconds();
    std::vector<double> reference;
    for (const auto& [name, type] : solvers) {
      if (c.target > 100000 && type != LinearSolverControls::Type::Direct) continue;
      std::vector<double> pressure;
      const std::array<Row, 2> rows = run(g, type, reference, pressure);
      if (reference.empty()) reference = pressure;
      for (int k = 0; k < 2; ++k) {
        const Row& r = rows[k];
        const char* kind = k == 0 ? "first" : "repeat";
        out << c.target << ',' << r.nodes << ',' << r.segments << ',' << r.unknowns << ',' << name
            << ',' << kind << ',' << build << ',' << r.t.reduction << ',' << r.t.assembly << ','
            << r.t.solve << ',' << r.t.post << ',' << r.total << ',' << r.iterations << ','
            << r.difference << '\n';
        std::printf("%8ld %8d %8d %8d %-7s %-6s %9.4f %9.4f %9.4f %9.4f %9.4f %6ld %9.2e\n",
                    c.target, r.nodes, r.segments, r.unknowns, name, kind, build, r.t.reduction,
                    r.t.assembly, r.t.solve, r.total, r.iterations, r.difference);
        std::fflush(stdout);
      }
    }
  }
  if (argc <= 2) write_config_network(dir);
  return 0;
}
