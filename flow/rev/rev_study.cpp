#include "flow/rev/rev_study.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <thread>

#include <fmt/format.h>

#include "core/base/errors.h"
#include "core/base/stopwatch.h"
#include "flow/rev/permeability.h"

namespace fissure::flow {

namespace {

constexpr double kQuarter = std::numbers::pi / 2;
// job, k00, k10, k01, k11, nodes, segments, connected, seconds, then the
// mechanics: blocks, contacts, slip fraction, cycles, equilibrium, and the
// compliance's 9 terms, column by column.
constexpr int kRowLength = 23;

struct Job {
  int size_index, realization;
  double angle;  ///< canonical rotation in [0, 90 deg)
  double cost;   ///< for ordering: larger squares first
};

/// Requested rotation -> (canonical rotation index, quarter turns).
struct RotationMap {
  std::vector<double> canonical;
  std::vector<std::pair<int, int>> of_rotation;
};

RotationMap map_rotations(const RevStudyConfig& c) {
  RotationMap m;
  for (int r = 0; r < c.rotations; ++r) {
    const double b = r * c.rotation_step;
    const int quarters = static_cast<int>(std::floor(b / kQuarter + 1e-9));
    double rest = b - quarters * kQuarter;
    if (std::abs(rest) < 1e-9) rest = 0;
    int index = -1;
    for (std::size_t k = 0; k < m.canonical.size(); ++k)
      if (std::abs(m.canonical[k] - rest) < 1e-9) index = static_cast<int>(k);
    if (index < 0) {
      index = static_cast<int>(m.canonical.size());
      m.canonical.push_back(rest);
    }
    m.of_rotation.emplace_back(index, quarters);
  }
  return m;
}

}  // namespace

double expected_study_nodes(const RevStudyConfig& config, const DomainSource& source) {
  const double domains_per_size =
      static_cast<double>(std::min(config.realizations, source.max_realizations())) *
      static_cast<double>(map_rotations(config).canonical.size());
  double nodes = 0;
  for (double size : config.sizes) nodes += domains_per_size * source.expected_nodes(size);
  return nodes;
}

void check_study_size(const RevStudyConfig& config, const DomainSource& source) {
  const double nodes = expected_study_nodes(config, source);
  if (nodes > config.max_nodes)
    throw SceneError(fmt::format(
        "{}: found a network expected to give about {:.3g} nodes (fracture crossings and trace "
        "ends) over the study's {} sizes x {} realizations x {} rotations, more than max_nodes "
        "= {:.3g}; expected lower densities, larger spacings, fewer or smaller sizes, fewer "
        "realizations or a larger max_nodes",
        config.network_location, nodes, config.sizes.size(),
        std::min(config.realizations, source.max_realizations()), config.rotations,
        config.max_nodes));
}

RevStudyResult run_rev_study(const RevStudyConfig& config, const DomainSource& source,
                             const ParallelContext& parallel, const DomainSolver& solver) {
  const Stopwatch wall;
  FISSURE_CHECK(!config.sizes.empty() && config.realizations >= 1 && config.rotations >= 1,
                SolverError, "rev: the study needs sizes, realizations >= 1 and rotations >= 1");
  RevStudyResult result;
  result.config = config;
  check_study_size(config, source);
  result.source = source.describe();
  result.ranks = parallel.size;
  const int realizations = std::min(config.realizations, source.max_realizations());
  result.config.realizations = realizations;

  // 1. Jobs: one per (size, realization, rotation modulo 90 deg), big first;
  //    rank r takes every size-th job.
  const RotationMap rotations = map_rotations(config);
  std::vector<Job> jobs;
  for (std::size_t s = 0; s < config.sizes.size(); ++s)
    for (int r = 0; r < realizations; ++r)
      for (double a : rotations.canonical)
        jobs.push_back({static_cast<int>(s), r, a, config.sizes[s]});
  std::stable_sort(jobs.begin(), jobs.end(),
                   [](const Job& x, const Job& y) { return x.cost > y.cost; });
  std::vector<int> mine;
  for (int j = parallel.rank; j < static_cast<int>(jobs.size()); j += parallel.size)
    mine.push_back(j);

  // 2. Threads pull jobs from a shared counter.
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int n_threads = std::max(1, std::min<int>(config.threads > 0 ? config.threads : hardware,
                                                  static_cast<int>(mine.size())));
  result.threads = n_threads;
  std::vector<double> rows(mine.size() * kRowLength, 0.0);
  std::atomic<int> next{0};
  std::vector<std::string> errors(n_threads);
  auto work = [&](int thread) {
    int current = 0;  // the job being solved, for the message of a failure
    try {
      for (int i = next++; i < static_cast<int>(mine.size()); i = next++) {
        current = i;
        const Job& job = jobs[mine[i]];
        const Stopwatch clock;
        const double size = config.sizes[job.size_index];
        DomainSolution solution;
        if (solver)
          solution = solver(job.realization, size, job.angle);
        else
          solution.permeability =
              domain_permeability(source.domain(job.realization, size, job.angle), size,
                                  config.fluid.viscosity, config.pressure_drop);
        const DomainPermeability& k = solution.permeability;
        double* row = &rows[i * kRowLength];
        row[0] = mine[i];
        row[1] = k.k(0, 0), row[2] = k.k(1, 0), row[3] = k.k(0, 1), row[4] = k.k(1, 1);
        row[5] = k.n_nodes, row[6] = k.n_segments, row[7] = k.connected;
        row[8] = clock.seconds();
        const DomainMechanics& m = solution.mechanics;
        row[9] = m.blocks, row[10] = m.contacts, row[11] = m.slip_fraction;
        row[12] = static_cast<double>(m.cycles), row[13] = m.equilibrium;
        std::copy(m.compliance.data(), m.compliance.data() + 9, row + 14);
      }
    } catch (const std::exception& e) {
      // The scene key whose values made this domain (the network's).
      const Job& job = jobs[mine[current]];
      errors[thread] =
          fmt::format("{}: size {:g} m, realization {}, rotation {:g} deg: {}",
                      config.network_location, config.sizes[job.size_index], job.realization + 1,
                      job.angle * 180 / std::numbers::pi, e.what());
      next = static_cast<int>(mine.size());
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < n_threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (std::thread& t : pool) t.join();
  for (const std::string& e : errors) FISSURE_CHECK(e.empty(), SolverError, "rev: " << e);

  // 3. Gather on rank 0.
  if (parallel.size > 1) rows = parallel.gather(rows);
  result.wall_seconds = wall.seconds();
  if (parallel.rank != 0) return result;

  // 4. Expand to every requested rotation: k(b) = Q^T k(canonical) Q.
  std::vector<std::vector<DomainResult>> by_job(jobs.size());
  std::vector<DomainResult> solved(jobs.size());
  for (std::size_t i = 0; i * kRowLength < rows.size(); ++i) {
    const double* row = &rows[i * kRowLength];
    const Job& job = jobs[static_cast<int>(row[0])];
    DomainResult d;
    d.size_index = job.size_index;
    d.realization = job.realization;
    d.angle = job.angle;
    d.k << row[1], row[3], row[2], row[4];
    d.n_nodes = static_cast<int>(row[5]);
    d.n_segments = static_cast<int>(row[6]);
    d.connected = row[7] != 0;
    d.seconds = row[8];
    d.mechanics = {static_cast<int>(row[9]),
                   static_cast<int>(row[10]),
                   row[11],
                   static_cast<long>(row[12]),
                   row[13] != 0,
                   Eigen::Matrix3d(Eigen::Map<const Eigen::Matrix3d>(row + 14))};
    result.solve_seconds += d.seconds;
    solved[static_cast<int>(row[0])] = d;
  }
  auto find_solved = [&](int s, int r, double a) -> const DomainResult& {
    for (std::size_t j = 0; j < jobs.size(); ++j)
      if (jobs[j].size_index == s && jobs[j].realization == r && jobs[j].angle == a)
        return solved[j];
    throw SolverError("rev: internal error, a rotation was not solved");
  };
  for (std::size_t s = 0; s < config.sizes.size(); ++s) {
    for (int r = 0; r < realizations; ++r) {
      std::vector<double> angles, values;
      RealizationFit fit;
      fit.size_index = static_cast<int>(s);
      fit.realization = r;
      for (int q = 0; q < config.rotations; ++q) {
        const auto [index, quarters] = rotations.of_rotation[q];
        const DomainResult& base = find_solved(static_cast<int>(s), r, rotations.canonical[index]);
        DomainResult d = base;
        d.angle = q * config.rotation_step;
        // The general (possibly unsymmetric) k transforms as Q^T k Q too.
        d.k = rotate_into(base.k, quarters * kQuarter);
        if (quarters == 0) d.k = base.k;
        result.domains.push_back(d);
        // Directional values along the square's x and y axes.
        angles.push_back(d.angle);
        values.push_back(d.k(0, 0));
        angles.push_back(d.angle + kQuarter);
        values.push_back(d.k(1, 1));
        if (rotations.canonical.size() == 1) {
          // Only quarter turns: the axes alone cannot fix k12; the domain's
          // own tensor gives the diagonal directions too (n.k.n).
          const double diagonal = 0.5 * (d.k(0, 1) + d.k(1, 0));
          const double mean = 0.5 * (d.k(0, 0) + d.k(1, 1));
          angles.push_back(d.angle + kQuarter / 2);
          values.push_back(mean + diagonal);
          angles.push_back(d.angle + 3 * kQuarter / 2);
          values.push_back(mean - diagonal);
        }
        const double scale = std::sqrt(std::abs(d.k(0, 0) * d.k(1, 1)));
        if (scale > 0)
          fit.asymmetry = std::max(fit.asymmetry, std::abs(d.k(0, 1) - d.k(1, 0)) / scale);
        fit.connected = fit.connected || d.connected;
      }
      fit.fit = fit_tensor(angles, values);
      result.fits.push_back(fit);
    }
  }
  summarize_rev(result);
  result.wall_seconds = wall.seconds();
  return result;
}

}  // namespace fissure::flow
