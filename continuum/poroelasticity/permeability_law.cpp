#include "continuum/poroelasticity/permeability_law.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/base/errors.h"

namespace fissure::continuum {

StressPermeabilityLaw StressPermeabilityLaw::exponential(const Eigen::Vector2d& k_ref,
                                                         const Eigen::Vector2d& beta,
                                                         double sigma_ref, double angle) {
  // Two points 1 MPa apart on the line ln k = ln k_ref - beta (s - s_ref).
  constexpr double kSpan = 1e6;
  StressPermeabilityLaw law;
  law.stresses = {sigma_ref, sigma_ref + kSpan};
  const Eigen::Vector2d ln_ref(std::log(k_ref(0)), std::log(k_ref(1)));
  law.log_k = {ln_ref, ln_ref - beta * kSpan};
  law.extrapolate = true;
  law.angle = angle;
  return law;
}

Eigen::Vector3d StressPermeabilityLaw::at(double sigma) const {
  const double s = std::max(sigma, 0.0);
  // The segment of s (the first or last beyond the points), then ln k on its line.
  const auto upper = std::upper_bound(stresses.begin() + 1, stresses.end() - 1, s);
  const std::size_t b = static_cast<std::size_t>(upper - stresses.begin()), a = b - 1;
  double w = (s - stresses[a]) / (stresses[b] - stresses[a]);
  if (!extrapolate) w = std::clamp(w, 0.0, 1.0);
  const Eigen::Vector2d ln_k = (1 - w) * log_k[a] + w * log_k[b];
  const double k1 = std::exp(ln_k(0)), k2 = std::exp(ln_k(1));
  // R diag(k1, k2) R^T with R the rotation by `angle`.
  const double c = std::cos(angle), n = std::sin(angle);
  return {k1 * c * c + k2 * n * n, k1 * n * n + k2 * c * c, (k1 - k2) * c * n};
}

namespace {

/// A stress state of the study: its mean effective stress (Pa), ratio, and
/// its largest size's principal permeabilities and direction.
struct StudyState {
  int index = 0;
  double mean = 0, ratio = 0, k_max = 0, k_min = 0, angle = 0;
};

std::vector<StudyState> study_states(const nlohmann::json& study, const std::string& what) {
  if (!study.contains("states") || !study["states"].is_array() || study["states"].empty())
    throw Error(
        fmt::format("{} has no stress states; expected the stress.json of a `fissure "
                    "rev` study with a mechanics section",
                    what));
  std::vector<StudyState> out;
  for (const nlohmann::json& s : study["states"]) {
    StudyState x;
    x.index = s.value("state", static_cast<int>(out.size()));
    const nlohmann::json& p = s.at("effective_principal_MPa");
    const double s1 = p.at("sigma_1").get<double>(), s3 = p.at("sigma_3").get<double>();
    x.mean = 0.5 * (s1 + s3) * 1e6;
    x.ratio = s3 > 0 ? s1 / s3 : 0;
    if (s.contains("largest_size")) {
      const nlohmann::json& z = s["largest_size"];
      x.k_max = z.value("k_max", 0.0);
      x.k_min = z.value("k_min", 0.0);
      x.angle = z.value("k_max_angle_deg", 0.0) * M_PI / 180;
    }
    out.push_back(x);
  }
  return out;
}

}  // namespace

StressPermeabilityLaw stress_study_table(const nlohmann::json& study,
                                         const std::vector<int>& states, const std::string& what) {
  std::vector<StudyState> all;
  try {
    all = study_states(study, what);
  } catch (const nlohmann::json::exception& e) {
    throw Error(fmt::format("cannot read the stress states of {}: {}", what, e.what()));
  }
  std::vector<StudyState> chosen;
  if (states.empty()) {
    // The ratio to the 3 digits a scene gives its stresses to.
    for (const StudyState& s : all)
      if (std::abs(s.ratio - all.front().ratio) <= 1e-3 * all.front().ratio) chosen.push_back(s);
  } else {
    for (int i : states) {
      const auto it =
          std::find_if(all.begin(), all.end(), [i](const StudyState& s) { return s.index == i; });
      if (it == all.end())
        throw Error(fmt::format("{} has no stress state {}; expected states 0 to {}", what, i,
                                static_cast<int>(all.size()) - 1));
      chosen.push_back(*it);
    }
  }
  std::erase_if(chosen, [](const StudyState& s) { return !(s.k_max > 0 && s.k_min > 0); });
  if (chosen.size() < 2)
    throw Error(
        fmt::format("{}: {} of the chosen stress states came to rest with a "
                    "permeability tensor; expected at least two for the table",
                    what, chosen.size()));
  std::sort(chosen.begin(), chosen.end(),
            [](const StudyState& a, const StudyState& b) { return a.mean < b.mean; });
  StressPermeabilityLaw law;
  double c2 = 0, s2 = 0;
  for (const StudyState& s : chosen) {
    if (!law.stresses.empty() && !(s.mean > law.stresses.back()))
      throw Error(
          fmt::format("{}: two of the chosen states have the mean effective stress "
                      "{:g} MPa; expected states of distinct mean stress (one series)",
                      what, s.mean * 1e-6));
    law.stresses.push_back(s.mean);
    law.log_k.emplace_back(std::log(s.k_max), std::log(s.k_min));
    // The direction is an axis: its mean is that of the doubled angles.
    c2 += std::cos(2 * s.angle);
    s2 += std::sin(2 * s.angle);
  }
  law.angle = 0.5 * std::atan2(s2, c2);
  return law;
}

}  // namespace fissure::continuum
