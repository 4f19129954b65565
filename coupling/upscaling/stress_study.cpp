#include "coupling/upscaling/stress_study.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "core/base/errors.h"
#include "core/parallel/openmp_threads.h"
#include "core/scene/config_map.h"
#include "core/scene/joint_models.h"
#include "core/scene/scene_section.h"
#include "core/state/rock_mass.h"
#include "flow/rev/tensor_fit.h"
#include "mechanics/dem/dem_settings.h"
#include "rockmass/joints/joint_law.h"
#include "rockmass/joints/joint_model.h"
#include "rockmass/physical_quantities.h"

namespace fissure {

namespace {

constexpr std::string_view kMechanics[] = {"stresses", "pore_pressure", "aperture_law",
                                           "compliance"};
constexpr std::string_view kCompliance[] = {"increment"};
constexpr std::string_view kState[] = {"stress", "sigma_1", "sigma_3", "angle"};
constexpr std::string_view kApertureLaw[] = {"normal_stiffness", "dilation_angle", "dilation_limit",
                                             "residual", "maximum"};
const KeyTable mechanics_table{"mechanics", kMechanics};
const KeyTable state_table{"mechanics.stresses[]", kState};
const KeyTable aperture_table{"mechanics.aperture_law", kApertureLaw};
const KeyTable compliance_table{"mechanics.compliance", kCompliance};

StressState read_state(const ConfigNode& item) {
  ConfigMap map(item, state_table);
  StressState s;
  s.location = item.located_path();
  const bool tensor = map.contains("stress");
  if (tensor) {
    if (map.contains("sigma_1") || map.contains("sigma_3") || map.contains("angle"))
      item.error("found both stress and sigma_1/sigma_3/angle; expected one of the two forms");
    const QuantityKind* kinds[] = {&quantity::stress, &quantity::stress, &quantity::stress};
    if (auto n = map.optional("stress"))
      if (auto v = n->numbers(kinds, "[sxx, syy, sxy]")) s.stress << (*v)[0], (*v)[1], (*v)[2];
    return s;
  }
  // Principal form, compression +: sigma_1 along `angle` from x.
  double s1 = std::nan(""), s3 = std::nan(""), angle = 0;
  map.read_required("sigma_1", s1, quantity::stress);
  map.read_required("sigma_3", s3, quantity::stress);
  map.read("angle", angle, quantity::angle);
  if (s3 > s1)  // false when either is missing or wrong (NaN): reported at its key
    item.error(
        fmt::format("found sigma_3 = {:g} Pa above sigma_1 = {:g} Pa; expected sigma_1 >= "
                    "sigma_3 (compression positive)",
                    s3, s1));
  const double c = std::cos(angle), sn = std::sin(angle);
  // sigma = -(s1 d1 d1^T + s3 d3 d3^T), d1 = (c, s), d3 = (-s, c).
  s.stress << -(s1 * c * c + s3 * sn * sn), -(s1 * sn * sn + s3 * c * c), -(s1 - s3) * c * sn;
  return s;
}

}  // namespace

double PrincipalStress::ratio() const {
  return sigma_3 > 0 ? sigma_1 / sigma_3 : std::numeric_limits<double>::infinity();
}

PrincipalStress effective_principal(const Eigen::Vector3d& stress, double pore_pressure) {
  // Compression +: C = -(sigma + p I).
  const double cxx = -(stress(0) + pore_pressure), cyy = -(stress(1) + pore_pressure);
  const double cxy = -stress(2);
  const double mean = 0.5 * (cxx + cyy), radius = std::hypot(0.5 * (cxx - cyy), cxy);
  PrincipalStress p;
  p.sigma_1 = mean + radius;
  p.sigma_3 = mean - radius;
  p.angle = radius > 0 ? 0.5 * std::atan2(2 * cxy, cxx - cyy) : 0;
  if (p.angle < 0) p.angle += std::numbers::pi;
  return p;
}

void read_stress_study(const ConfigNode& node, StressStudyConfig& config) {
  ConfigMap map(node, mechanics_table);
  config.location = node.located_path();
  if (auto s = map.required("stresses",
                            "a list of stress states {sigma_1, sigma_3, angle} or "
                            "{stress: [sxx, syy, sxy]}"))
    if (auto items = s->list("stress states", true))
      for (const ConfigNode& item : *items) {
        config.states.push_back(read_state(item));
        config.states.back().index = static_cast<int>(config.states.size()) - 1;
      }
  map.read("pore_pressure", config.pore_pressure, quantity::stress, Range::non_negative());
  if (auto n = map.optional("compliance")) {
    ConfigMap m(*n, compliance_table);
    m.read_required("increment", config.compliance_increment, quantity::stress, Range::positive());
  }
  flow::HmApertureLaw& law = config.aperture_law;
  law.limits.residual = 1e-6;  // flow.apertures.residual's default
  if (auto n = map.optional("aperture_law")) {
    ConfigMap m(*n, aperture_table);
    m.read("normal_stiffness", law.normal_stiffness, quantity::joint_normal_stiffness,
           Range::positive());
    m.read("dilation_angle", law.dilation_angle, quantity::angle,
           Range::closed_open(0, 90 * quantity::kDegree));
    m.read("dilation_limit", law.dilation_limit, quantity::length, Range::non_negative());
    m.read("residual", law.limits.residual, quantity::length, Range::positive());
    m.read("maximum", law.limits.maximum, quantity::length, Range::non_negative());
  }
}

std::vector<std::string> stress_study_keys() {
  const KeyTable* tables[] = {&mechanics_table, &state_table, &aperture_table, &compliance_table};
  return documented_keys(tables);
}

std::shared_ptr<const Scene> stress_stage_scene(const flow::RevStudyConfig& study,
                                                const StressStudyConfig& config,
                                                const Scene& rock_mass_scene) {
  const std::string& where = config.location;
  // 1. The block process, which must bring an update to rest.
  FISSURE_CHECK(rock_mass_scene.has_physics("dem"), SceneError,
                where << ": found a rock-mass scene (" << rock_mass_scene.source.string()
                      << ") whose physics has no dem; expected physics [dem] with "
                         "dem.solve_ratio (the stress stage brings each domain to rest in one "
                         "solved update; the DDA has no solve ratio yet)");
  FISSURE_CHECK(section_settings(rock_mass_scene, dem::kDemSettings).solve_ratio, SceneError,
                where << ": found a rock-mass scene (" << rock_mass_scene.source.string()
                      << ") without dem.solve_ratio; expected one (e.g. 1e-5): each domain is "
                         "solved to rest");
  // 2. Quarter turns only: the sides carry normal stress alone, so the
  //    square follows the principal axes; a turned square would need shear.
  for (int r = 0; r < study.rotations; ++r) {
    const double q = r * study.rotation_step / (std::numbers::pi / 2);
    FISSURE_CHECK(std::abs(q - std::round(q)) < 1e-9, SceneError,
                  where << ": found rotations of " << study.rotation_step * 180 / std::numbers::pi
                        << " deg; expected rotations: 1 or a rotation_step of 90 deg under "
                           "stress (each domain is aligned with its state's principal axes)");
  }
  // 3. Compressive states below the largest normal stress of every joint's
  //    model (Bandis's JCS); the rollers' joint is frictionless and ten
  //    times as stiff as the stiffest joint at the largest stress, so that
  //    the sides hardly move.
  double stiffest = config.aperture_law.normal_stiffness;
  for (const StressState& s : config.states) {
    const PrincipalStress p = effective_principal(s.stress, config.pore_pressure);
    FISSURE_CHECK(p.sigma_1 >= 0 && p.sigma_3 >= 0, SceneError,
                  s.location << ": found an effective principal stress in tension (sigma_1 = "
                             << p.sigma_1 << " Pa, sigma_3 = " << p.sigma_3
                             << " Pa after the pore pressure); expected compression");
    for (const JointProperties& j : rock_mass_scene.joints) {
      FISSURE_CHECK(p.sigma_1 < j.largest_normal_stress, SceneError,
                    s.location << ": found sigma_1' = " << p.sigma_1 << " Pa, not below joint '"
                               << j.name << "''s " << j.largest_normal_stress_key << " ("
                               << j.largest_normal_stress << " Pa); expected lower stresses");
      const joints::JointLaw law(joints::joint_model(j));
      stiffest = std::max(stiffest, law.stiffness(p.sigma_1, 1).normal);
    }
  }
  FISSURE_CHECK(stiffest > 0 && std::isfinite(stiffest), SceneError,
                where << ": found no joint stiffness in " << rock_mass_scene.source.string()
                      << "; expected joints with normal_stiffness (or a model that has one)");
  JointProperties platen;
  platen.name = "rev_platen";
  platen.model.set(joints::kJointModel,
                   joints::JointModel(joints::CoulombProperties{10 * stiffest, 10 * stiffest}));
  auto bare = std::make_shared<Scene>(rock_mass_scene);
  bare->joints.push_back(platen);
  bare->blocks.clear();
  bare->initial_fields = {};
  bare->monitors.clear();
  bare->fixed_points.clear();
  bare->point_loads.clear();
  bare->gravity.setZero();
  bare->physics = {"dem"};
  return bare;
}

std::vector<StressStateResult> run_stress_study(const flow::RevStudyConfig& study,
                                                const StressStudyConfig& config,
                                                const SceneRockMassSource& source,
                                                const flow::ParallelContext& parallel) {
  const std::shared_ptr<const Scene> scene = stress_stage_scene(study, config, source.scene());
  StressedDomainSetup setup;
  setup.scene = scene.get();
  setup.platen_joint = static_cast<int>(scene->joints.size()) - 1;
  setup.aperture_law = config.aperture_law;
  setup.viscosity = study.fluid.viscosity;
  setup.pressure_drop = study.pressure_drop;
  setup.compliance_increment = config.compliance_increment;
  std::vector<StressStateResult> results;
  for (const StressState& state : config.states) {
    const PrincipalStress p = effective_principal(state.stress, config.pore_pressure);
    // In the square's frame (x along sigma_1): sxx = -sigma_1', syy = -sigma_3'.
    const Eigen::Vector2d principal(-p.sigma_1, -p.sigma_3);
    auto solver = [&](int realization, double size, double angle) {
      // The domains share the cores: one OpenMP thread each.
      const OpenMpThreadsOfThisThread one(1);
      flow::DomainSolution s = solve_stressed_domain(
          setup, source.square_traces(realization, size, angle + p.angle), size, principal);
      // From the square's frame (turned by p.angle) into the domain's.
      s.permeability.k = flow::rotate_into(s.permeability.k, -p.angle);
      return s;
    };
    results.push_back({state, p, flow::run_rev_study(study, source, parallel, solver)});
  }
  return results;
}

}  // namespace fissure
