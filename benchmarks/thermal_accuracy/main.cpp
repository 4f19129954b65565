// Accuracy of block heat conduction against closed forms, for the figures of
// docs/thermal.md (section 6) and the work-precision table of
// docs/performance.md ("thermal_accuracy"):
//   profiles.csv        verification.md (h): T = 1 at x = 0 of a 4.4 m strip,
//                       h = 0.01 m, dt = 100 s, backward Euler, lumped; the
//                       computed profile along the strip's middle and erfc at
//                       t = 1e4, 1e5, 1e6 s;
//   line_source.csv     verification.md (l), 2D: 1 kW/m in a 60 m square of
//                       the same rock, BDF2, 100 steps to 1 year; T(r) along
//                       the x axis and Q / (4 pi lambda) E1(r^2 / 4 kappa t);
//   work_precision.csv  the smooth mode sin(pi x) exp(-kappa pi^2 t) on a
//                       1 m x 0.1 m strip at t = 4e4 s: largest nodal error
//                       against the exact solution and wall time, for
//                       backward Euler and BDF2 with 5 to 640 steps, at
//                       h = 0.05 and 0.0125 m;
//   lauwerier_work_precision.csv  verification.md (i), Lauwerier's fracture
//                       (the strict test, the wall-temperature limit): the
//                       largest error of the water's temperature at x = 2,
//                       5, 10, 15 m at t = 1e6 s against the wall time, for
//                       h = 1 to 0.125 m with dt = 4e4 h, both schemes;
//   stability.csv       the maximum principle over steps from 1 s to a
//                       century: a cold rock (0) heated to 1 from one side
//                       (two blocks, 1.7 m x 0.5 m, h = 0.05 m), 5 steps
//                       each; the lowest and highest temperature for
//                       lumped and consistent capacity, backward Euler and
//                       BDF2 (docs/thermal.md 3).
// Usage: bench_thermal_accuracy; then plot.py draws the PNGs.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>

#include "core/base/stopwatch.h"
#include "coupling/process_registry.h"
#include "tests/support/convection_runs.h"
#include "tests/support/thermal_runs.h"

using namespace fissure;
using testing::box;
using testing::thermal_scene;
using testing::ThermalRun;

namespace {

const std::string kDir = FISSURE_SOURCE_DIR "/benchmarks/thermal_accuracy/";
constexpr double kLambda = 3, kRhoC = 2760.0 * 900.0, kKappa = kLambda / kRhoC;
const ThermalMaterial kRock{Eigen::Vector3d(kLambda, kLambda, 0), kRhoC};

ThermalCondition fixed(const std::string& boundary, double value) {
  ThermalCondition c;
  c.boundary = boundary;
  c.value = value;
  return c;
}

void profiles() {
  ThermalControls c;
  c.element_size = 0.01;
  c.initial_temperature = 0;
  c.conditions = {fixed("left", 1)};
  ThermalRun run(thermal_scene({box(0, 0, 4.4, 0.02)}, c, kRock));
  std::ofstream out(kDir + "profiles.csv");
  out << "t,x,T,erfc\n";
  for (const double t : {1e4, 1e5, 1e6}) {
    run.run(100, static_cast<int>(std::lround((t - run.state.time) / 100)));
    for (double x = 0; x <= 2.0 + 1e-9; x += 0.01)
      out << t << ',' << x << ',' << run.temperature_at(Vec2(x, 0.01)) << ','
          << std::erfc(x / (2 * std::sqrt(kKappa * t))) << '\n';
  }
}

void line_source() {
  const ThermalControls c = testing::line_source_controls(3, 0.05, 0.2, 0);
  ThermalRun run(thermal_scene({box(-30, -30, 30, 30)}, c, kRock));
  const double year = 365.25 * 86400;
  run.run(year / 100, 100);
  std::ofstream out(kDir + "line_source.csv");
  out << "r,T,E1\n";
  for (double r = 0.05; r <= 20 + 1e-9; r *= 1.1)
    out << r << ',' << run.temperature_at(Vec2(r, 0)) << ','
        << 1000 / (4 * std::numbers::pi * kLambda) * -std::expint(-r * r / (4 * kKappa * year))
        << '\n';
}

void work_precision() {
  std::ofstream out(kDir + "work_precision.csv");
  out << "scheme,h,steps,error,seconds\n";
  const double end = 4e4, k = std::numbers::pi;
  for (const double h : {0.05, 0.0125})
    for (const auto scheme :
         {ThermalControls::Scheme::BackwardEuler, ThermalControls::Scheme::Bdf2})
      for (int steps = 5; steps <= 640; steps *= 2) {
        ThermalControls c;
        c.element_size = h;
        c.scheme = scheme;
        c.conditions = {fixed("left", 0), fixed("right", 0)};
        Stopwatch clock;
        ThermalRun run(thermal_scene({box(0, 0, 1, 0.1)}, c, kRock));
        const auto& nodes = run.process->mesh().nodes;
        std::vector<double> initial(nodes.size());
        for (std::size_t i = 0; i < nodes.size(); ++i) initial[i] = std::sin(k * nodes[i].x());
        run.process->set_temperature(run.state, std::move(initial));
        const auto& s = run.thermal();
        run.run(end / steps, steps);
        const double seconds = clock.seconds();
        double error = 0;
        for (std::size_t i = 0; i < nodes.size(); ++i)
          error = std::max(error, std::abs(s.temperature[i] - std::sin(k * nodes[i].x()) *
                                                                  std::exp(-kKappa * k * k * end)));
        const char* name = scheme == ThermalControls::Scheme::Bdf2 ? "bdf2" : "backward_euler";
        out << name << ',' << h << ',' << steps << ',' << error << ',' << seconds << '\n';
        std::printf("%-15s h = %-7g %4d steps: error %.3e, %.4f s\n", name, h, steps, error,
                    seconds);
      }
}

void lauwerier_work_precision() {
  std::ofstream out(kDir + "lauwerier_work_precision.csv");
  out << "scheme,h,dt,error,seconds\n";
  for (const auto scheme : {ThermalControls::Scheme::BackwardEuler, ThermalControls::Scheme::Bdf2})
    for (const double h : {1.0, 0.5, 0.25, 0.125}) {
      const double dt = 4e4 * h;
      Stopwatch clock;
      Scene scene = read_scene_text(testing::fracture_scene(20, 4, h, 2400, "wall_temperature"),
                                    "lauwerier.yaml");
      ThermalControls& c = thermal_controls(scene);
      c.materials[0].conductivity = Eigen::Vector3d(0, testing::kLauwerierLambda, 0);
      c.scheme = scheme;
      testing::ConvectionRun run(std::move(scene));
      run.run(dt, static_cast<int>(std::lround(1e6 / dt)));
      const double seconds = clock.seconds();
      double error = 0;
      for (const double x : {2.0, 5.0, 10.0, 15.0})
        error = std::max(error, std::abs(run.fluid_at(x) - testing::lauwerier(x, 1e6)));
      const char* name = scheme == ThermalControls::Scheme::Bdf2 ? "bdf2" : "backward_euler";
      out << name << ',' << h << ',' << dt << ',' << error << ',' << seconds << '\n';
      std::printf("Lauwerier %-15s h = %-6g dt = %-6g: error %.3e, %.3f s\n", name, h, dt, error,
                  seconds);
    }
}

void stability() {
  std::ofstream out(kDir + "stability.csv");
  out << "capacity,scheme,dt,lowest,highest\n";
  std::printf("%-10s %-15s %9s %12s %12s\n", "capacity", "scheme", "dt (s)", "lowest",
              "highest - 1");
  for (const bool lumped : {true, false})
    for (const auto scheme :
         {ThermalControls::Scheme::BackwardEuler, ThermalControls::Scheme::Bdf2})
      for (const double dt : {1.0, 1e2, 1e4, 1e6, 1e8, 3e9}) {
        ThermalControls c;
        c.element_size = 0.05;
        c.initial_temperature = 0;
        c.lumped_capacity = lumped;
        c.scheme = scheme;
        c.conditions = {fixed("left", 1)};
        ThermalRun run(thermal_scene({box(0, 0, 1, 0.5), box(1, 0, 1.7, 0.5)}, c, kRock));
        double lowest = 0, highest = 0;
        for (int k = 0; k < 5; ++k) {
          run.run(dt, 1);
          for (const double t : run.thermal().temperature)
            lowest = std::min(lowest, t), highest = std::max(highest, t);
        }
        const char* capacity = lumped ? "lumped" : "consistent";
        const char* name = scheme == ThermalControls::Scheme::Bdf2 ? "bdf2" : "backward_euler";
        out << capacity << ',' << name << ',' << dt << ',' << lowest << ',' << highest << '\n';
        std::printf("%-10s %-15s %9.0e %12.3e %12.3e\n", capacity, name, dt, lowest, highest - 1);
      }
}

}  // namespace

int main() {
  profiles();
  line_source();
  work_precision();
  lauwerier_work_precision();
  stability();
  return 0;
}
