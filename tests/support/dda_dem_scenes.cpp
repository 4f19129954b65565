#include "tests/support/dda_dem_scenes.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "coupling/process_registry.h"

namespace fissure::testing {

Scene edited_config(const std::string& stem, const std::vector<TextEdit>& edits) {
  const std::string file = std::string(FISSURE_SOURCE_DIR) + "/configs/" + stem + ".yaml";
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file);
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  for (const auto& [from, to] : edits) {
    const std::size_t at = text.find(from);
    if (at == std::string::npos || text.find(from, at + 1) != std::string::npos)
      throw std::runtime_error(fmt::format("{}: '{}' is not there exactly once", file, from));
    text.replace(at, from.size(), to);
  }
  Scene scene = read_scene_text(text, file);
  scene.output.hdf5 = false;
  return scene;
}

Scene stiff_wall_dda(double time_step, double velocity_carry_over, double end_time) {
  using namespace wall;
  return edited_config(
      "brick_wall",
      {{"young_modulus: 10 GPa", fmt::format("young_modulus: {} Pa", kStiffYoungModulus)},
       {"penalty: auto", fmt::format("penalty: {} N/m", kPenalty)},
       {"time_step: 1 ms", fmt::format("time_step: {} s", time_step)},
       {"velocity_carry_over: 1.0", fmt::format("velocity_carry_over: {}", velocity_carry_over)},
       {"end: 1.0", fmt::format("end: {}", end_time)},
       {"interval: 0.02", fmt::format("interval: {}", end_time)}});
}

Scene rigid_wall_dem(const std::string& dem_controls, double end_time) {
  using namespace wall;
  return edited_config(
      "dem_brick_wall",
      {{"normal_stiffness: 10 GPa/m, shear_stiffness: 5 GPa/m}",
        fmt::format("normal_stiffness: {0} Pa/m, shear_stiffness: {0} Pa/m}}\n"
                    "  - {{name: base, friction_angle: 30, normal_stiffness: {1} Pa/m, "
                    "shear_stiffness: {1} Pa/m}}",
                    kJointNormalStiffness, kBaseNormalStiffness)},
       {"[-1, 0]], fixed: true}", "[-1, 0]], fixed: true, joint: base}"},
       {"damping: {local: 0.8}\n", "damping: {local: 0.8}\n" + dem_controls},
       {"end: 1.0", fmt::format("end: {}", end_time)},
       {"interval: 0.02", fmt::format("interval: {}", end_time)}});
}

double wall_joints_settlement() {
  using namespace wall;
  double sum = 0;  // sum over the nine bed joints above the base of H - y_k
  for (int k = 1; k < 10; ++k) sum += kHeight - k * kCourseHeight;
  return kDensity * kG * (sum / kJointNormalStiffness + kHeight / kBaseNormalStiffness);
}

double wall_blocks_shortening(double young_modulus) {
  using namespace wall;
  const double h = kCourseHeight;
  // The nine courses below the top one, each its whole height under its
  // mean overburden H - y_c, and the top brick from its base to its
  // centroid (h / 2) under its own mean overburden h / 2.
  double sum = 0;
  for (int k = 0; k < 9; ++k) sum += (kHeight - (k + 0.5) * h) * h;
  sum += 0.5 * h * 0.5 * h;
  return (1 - kPoissonRatio * kPoissonRatio) * kDensity * kG * sum / young_modulus;
}

}  // namespace fissure::testing
