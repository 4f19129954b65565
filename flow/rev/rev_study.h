// The permeability REV study (theory.md 3.7; Min, Jing et al. 2004): square
// sub-domains of a DFN over a list of sizes, several realizations per size,
// each rotated in steps; the full 2x2 tensor per domain, a least-squares
// tensor fit over the rotations with its misfit, principal values and
// direction, mean and spread per size, and the REV size.
//
// A square rotated by b + 90 deg is the same square with its axes turned, so
// only rotations modulo 90 deg are solved; the tensor of every requested
// rotation follows exactly from them (k' = Q^T k Q, Q a quarter turn).
// Work is spread over threads, and over MPI ranks when launched with mpirun
// (rank 0 gathers).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "flow/network/fluid.h"
#include "flow/rev/domain_source.h"
#include "flow/rev/permeability.h"
#include "flow/rev/tensor_fit.h"

namespace fissure::flow {

struct RevStudyConfig {
  std::string name = "rev";
  std::vector<double> sizes;  ///< square sides (m), increasing
  int realizations = 10;
  double rotation_step = 0.5235987755982988;  ///< rad (30 deg)
  int rotations = 12;                         ///< directions b = 0, step, 2 step, ...
  FluidProperties fluid;                      ///< its viscosity (the fluid's default: water)
  double pressure_drop = 1e6;                 ///< across a domain, Pa (k does not depend on it)
  double cv_max = 0.1;                        ///< REV: coefficient of variation of k_max and k_min
  double misfit_max = 0.1;                    ///< REV: mean ellipse misfit
  int threads = 0;                            ///< 0 = all hardware threads
  /// A study expected to build more network nodes than this, summed over its
  /// domains, is refused before it starts (check_study_size).
  double max_nodes = 1e7;
  /// "file:line:column: network" of the study file, for that refusal.
  std::string network_location = "network";
  /// "file:line:column: sizes", for a command line that names a size the
  /// study does not have.
  std::string sizes_location = "sizes";
};

/// Network nodes the study is expected to build: the source's
/// expected_nodes summed over every (size, realization, rotation modulo 90
/// deg) domain it solves.
double expected_study_nodes(const RevStudyConfig& config, const DomainSource& source);

/// Throws SceneError, located at the study's network, when
/// expected_study_nodes exceeds config.max_nodes (a density or spacing typed
/// wrong would otherwise run for hours or run out of memory).
void check_study_size(const RevStudyConfig& config, const DomainSource& source);

/// What a domain solved under stress adds (the mechanical stage,
/// docs/upscaling.md); the defaults for a geometric study.
struct DomainMechanics {
  int blocks = 0, contacts = 0;
  double slip_fraction = 0;  ///< of the closed contacts, the share that slips
  long cycles = 0;           ///< the mechanics' cycles to equilibrium
  bool equilibrium = true;   ///< the mechanics reached its solve ratio
  /// The tangent compliance of the loaded square in its own frame (1/Pa,
  /// tension +, Voigt: sxx, syy, sxy and e_xx, e_yy, gamma_xy): column j is
  /// the mean strain per unit stress increment j; zero when not measured.
  Eigen::Matrix3d compliance = Eigen::Matrix3d::Zero();
};

/// One domain's permeability as a solver finds it.
struct DomainSolution {
  DomainPermeability permeability;
  DomainMechanics mechanics;
};

/// Solves the square of side `size` of realization r rotated by `angle`
/// (rad). Must be safe to call from several threads at once. Empty: the
/// geometric network's permeability at its apertures (permeability.h).
using DomainSolver = std::function<DomainSolution(int realization, double size, double angle)>;

/// One solved square.
struct DomainResult {
  int size_index = 0, realization = 0;
  double angle = 0;                             ///< rad
  Eigen::Matrix2d k = Eigen::Matrix2d::Zero();  ///< in the square's frame (permeability.h)
  int n_nodes = 0, n_segments = 0;
  bool connected = false;
  double seconds = 0;
  DomainMechanics mechanics;
};

/// Tensor of one (size, realization) fitted over its rotations.
struct RealizationFit {
  int size_index = 0, realization = 0;
  TensorFit fit;
  double asymmetry = 0;  ///< max |kxy - kyx| / sqrt(kxx kyy) over its domains
  bool connected = false;
};

struct SizeStatistics {
  double size = 0;
  int samples = 0;  ///< realizations with a connected network
  double mean_kxx = 0, mean_kyy = 0, mean_kxy = 0;
  double mean_kmax = 0, std_kmax = 0, cv_kmax = 0;
  double mean_kmin = 0, std_kmin = 0, cv_kmin = 0;
  double mean_angle = 0;  ///< mean principal direction (rad, axial mean)
  double mean_misfit = 0;
  bool meets_criterion = false;
};

struct RevStudyResult {
  RevStudyConfig config;
  std::string source;
  std::string study_file;  ///< the study file, absolute (rev.json's study_file); may be empty
  std::vector<DomainResult> domains;  ///< every requested rotation
  std::vector<RealizationFit> fits;
  std::vector<SizeStatistics> sizes;
  std::optional<double> rev_size;  ///< smallest size meeting the criterion at it and above
  double wall_seconds = 0, solve_seconds = 0;
  int threads = 1, ranks = 1;
};

/// How the work is shared with other processes (MPI ranks). The default is
/// one process. `gather` collects every rank's rows on rank 0.
struct ParallelContext {
  int rank = 0, size = 1;
  /// Concatenates each rank's `local` rows (equal row length) on rank 0.
  std::function<std::vector<double>(const std::vector<double>& local)> gather;
};

/// Runs the study, each domain by `solver` (empty: the geometric network's
/// permeability). On ranks other than 0 the result holds only timings.
RevStudyResult run_rev_study(const RevStudyConfig& config, const DomainSource& source,
                             const ParallelContext& parallel = {}, const DomainSolver& solver = {});

/// Statistics and REV size from the fits (rev_statistics.cpp).
void summarize_rev(RevStudyResult& result);

}  // namespace fissure::flow
