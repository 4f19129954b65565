// The continuum's permeability laws of the stress (continuum/poroelasticity/
// permeability_law.h): the exponential law, and a stress study's table as
// the far field of configs/sellafield_far_field.yaml reads it.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "continuum/poroelasticity/permeability_law.h"
#include "core/base/errors.h"

namespace fissure {
namespace {

using continuum::StressPermeabilityLaw;

TEST(PermeabilityLaw, ExponentialFallsFromItsReferenceAndTurnsWithItsAngle) {
  const auto law = StressPermeabilityLaw::exponential({4e-14, 1e-14}, {2e-7, 1e-7}, 5e6, 0);
  EXPECT_NEAR(law.at(5e6)(0) / 4e-14, 1, 1e-14);
  EXPECT_NEAR(law.at(5e6)(1) / 1e-14, 1, 1e-14);
  // 3 MPa beyond the points (extrapolated): exp(-0.6) and exp(-0.3).
  EXPECT_NEAR(law.at(8e6)(0) / (4e-14 * std::exp(-0.6)), 1, 1e-13);
  EXPECT_NEAR(law.at(8e6)(1) / (1e-14 * std::exp(-0.3)), 1, 1e-13);
  // Below the reference, and at effective tension the tensor of zero stress.
  EXPECT_NEAR(law.at(0)(0) / (4e-14 * std::exp(1.0)), 1, 1e-13);
  EXPECT_EQ(law.at(-3e6), law.at(0));
  // k_max along y: the principal values trade places; at 45 deg a shear term.
  const auto turned = StressPermeabilityLaw::exponential({4e-14, 1e-14}, {0, 0}, 0, M_PI / 2);
  EXPECT_NEAR(turned.at(1e6)(0), 1e-14, 1e-28);
  EXPECT_NEAR(turned.at(1e6)(1), 4e-14, 1e-28);
  const auto diagonal = StressPermeabilityLaw::exponential({4e-14, 1e-14}, {0, 0}, 0, M_PI / 4);
  EXPECT_NEAR(diagonal.at(1e6)(2), 1.5e-14, 1e-28);
}

// configs/sellafield_stress_study/stress.json: five depths at one ratio.
// The table returns each state's tensor, the geometric mean half-way (in
// sigma') between two states, and the end states' tensors beyond them.
TEST(PermeabilityLaw, StudyTableReturnsTheStudyAtItsStates) {
  std::ifstream in(std::string(FISSURE_SOURCE_DIR) +
                   "/configs/sellafield_stress_study/stress.json");
  const nlohmann::json study = nlohmann::json::parse(in);
  const StressPermeabilityLaw law = continuum::stress_study_table(study, {}, "stress.json");
  ASSERT_EQ(law.stresses.size(), study["states"].size());
  const double c = std::cos(law.angle), s = std::sin(law.angle);
  const auto along = [&](const Eigen::Vector3d& k) {  // k_max: along the law's direction
    return k(0) * c * c + k(1) * s * s + 2 * k(2) * c * s;
  };
  for (std::size_t i = 0; i < law.stresses.size(); ++i) {
    const nlohmann::json& state = study["states"][i];
    const double mean = 0.5e6 * (state["effective_principal_MPa"]["sigma_1"].get<double>() +
                                 state["effective_principal_MPa"]["sigma_3"].get<double>());
    EXPECT_NEAR(law.stresses[i] / mean, 1, 1e-12);
    EXPECT_NEAR(along(law.at(mean)) / state["largest_size"]["k_max"].get<double>(), 1, 1e-12);
  }
  const double half = 0.5 * (law.stresses[1] + law.stresses[2]);
  EXPECT_NEAR(along(law.at(half)) /
                  std::sqrt(along(law.at(law.stresses[1])) * along(law.at(law.stresses[2]))),
              1, 1e-12);
  EXPECT_EQ(law.at(0), law.at(law.stresses.front()));
  EXPECT_EQ(law.at(1e9), law.at(law.stresses.back()));
  // k falls with depth.
  for (std::size_t i = 1; i < law.stresses.size(); ++i)
    EXPECT_LT(along(law.at(law.stresses[i])), along(law.at(law.stresses[i - 1])));
}

TEST(PermeabilityLaw, StudyTableNeedsTwoStatesOfDistinctStress) {
  const nlohmann::json one = nlohmann::json::parse(R"({"states": [
    {"state": 0, "effective_principal_MPa": {"sigma_1": 2.6, "sigma_3": 2.0},
     "largest_size": {"k_max": 1e-13, "k_min": 5e-14}},
    {"state": 1, "effective_principal_MPa": {"sigma_1": 2.0, "sigma_3": 2.6},
     "largest_size": {"k_max": 2e-13, "k_min": 5e-14}}]})");
  EXPECT_THROW(continuum::stress_study_table(one, {}, "one.json"), Error);
  EXPECT_THROW(continuum::stress_study_table(one, {0, 1}, "one.json"), Error);
  EXPECT_THROW(continuum::stress_study_table(nlohmann::json::object(), {}, "empty.json"), Error);
}

}  // namespace
}  // namespace fissure
