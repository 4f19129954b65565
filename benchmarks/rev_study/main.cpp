// REV study wall time (issue 4, "Benchmarks"; docs/performance.md
// "rev_study"): the full study of configs/flow_rev_study.yaml (20 sizes x 20
// realizations x 12 rotations of a four-family DFN, P21 = 6.4 1/m,
// theory.md 3.7) with 1 and with 2 threads in this process, and with
// `mpirun -np 2 fissure rev ... -j 1` (two MPI ranks of one thread each) when
// mpirun is available. Every run must give the same tensors: the maximum
// relative difference of the fitted k_max/k_min against the 1-thread run is
// reported (the MPI run's is read back from fits.csv, written with 11
// significant digits). The 2-thread study's output goes to the build tree
// (bench-output/rev_study/study/); its plots (scripts/plot_rev.py) are copied
// to docs/img/flow_rev_size.png and flow_rev_polar.png for docs/flow.md.
//
// Usage: bench_rev_study [OUTPUT.csv]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "flow/rev/read_rev_study.h"
#include "flow/rev/rev_dfn_source.h"
#include "flow/rev/rev_output.h"
#include "flow/rev/rev_study.h"

using namespace fissure;
using namespace fissure::flow;

namespace {

const std::string kDir = FISSURE_SOURCE_DIR "/benchmarks/rev_study";
/// Study outputs (CSV of every domain) stay in the build tree.
const std::string kOut = FISSURE_BINARY_DIR "/bench-output/rev_study";
const std::string kStudy = FISSURE_SOURCE_DIR "/configs/flow_rev_study.yaml";

/// k_max and k_min of every fit, in order.
std::vector<double> principal_values(const RevStudyResult& r) {
  std::vector<double> v;
  for (const RealizationFit& f : r.fits) {
    v.push_back(f.fit.k_max);
    v.push_back(f.fit.k_min);
  }
  return v;
}

/// The same from a fits.csv (columns k_max, k_min are 6th and 7th).
std::vector<double> principal_values(const std::string& fits_csv) {
  std::ifstream in(fits_csv);
  std::vector<double> v;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string cell;
    for (int k = 0; std::getline(row, cell, ','); ++k)
      if (k == 5 || k == 6) v.push_back(std::stod(cell));
  }
  return v;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return INFINITY;
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != 0 || b[i] != 0)
      d = std::max(d, std::abs(a[i] - b[i]) / std::max(std::abs(a[i]), std::abs(b[i])));
  return d;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string csv = argc > 1 ? argv[1] : kDir + "/results.csv";
  std::ofstream out(csv);
  out << "run,ranks,threads,domains_solved,wall_s,solve_s,rev_size,max_difference\n";
  std::vector<double> reference;
  for (int threads : {1, 2}) {
    // A fresh source per run: its DFN realizations are generated (and cached)
    // on first use, which is part of the study's cost.
    RevStudy study = read_rev_study(kStudy, rev_dfn_source_factory());
    study.config.threads = threads;
    const RevStudyResult r = run_rev_study(study.config, *study.source);
    const std::vector<double> k = principal_values(r);
    if (reference.empty()) reference = k;
    const double diff = max_difference(k, reference);
    out << "threads," << 1 << ',' << r.threads << ',' << r.domains.size() << ',' << r.wall_seconds
        << ',' << r.solve_seconds << ',' << (r.rev_size ? *r.rev_size : NAN) << ',' << diff << '\n';
    std::printf(
        "1 rank x %d threads: %zu domains in %.2f s wall (%.2f s solving), REV size %s, "
        "max difference %.1e\n",
        r.threads, r.domains.size(), r.wall_seconds, r.solve_seconds,
        r.rev_size ? std::to_string(*r.rev_size).c_str() : "none", diff);
    if (threads == 2) {
      // The study's own plots become the figures of docs/flow.md.
      write_rev_output(r, kOut + "/study");
      const std::string plot = "/usr/bin/python3 " FISSURE_SOURCE_DIR "/scripts/plot_rev.py " +
                               kOut + "/study > /dev/null 2>&1";
      if (std::system(plot.c_str()) == 0)
        for (const char* name : {"rev_size.png", "rev_polar.png"})
          std::filesystem::copy_file(kOut + "/study/" + name,
                                     FISSURE_SOURCE_DIR "/docs/img/flow_" + std::string(name),
                                     std::filesystem::copy_options::overwrite_existing);
    }
  }
  // Two MPI ranks of one thread each, through the command line.
  if (std::system("command -v mpirun > /dev/null 2>&1") == 0) {
    const std::string outdir = kOut + "/study_mpi";
    const std::string command =
        "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun -np 2 " FISSURE_APP
        " rev " +
        kStudy + " -j 1 --no-plots -q -o " + outdir + " > " + outdir + ".log 2>&1";
    std::filesystem::create_directories(outdir);
    const int status = std::system(command.c_str());
    std::ifstream json(outdir + "/rev.json");
    std::stringstream text;
    text << json.rdbuf();
    const std::string j = text.str();
    auto number_after = [&](const std::string& key) {
      const auto at = j.find("\"" + key + "\"");
      return at == std::string::npos ? NAN : std::atof(j.c_str() + j.find(':', at) + 1);
    };
    const double diff = max_difference(principal_values(outdir + "/fits.csv"), reference);
    out << "mpirun,2,1," << number_after("domains_solved") << ',' << number_after("wall_seconds")
        << ',' << number_after("solve_seconds") << ',' << number_after("rev_size") << ',' << diff
        << '\n';
    std::printf("mpirun -np 2 (1 thread each): exit %d, %.2f s wall, max difference %.1e\n", status,
                number_after("wall_seconds"), diff);
  }
  return 0;
}
