// Block cutting benchmark (issue 3; docs/performance.md, section block_cutting)
//
// Run: build/benchmarks/bench_block_cutting [OUTPUT.csv]   (default: results.csv here)
//      build/benchmarks/bench_block_cutting --case N      (one case, in-process: profiling)
//
// Random DFNs of 1e3, 1e4 and 1e5 fractures at fixed density
// (tests/support/rock_mass_specs.h: P20 = 2 /m^2 of exponential traces of mean
// 2 m, a tunnel; the domain grows with N, the density does not). Each case
// runs in a forked child, so that its peak memory (ru_maxrss from wait4) is
// its own; an idle child gives the baseline of the program itself. The child
// times, best of R runs,
//  1. generation: the DFN traces (generate_traces),
//  2. cutting: cut_blocks, with its steps (input, exact arrangement,
//     merging, block extraction, fracture graph),
// and reports the counts. Then the cost exponent k of t = c N^k, fitted by
// least squares to log t against log N over the three cases. Targets
// (issue 3): 1e4 fractures cut in under 2 s on one core, k <= 1.2.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/base/stopwatch.h"
#include "rockmass/block_cutter.h"
#include "rockmass/generate_rock_mass.h"
#include "tests/support/rock_mass_specs.h"

using namespace fissure;

namespace {

/// What a child reports through its pipe (plain doubles).
struct CaseResult {
  double fractures = 0, blocks = 0, segments = 0, nodes = 0, domain_side = 0;
  double generation = 1e300, cutting = 1e300;  ///< s, best of the runs (wall)
  double cutting_cpu = 0;                      ///< s, process CPU time of the best cut
  double prepare = 0, arrange = 0, merge = 0, extract = 0, graph = 0;  ///< s, of the best cut
  double peak_rss_mb = 0;                                              ///< filled in by the parent
};

/// The child's work: `runs` generations and cuts of the DFN of n fractures.
CaseResult run_case(int n, int runs) {
  const RockMassSpec spec = testing::random_dfn_spec(n, 1000 + n);
  CaseResult r;
  r.domain_side = spec.domain[1].x();
  for (int run = 0; run < runs; ++run) {
    Stopwatch clock;
    const CutInput input = cut_input(spec);
    r.generation = std::min(r.generation, clock.lap());

    const double cpu0 = process_cpu_seconds();
    const CutResult cut = cut_blocks(input);
    const double t = clock.lap(), cpu = process_cpu_seconds() - cpu0;
    if (t < r.cutting) {
      const CutStatistics& s = cut.statistics;
      r.cutting = t;
      r.cutting_cpu = cpu;
      r.prepare = s.prepare_seconds;
      r.arrange = s.arrange_seconds;
      r.merge = s.merge_seconds;
      r.extract = s.extract_seconds;
      r.graph = s.graph_seconds;
    }
    r.fractures = static_cast<double>(input.traces.size());
    r.blocks = static_cast<double>(cut.blocks.size());
    r.segments = cut.graph.n_segments();
    r.nodes = cut.graph.n_nodes();
  }
  return r;
}

/// run_case(n, runs) in a forked child: its result and its peak RSS (MB).
/// n = 0: an idle child (the baseline).
CaseResult in_child(int n, int runs) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
  std::fflush(stdout);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    close(fds[0]);
    const CaseResult r = n > 0 ? run_case(n, runs) : CaseResult{};
    const ssize_t written = write(fds[1], &r, sizeof r);
    _exit(written == static_cast<ssize_t>(sizeof r) ? 0 : 1);
  }
  close(fds[1]);
  CaseResult r;
  const ssize_t got = read(fds[0], &r, sizeof r);
  close(fds[0]);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  if (got != static_cast<ssize_t>(sizeof r) || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(fmt::format("the case of {} fractures failed", n));
  r.peak_rss_mb = usage.ru_maxrss / 1024.0;  // Linux: KiB
  return r;
}

/// Least-squares slope of log y against log x.
double fitted_exponent(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double m = static_cast<double>(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

}  // namespace

int main(int argc, char** argv) {
  // One case in this process, for profiling (perf record, callgrind).
  if (argc > 2 && std::string(argv[1]) == "--case") {
    const CaseResult r = run_case(std::atoi(argv[2]), 1);
    std::printf(
        "%.0f fractures: generation %.3f s, cutting %.3f s (CPU %.3f s): input %.3f, "
        "arrangement %.3f, merging %.3f, extraction %.3f, graph %.3f\n",
        r.fractures, r.generation, r.cutting, r.cutting_cpu, r.prepare, r.arrange, r.merge,
        r.extract, r.graph);
    return 0;
  }
  const std::string csv =
      argc > 1 ? argv[1] : FISSURE_SOURCE_DIR "/benchmarks/block_cutting/results.csv";
  double load[3] = {0, 0, 0};
  getloadavg(load, 3);
  std::printf("block cutting: random DFNs at fixed density (load average %.2f at start)\n",
              load[0]);

  // 1. Baseline, then the three sizes (runs: best of R).
  const CaseResult baseline = in_child(0, 0);
  const std::vector<std::pair<int, int>> cases = {{1000, 5}, {10000, 3}, {100000, 2}};
  std::vector<CaseResult> results;
  std::printf("%9s %9s %8s %9s %8s %8s %8s %8s | %7s %7s %7s %7s %7s | %8s\n", "N", "drawn",
              "L (m)", "blocks", "segments", "gen (s)", "cut (s)", "cut cpu", "input", "arrange",
              "merge", "extract", "graph", "RSS (MB)");
  for (const auto& [n, runs] : cases) {
    results.push_back(in_child(n, runs));
    const CaseResult& r = results.back();
    std::printf(
        "%9d %9.0f %8.1f %9.0f %8.0f %8.3f %8.3f %8.3f | %7.3f %7.3f %7.3f %7.3f %7.3f | %8.1f\n",
        n, r.fractures, r.domain_side, r.blocks, r.segments, r.generation, r.cutting, r.cutting_cpu,
        r.prepare, r.arrange, r.merge, r.extract, r.graph, r.peak_rss_mb);
  }
  std::printf("baseline (idle child): %.1f MB\n", baseline.peak_rss_mb);

  // 2. Cost exponents over the three sizes, against the fractures drawn.
  std::vector<double> n, cut, cut_cpu, gen, memory;
  for (const CaseResult& r : results) {
    n.push_back(r.fractures);
    cut.push_back(r.cutting);
    cut_cpu.push_back(r.cutting_cpu);
    gen.push_back(r.generation);
    memory.push_back(r.peak_rss_mb - baseline.peak_rss_mb);
  }
  const double k_cut = fitted_exponent(n, cut), k_gen = fitted_exponent(n, gen);
  const double k_cpu = fitted_exponent(n, cut_cpu);
  // Memory above the baseline may be ~0 for the smallest case: fit it when
  // every case grew.
  const bool memory_grew =
      std::all_of(memory.begin(), memory.end(), [](double m) { return m > 0; });
  const double k_mem = memory_grew ? fitted_exponent(n, memory) : NAN;
  std::printf(
      "fitted exponents: cutting %.3f (CPU time %.3f), generation %.3f, memory above "
      "baseline %.3f\n",
      k_cut, k_cpu, k_gen, k_mem);
  const double t_1e4 = results[1].cutting;
  std::printf("targets: 1e4 cut in %.3f s (< 2 s: %s), exponent %.3f (<= 1.2: %s)\n", t_1e4,
              t_1e4 < 2 ? "met" : "MISSED", k_cut, k_cut <= 1.2 ? "met" : "MISSED");

  // 3. CSV: one row per case; the fits and the load repeated on each row.
  std::ofstream out(csv);
  out << "n_requested,n_drawn,domain_side_m,blocks,segments,nodes,generation_s,cutting_s,"
         "cutting_cpu_s,"
         "prepare_s,arrange_s,merge_s,extract_s,graph_s,peak_rss_mb,baseline_rss_mb,"
         "exponent_cutting,exponent_cutting_cpu,exponent_generation,exponent_memory,load_average\n";
  for (size_t i = 0; i < results.size(); ++i) {
    const CaseResult& r = results[i];
    out << fmt::format(
        "{},{},{:.4f},{},{},{},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.2f},"
        "{:.2f},{:.4f},{:.4f},{:.4f},{:.4f},{:.2f}\n",
        cases[i].first, r.fractures, r.domain_side, r.blocks, r.segments, r.nodes, r.generation,
        r.cutting, r.cutting_cpu, r.prepare, r.arrange, r.merge, r.extract, r.graph, r.peak_rss_mb,
        baseline.peak_rss_mb, k_cut, k_cpu, k_gen, k_mem, load[0]);
  }
  std::printf("wrote %s\n", csv.c_str());
  return t_1e4 < 2 && k_cut <= 1.2 ? 0 : 1;
}
