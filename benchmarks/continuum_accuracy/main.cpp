// Accuracy and cost of the poro-elastic continuum against Terzaghi's and
// Mandel's solutions, for docs/continuum.md (section 6) and the tables of
// docs/performance.md ("continuum_accuracy"):
//   terzaghi_profiles.csv    p(z)/p0 along the column at T_v = 0.05, 0.2, 0.5,
//                            1 (1 x 40 cells, dt = 100 s), and the series;
//   mandel_curves.csv        p/p0 at x = 0 and a/2 over c t / a^2 = 0 to 1.5
//                            (16 x 16 cells, dt = 0.01 s), and the series;
//   mandel_orders.csv        L2 errors of p and u at c t / a^2 = 0.1: in mesh
//                            size (n = 4 to 32 cells across, dt = 1e-3 s) against
//                            the series, and in the step (n = 16, dt = 0.08 to
//                            0.005 s) against a run with dt = 1.25e-3 s;
//   mandel_work_precision.csv  largest nodal pressure error over c t / a^2 =
//                            0.05, 0.1, 0.2 against wall time, mesh and step
//                            refined together (n = 4 to 32, dt = 0.04 x 4 / n),
//                            monolithic and fixed stress;
//   fixed_stress.csv         passes per step of the fixed-stress split against
//                            its factor (Mandel, tau = 2.88, 16 x 16);
//   scaling.csv              wall time per step (after the first) against the
//                            number of unknowns, monolithic and fixed stress;
//   first_step.csv           p/p0 along Terzaghi's column after one step of 1 s
//                            (c_v dt / h^2 = 0.017): Taylor-Hood and equal-order
//                            P1/P1, each with and without the pressure
//                            stabilization, and the series;
//   stability.csv            fixed stress on Terzaghi's column over k = 1e-21
//                            to 1e-10 m^2 and dt = 1 s to 1000 yr: passes per
//                            step, and the pressure's range against [0, p0].
// Usage: bench_continuum_accuracy [--quick]; then plot.py draws the PNGs.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <utility>

#include "continuum/poroelasticity/taylor_hood.h"
#include "core/base/errors.h"
#include "core/base/stopwatch.h"
#include "coupling/process_registry.h"
#include "tests/support/continuum_runs.h"
#include "tests/support/poroelastic_solutions.h"

using namespace fissure;
using Scheme = ContinuumControls::Scheme;
using testing::continuum_scene;
using testing::ContinuumRun;

namespace {

const std::string kDir = FISSURE_SOURCE_DIR "/benchmarks/continuum_accuracy/";
const test::Mandel kMandel;
const test::Terzaghi kTerzaghi;

Scene mandel(int n, Scheme scheme) {
  Scene s = continuum_scene("continuum_mandel.yaml");
  continuum_controls(s).divisions = {n, n};
  continuum_controls(s).scheme = scheme;
  continuum_controls(s).max_elements = 1e7;
  return s;
}

void terzaghi_profiles() {
  std::ofstream out(kDir + "terzaghi_profiles.csv");
  out << "time_factor,depth,p_over_p0,exact\n";
  ContinuumRun run(continuum_scene("continuum_terzaghi.yaml"));
  const double p0 = kTerzaghi.initial_pressure();
  for (double tv : {0.05, 0.2, 0.5, 1.0}) {
    const double t = tv * 100 / kTerzaghi.consolidation_coefficient();
    run.advance_to(t, 100);
    for (int k = 0; k <= 40; ++k) {
      const double z = 10.0 * k / 40;
      out << tv << "," << z << "," << run.at({0.5, 10 - z}).pressure / p0 << ","
          << kTerzaghi.pressure(z, t) / p0 << "\n";
    }
  }
}

void mandel_curves() {
  std::ofstream out(kDir + "mandel_curves.csv");
  out << "ct_a2,centre,centre_exact,half,half_exact\n";
  ContinuumRun run(mandel(16, Scheme::Monolithic));
  const double p0 = kMandel.initial_pressure(), c = kMandel.consolidation_coefficient();
  for (int k = 0; k <= 150; ++k) {
    const double t = 0.01 * k / c;
    run.advance_to(t, 0.01);
    out << 0.01 * k << "," << run.at({0, 0}).pressure / p0 << "," << kMandel.pressure(0, t) / p0
        << "," << run.at({0.5, 0}).pressure / p0 << "," << kMandel.pressure(0.5, t) / p0 << "\n";
  }
}

/// L2 norms over the domain of p - p_exact (relative to p0) and of u -
/// u_exact (relative to the largest |u|), with the 6-point rule.
std::pair<double, double> l2_errors(const ContinuumRun& run, double t) {
  const auto& mesh = run.process().mesh();
  double ep = 0, eu = 0, uu = 0;
  for (int tri = 0; tri < mesh.n_triangles(); ++tri) {
    const auto& n = mesh.triangles[tri];
    const continuum::TriangleGeometry g({mesh.nodes[n[0]], mesh.nodes[n[1]], mesh.nodes[n[2]]},
                                        false);
    for (const continuum::QuadraturePoint& q : continuum::kQuadrature) {
      const Vec2 x = g.point(q.L);
      const continuum::PointValues v = run.process().values_in(tri, q.L);
      const double w = q.w * g.area;
      ep += w * std::pow(v.pressure - kMandel.pressure(x.x(), t), 2);
      const Vec2 u(kMandel.displacement_x(x.x(), t), kMandel.displacement_y(x.y(), t));
      eu += w * (v.displacement - u).squaredNorm();
      uu += w * u.squaredNorm();
    }
  }
  return {std::sqrt(ep) / kMandel.initial_pressure(), std::sqrt(eu / uu)};
}

void mandel_orders(bool quick) {
  std::ofstream out(kDir + "mandel_orders.csv");
  out << "study,n,dt,error_p,error_u\n";
  const double t = 0.1 / kMandel.consolidation_coefficient();
  std::printf("Mandel at ct/a^2 = 0.1, L2 errors\n  space (dt = 1e-3 s):\n");
  for (int n : {4, 8, 16, 32}) {
    if (quick && n > 16) break;
    ContinuumRun run(mandel(n, Scheme::Monolithic));
    run.advance_to(t, 1e-3);
    const auto [ep, eu] = l2_errors(run, t);
    out << "space," << n << ",0.001," << ep << "," << eu << "\n";
    std::printf("    n = %2d  p %.3e  u %.3e\n", n, ep, eu);
  }
  std::printf("  time (n = 16, against dt = 1.25e-3 s):\n");
  ContinuumRun fine(mandel(16, Scheme::Monolithic));
  fine.advance_to(t, 1.25e-3);
  const auto& ref = fine.process().fields();
  for (double dt : {0.08, 0.04, 0.02, 0.01, 0.005}) {
    ContinuumRun run(mandel(16, Scheme::Monolithic));
    run.advance_to(t, dt);
    const auto& f = run.process().fields();
    const double ep = (f.pressure - ref.pressure).norm() / ref.pressure.norm();
    const double eu = (f.displacement - ref.displacement).norm() / ref.displacement.norm();
    out << "time,16," << dt << "," << ep << "," << eu << "\n";
    std::printf("    dt = %.3f  p %.3e  u %.3e\n", dt, ep, eu);
  }
}

void mandel_work_precision(bool quick) {
  std::ofstream out(kDir + "mandel_work_precision.csv");
  out << "scheme,n,dt,error,seconds\n";
  const double c = kMandel.consolidation_coefficient(), p0 = kMandel.initial_pressure();
  std::printf("Mandel work-precision (largest nodal p error / p0 at ct/a^2 = 0.05, 0.1, 0.2)\n");
  for (Scheme scheme : {Scheme::Monolithic, Scheme::FixedStress}) {
    for (int n : {4, 8, 16, 32}) {
      if (quick && n > 16) break;
      const double dt = 0.04 * 4 / n;
      Stopwatch clock;
      ContinuumRun run(mandel(n, scheme));
      double error = 0;
      for (double ct : {0.05, 0.1, 0.2}) {
        run.advance_to(ct / c, dt);
        const auto& mesh = run.process().mesh();
        const auto& p = run.process().fields().pressure;
        for (int v = 0; v < mesh.n_vertices; ++v)
          error =
              std::max(error, std::abs(p(v) - kMandel.pressure(mesh.nodes[v].x(), ct / c)) / p0);
      }
      const double seconds = clock.seconds();
      const char* name = scheme == Scheme::Monolithic ? "monolithic" : "fixed_stress";
      out << name << "," << n << "," << dt << "," << error << "," << seconds << "\n";
      std::printf("  %-12s n = %2d dt = %.4f  error %.3e  %.3f s\n", name, n, dt, error, seconds);
    }
  }
}

// Booker and Savvidou's point source (verification.md (l)) at one year:
// the largest relative error of Delta T and of p at r = 1, 2, 4 m (along the
// axis and the plane of symmetry) against the wall time, over the mesh
// near the source (steps of 0.005 yr), the mesh's grading away from it (5 cm
// at the source) and the step. At r = 1 to 8 m the graded elements (0.2 to
// 1.3 m at grading 0.15) set the error: P1's h^2 T'' / 8 of the 1 / r
// profile is about 1 %.
void booker_savvidou_work_precision(bool quick) {
  std::ofstream out(kDir + "booker_savvidou_work_precision.csv");
  out << "study,fine_m,grading,dt_years,unknowns,error_T,error_p,seconds\n";
  const test::BookerSavvidou exact;
  const double year = 365.25 * 86400;
  std::printf("Booker-Savvidou work-precision (largest relative error at r = 1, 2, 4 m, 1 yr)\n");
  auto one = [&](const char* study, double fine, double grading, double step) {
    Stopwatch clock;
    ContinuumRun run(read_scene_text(exact.scene(fine, 6, step, grading), "booker_savvidou.yaml"));
    run.advance_to(year, step * year);
    double et = 0, ep = 0;
    for (double r : {1.0, 2.0, 4.0})
      for (const Vec2& at : {Vec2(0, r), Vec2(r, 0)}) {
        const continuum::PointValues v = run.at(at);
        et = std::max(et, std::abs(v.temperature / exact.temperature(r, year) - 1));
        ep = std::max(ep, std::abs(v.pressure / exact.pressure(r, year) - 1));
      }
    const double seconds = clock.seconds();
    const long unknowns = run.process().statistics()["mesh"]["unknowns"].get<long>();
    out << study << "," << fine << "," << grading << "," << step << "," << unknowns << "," << et
        << "," << ep << "," << seconds << "\n";
    std::printf(
        "  %-7s h_f = %.3f m grading %.4f dt = %.4f yr  %7ld unknowns  T %.3e  p %.3e  %.2f s\n",
        study, fine, grading, step, unknowns, et, ep, seconds);
  };
  for (double fine : {0.4, 0.2, 0.1, 0.05}) one("source", fine, 0.15, 0.005);
  if (quick) return;
  for (double grading : {0.1, 0.075, 0.05}) one("grading", 0.05, grading, 0.005);
  for (double step : {0.08, 0.04, 0.02, 0.01}) one("step", 0.05, 0.15, step);
}

void fixed_stress_factor() {
  std::ofstream out(kDir + "fixed_stress.csv");
  out << "factor,passes_per_step\n";
  std::printf("Fixed-stress passes per step (Mandel, tau = 2.88, 16 x 16, 20 steps of 0.01 s)\n");
  for (double f : {0.25, 0.4, 0.5, 0.6, 0.75, 1.0, 1.5, 2.0}) {
    Scene s = mandel(16, Scheme::FixedStress);
    continuum_controls(s).fixed_stress_factor = f;
    continuum_controls(s).max_iterations = 1000;
    ContinuumRun run(s);
    try {
      run.advance_to(0.2, 0.01);
    } catch (const DivergenceError& e) {  // below alpha^2 / 2 K_dr: no contraction
      out << f << ",nan\n";
      std::printf("  factor %.2f  diverges: %s\n", f, e.what());
      continue;
    }
    const double passes = run.process().statistics()["splitting_passes"].get<double>() / 20;
    out << f << "," << passes << "\n";
    std::printf("  factor %.2f  %.1f passes per step\n", f, passes);
  }
}

void scaling(bool quick) {
  std::ofstream out(kDir + "scaling.csv");
  out << "scheme,n,unknowns,seconds_per_step,passes_per_step\n";
  std::printf(
      "Wall time per step (Mandel, dt = 0.01 s, the factorization of the first step "
      "excluded)\n");
  for (Scheme scheme : {Scheme::Monolithic, Scheme::FixedStress}) {
    for (int n : {32, 100, 200}) {
      if (quick && n > 32) break;
      ContinuumRun run(mandel(n, scheme));
      run.advance_to(0.01, 0.01);
      const long passes0 = run.process().statistics()["splitting_passes"].get<long>();
      Stopwatch clock;
      run.advance_to(0.06, 0.01);
      const double per_step = clock.seconds() / 5;
      const nlohmann::json st = run.process().statistics();
      const double passes = (st["splitting_passes"].get<long>() - passes0) / 5.0;
      const long unknowns = st["mesh"]["unknowns"].get<long>();
      const char* name = scheme == Scheme::Monolithic ? "monolithic" : "fixed_stress";
      out << name << "," << n << "," << unknowns << "," << per_step << "," << passes << "\n";
      std::printf("  %-12s %7ld unknowns  %.4f s per step  %.1f passes\n", name, unknowns, per_step,
                  passes);
    }
  }
}

void first_step() {
  std::ofstream out(kDir + "first_step.csv");
  out << "elements,stabilization,depth,p_over_p0,exact\n";
  const double p0 = kTerzaghi.initial_pressure();
  for (bool p1 : {false, true})
    for (double stabilization : {0.0, 1.0}) {
      Scene s = continuum_scene("continuum_terzaghi.yaml");
      continuum_controls(s).linear_displacement = p1;
      continuum_controls(s).pressure_stabilization = stabilization;
      continuum_controls(s).scheme = Scheme::Monolithic;
      ContinuumRun run(s);
      run.advance_to(1, 1);
      double lo = 1e300, hi = -1e300;
      for (int k = 0; k <= 160; ++k) {
        const double z = 10.0 * k / 160;
        for (double x : {0.0, 0.5, 1.0}) {
          const double p = run.at({x, 10 - z}).pressure / p0;
          lo = std::min(lo, p);
          hi = std::max(hi, p);
          if (x == 0.5)
            out << (p1 ? "p1p1" : "taylor_hood") << "," << stabilization << "," << z << "," << p
                << "," << kTerzaghi.pressure(z, 1) / p0 << "\n";
        }
      }
      std::printf("First step of 1 s, %s, stabilization %g: p/p0 in [%.4f, %.4f]\n",
                  p1 ? "P1/P1" : "Taylor-Hood", stabilization, lo, hi);
    }
}

void stability() {
  std::ofstream out(kDir + "stability.csv");
  out << "stabilization,permeability,dt,passes_per_step,p_min,p_max\n";
  std::printf("Fixed stress on Terzaghi's column: passes per step and p / p0 range\n");
  const double year = 365.25 * 86400, p0 = kTerzaghi.initial_pressure();
  for (double stabilization : {0.0, 1.0})
    for (double k : {1e-21, 1e-19, 1e-17, 1e-15, 1e-13, 1e-11, 1e-10})
      for (double dt : {1.0, 60.0, 3600.0, 86400.0, year, 100 * year, 1000 * year}) {
        Scene s = continuum_scene("continuum_terzaghi.yaml");
        continuum_controls(s).materials[0].permeability = Eigen::Vector3d(k, k, 0);
        continuum_controls(s).pressure_stabilization = stabilization;
        ContinuumRun run(s);
        run.advance_to(5 * dt, dt);
        const auto& p = run.process().fields().pressure;
        const double passes = run.process().statistics()["splitting_passes"].get<double>() / 5;
        out << stabilization << "," << k << "," << dt << "," << passes << "," << p.minCoeff() / p0
            << "," << p.maxCoeff() / p0 << "\n";
        std::printf("  stabilization %g k %.0e dt %.1e s: %.1f passes, p/p0 in [%.4f, %.4f]\n",
                    stabilization, k, dt, passes, p.minCoeff() / p0, p.maxCoeff() / p0);
      }
}

}  // namespace

int main(int argc, char** argv) {
  // bench_continuum_accuracy [--quick] [STUDY]: every study, or the one named
  // (terzaghi, mandel_curves, mandel_orders, mandel_work_precision,
  // booker_savvidou, fixed_stress, first_step, stability, scaling).
  bool quick = false;
  std::string only;
  for (int a = 1; a < argc; ++a) {
    if (std::strcmp(argv[a], "--quick") == 0)
      quick = true;
    else
      only = argv[a];
  }
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  const std::pair<const char*, std::function<void()>> studies[] = {
      {"terzaghi", terzaghi_profiles},
      {"mandel_curves", mandel_curves},
      {"mandel_orders", [quick] { mandel_orders(quick); }},
      {"mandel_work_precision", [quick] { mandel_work_precision(quick); }},
      {"booker_savvidou", [quick] { booker_savvidou_work_precision(quick); }},
      {"fixed_stress", fixed_stress_factor},
      {"first_step", first_step},
      {"stability", stability},
      {"scaling", [quick] { scaling(quick); }}};
  for (const auto& [name, run] : studies)
    if (only.empty() || only == name) run();
  return 0;
}
