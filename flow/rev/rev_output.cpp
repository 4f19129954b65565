#include "flow/rev/rev_output.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "core/base/errors.h"
#include "core/io/atomic_file.h"

namespace fissure::flow {

namespace {

constexpr double kDeg = 180 / std::numbers::pi;

std::ofstream open(const std::filesystem::path& file) {
  std::ofstream out(file);
  FISSURE_CHECK(out, IoError, "rev: cannot write " << file.string());
  return out;
}

nlohmann::json finite_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json();
}

}  // namespace

void write_rev_output(const RevStudyResult& r, const std::filesystem::path& outdir) {
  std::filesystem::create_directories(outdir);
  {
    std::ofstream out = open(outdir / "domains.csv");
    out << "size,realization,rotation_deg,kxx,kyx,kxy,kyy,nodes,segments,connected,seconds\n";
    for (const DomainResult& d : r.domains)
      out << fmt::format("{},{},{:.6g},{:.10e},{:.10e},{:.10e},{:.10e},{},{},{},{:.4g}\n",
                         r.config.sizes[d.size_index], d.realization, d.angle * kDeg, d.k(0, 0),
                         d.k(1, 0), d.k(0, 1), d.k(1, 1), d.n_nodes, d.n_segments,
                         d.connected ? 1 : 0, d.seconds);
  }
  {
    std::ofstream out = open(outdir / "fits.csv");
    out << "size,realization,k11,k12,k22,k_max,k_min,angle_deg,misfit,asymmetry,connected\n";
    for (const RealizationFit& f : r.fits)
      out << fmt::format("{},{},{:.10e},{:.10e},{:.10e},{:.10e},{:.10e},{:.6g},{:.4e},{:.4e},{}\n",
                         r.config.sizes[f.size_index], f.realization, f.fit.k(0, 0), f.fit.k(0, 1),
                         f.fit.k(1, 1), f.fit.k_max, f.fit.k_min, f.fit.angle * kDeg, f.fit.misfit,
                         f.asymmetry, f.connected ? 1 : 0);
  }
  {
    std::ofstream out = open(outdir / "sizes.csv");
    out << "size,samples,mean_kxx,mean_kyy,mean_kxy,mean_kmax,std_kmax,cv_kmax,mean_kmin,"
           "std_kmin,cv_kmin,mean_angle_deg,mean_misfit,representative\n";
    for (const SizeStatistics& s : r.sizes)
      out << fmt::format(
          "{},{},{:.10e},{:.10e},{:.10e},{:.10e},{:.4e},{:.4g},{:.10e},{:.4e},{:.4g},"
          "{:.6g},{:.4e},{}\n",
          s.size, s.samples, s.mean_kxx, s.mean_kyy, s.mean_kxy, s.mean_kmax, s.std_kmax, s.cv_kmax,
          s.mean_kmin, s.std_kmin, s.cv_kmin, s.mean_angle * kDeg, s.mean_misfit,
          s.meets_criterion ? 1 : 0);
  }
  nlohmann::json j;
  j["name"] = r.config.name;
  if (!r.study_file.empty()) j["study_file"] = r.study_file;
  j["source"] = r.source;
  j["config"] = {{"sizes", r.config.sizes},
                 {"realizations", r.config.realizations},
                 {"rotation_step_deg", r.config.rotation_step * kDeg},
                 {"rotations", r.config.rotations},
                 {"viscosity", r.config.fluid.viscosity},
                 {"pressure_drop", r.config.pressure_drop},
                 {"cv_max", r.config.cv_max},
                 {"misfit_max", r.config.misfit_max}};
  j["criterion"] =
      "smallest size from which on every size has CV(k_max) < cv_max, CV(k_min) < cv_max, mean "
      "ellipse misfit < misfit_max and a connected network in every realization";
  j["rev_size"] = r.rev_size ? nlohmann::json(*r.rev_size) : nlohmann::json();
  for (const SizeStatistics& s : r.sizes)
    j["sizes"].push_back(
        {{"size", s.size},
         {"samples", s.samples},
         {"mean_k", {{"xx", s.mean_kxx}, {"yy", s.mean_kyy}, {"xy", s.mean_kxy}}},
         {"k_max", {{"mean", s.mean_kmax}, {"std", s.std_kmax}, {"cv", finite_or_null(s.cv_kmax)}}},
         {"k_min", {{"mean", s.mean_kmin}, {"std", s.std_kmin}, {"cv", finite_or_null(s.cv_kmin)}}},
         {"mean_angle_deg", s.mean_angle * kDeg},
         {"mean_misfit", s.mean_misfit},
         {"representative", s.meets_criterion}});
  j["timing"] = {{"wall_seconds", r.wall_seconds},
                 {"solve_seconds", r.solve_seconds},
                 {"threads", r.threads},
                 {"ranks", r.ranks},
                 {"domains_solved", r.domains.size()}};
  write_file_atomically(outdir / "rev.json", j.dump(2) + "\n");
}

}  // namespace fissure::flow
