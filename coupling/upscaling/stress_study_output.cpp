// The stress study's tables (docs/upscaling.md section 4).
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "core/base/errors.h"
#include "core/io/atomic_file.h"
#include "coupling/upscaling/stress_study.h"

namespace fissure {

namespace {

constexpr double kDeg = 180 / std::numbers::pi;
constexpr double kMPa = 1e-6;

/// The mean and standard deviation of `values` (two passes: moduli of
/// 1e10 Pa would lose their spread in the sum of their squares).
void mean_std(const std::vector<double>& values, double& mean, double& std) {
  mean = std = 0;
  if (values.empty()) return;
  for (double v : values) mean += v;
  mean /= static_cast<double>(values.size());
  for (double v : values) std += (v - mean) * (v - mean);
  std = std::sqrt(std / static_cast<double>(values.size()));
}

/// sigma_1 / sigma_3, empty when infinite (sigma_3 = 0: read as NaN).
std::string ratio_text(const PrincipalStress& p) {
  const double r = p.ratio();
  return std::isfinite(r) ? fmt::format("{:.6g}", r) : std::string();
}

/// A value, or empty when not measured (read as NaN).
std::string measured(bool given, double value) {
  return given ? fmt::format("{:.6e}", value) : std::string();
}

/// A square's compliance term (1/Pa), empty when not measured.
std::string compliance(const flow::DomainResult& d, int i, int j) {
  const Eigen::Matrix3d& c = d.mechanics.compliance;
  return measured(!c.isZero(), c(i, j));
}

std::ofstream open(const std::filesystem::path& file) {
  std::ofstream out(file);
  FISSURE_CHECK(out, IoError, "rev: cannot write " << file.string());
  return out;
}

}  // namespace

SizeMechanics size_mechanics(const flow::RevStudyResult& r, int size_index) {
  SizeMechanics m;
  std::vector<double> slip, e1, e3, g13;
  for (const flow::DomainResult& d : r.domains)
    if (d.size_index == size_index && d.angle == 0) {
      slip.push_back(d.mechanics.slip_fraction);
      m.equilibrium += d.mechanics.equilibrium ? 1 : 0;
      m.blocks += d.mechanics.blocks;
      m.cycles += static_cast<double>(d.mechanics.cycles);
      m.seconds += d.seconds;
      const Eigen::Matrix3d& c = d.mechanics.compliance;
      if (c(0, 0) > 0 && c(1, 1) > 0 && c(2, 2) > 0) {
        e1.push_back(1 / c(0, 0));
        e3.push_back(1 / c(1, 1));
        g13.push_back(1 / c(2, 2));
        m.nu += -c(1, 0) / c(0, 0);
      }
    }
  const auto n = static_cast<double>(slip.size());
  if (n == 0) return m;
  mean_std(slip, m.slip, m.slip_std);
  m.equilibrium /= n;
  m.blocks /= n;
  m.cycles /= n;
  m.seconds /= n;
  m.measured = static_cast<int>(e1.size());
  mean_std(e1, m.e1, m.e1_std);
  mean_std(e3, m.e3, m.e3_std);
  mean_std(g13, m.g13, m.g13_std);
  if (m.measured > 0) m.nu /= m.measured;
  return m;
}

void write_stress_study(const std::vector<StressStateResult>& results, const std::string& outdir) {
  const std::filesystem::path dir(outdir);
  std::filesystem::create_directories(dir);
  {
    std::ofstream out = open(dir / "stress_states.csv");
    out << "state,sigma_1_MPa,sigma_3_MPa,sigma_1_angle_deg,mean_MPa,ratio,size,samples,"
           "mean_kmax,std_kmax,mean_kmin,std_kmin,mean_kxx,mean_kyy,mean_kxy,kmax_angle_deg,"
           "slip_fraction,std_slip_fraction,equilibrium_fraction,mean_blocks,mean_cycles,"
           "seconds_per_domain,mean_E_1,std_E_1,mean_E_3,std_E_3,mean_nu_13,mean_G_13,std_G_13\n";
    for (const StressStateResult& s : results) {
      for (std::size_t k = 0; k < s.rev.sizes.size(); ++k) {
        const flow::SizeStatistics& z = s.rev.sizes[k];
        const SizeMechanics m = size_mechanics(s.rev, static_cast<int>(k));
        out << fmt::format(
            "{},{:.6g},{:.6g},{:.6g},{:.6g},{},{},{},{:.8e},{:.4e},{:.8e},{:.4e},{:.8e},"
            "{:.8e},{:.8e},{:.6g},{:.6g},{:.4g},{:.4g},{:.6g},{:.6g},{:.4g},{},{},{},{},{},{},"
            "{}\n",
            s.state.index, s.principal.sigma_1 * kMPa, s.principal.sigma_3 * kMPa,
            s.principal.angle * kDeg, s.principal.mean() * kMPa, ratio_text(s.principal), z.size,
            z.samples, z.mean_kmax, z.std_kmax, z.mean_kmin, z.std_kmin, z.mean_kxx, z.mean_kyy,
            z.mean_kxy, z.mean_angle * kDeg, m.slip, m.slip_std, m.equilibrium, m.blocks, m.cycles,
            m.seconds, measured(m.measured > 0, m.e1), measured(m.measured > 0, m.e1_std),
            measured(m.measured > 0, m.e3), measured(m.measured > 0, m.e3_std),
            measured(m.measured > 0, m.nu), measured(m.measured > 0, m.g13),
            measured(m.measured > 0, m.g13_std));
      }
    }
  }
  {
    std::ofstream out = open(dir / "stress_domains.csv");
    out << "state,size,realization,rotation_deg,kxx,kyx,kxy,kyy,connected,blocks,contacts,"
           "slip_fraction,cycles,equilibrium,seconds,c11,c21,c31,c12,c22,c32,c13,c23,c33\n";
    for (const StressStateResult& s : results)
      for (const flow::DomainResult& d : s.rev.domains)
        out << fmt::format(
            "{},{},{},{:.6g},{:.10e},{:.10e},{:.10e},{:.10e},{},{},{},{:.6g},{},{},"
            "{:.4g},{},{},{},{},{},{},{},{},{}\n",
            s.state.index, s.rev.config.sizes[d.size_index], d.realization, d.angle * kDeg,
            d.k(0, 0), d.k(1, 0), d.k(0, 1), d.k(1, 1), d.connected ? 1 : 0, d.mechanics.blocks,
            d.mechanics.contacts, d.mechanics.slip_fraction, d.mechanics.cycles,
            d.mechanics.equilibrium ? 1 : 0, d.seconds, compliance(d, 0, 0), compliance(d, 1, 0),
            compliance(d, 2, 0), compliance(d, 0, 1), compliance(d, 1, 1), compliance(d, 2, 1),
            compliance(d, 0, 2), compliance(d, 1, 2), compliance(d, 2, 2));
  }
  nlohmann::json j;
  double wall = 0, solve = 0;
  for (const StressStateResult& s : results) {
    wall += s.rev.wall_seconds;
    solve += s.rev.solve_seconds;
    nlohmann::json state = {
        {"state", s.state.index},
        {"stress_Pa", {s.state.stress(0), s.state.stress(1), s.state.stress(2)}},
        {"effective_principal_MPa",
         {{"sigma_1", s.principal.sigma_1 * kMPa},
          {"sigma_3", s.principal.sigma_3 * kMPa},
          {"sigma_1_angle_deg", s.principal.angle * kDeg}}},
        {"rev_size", s.rev.rev_size ? nlohmann::json(*s.rev.rev_size) : nlohmann::json()},
        {"wall_seconds", s.rev.wall_seconds}};
    if (!s.rev.sizes.empty()) {
      const flow::SizeStatistics& z = s.rev.sizes.back();
      const SizeMechanics m = size_mechanics(s.rev, static_cast<int>(s.rev.sizes.size()) - 1);
      state["largest_size"] = {{"size", z.size},          {"k_max", z.mean_kmax},
                               {"k_min", z.mean_kmin},    {"k_max_angle_deg", z.mean_angle * kDeg},
                               {"slip_fraction", m.slip}, {"equilibrium_fraction", m.equilibrium}};
      if (m.measured > 0)
        state["largest_size"]["compliance"] = {{"E_1", m.e1},
                                               {"E_3", m.e3},
                                               {"nu_13", m.nu},
                                               {"G_13", m.g13},
                                               {"squares", m.measured}};
    }
    j["states"].push_back(state);
  }
  if (!results.empty()) {
    j["name"] = results.front().rev.config.name;
    j["source"] = results.front().rev.source;
    j["timing"] = {{"wall_seconds", wall},
                   {"solve_seconds", solve},
                   {"threads", results.front().rev.threads},
                   {"ranks", results.front().rev.ranks}};
  }
  write_file_atomically(dir / "stress.json", j.dump(2) + "\n");
}

}  // namespace fissure
