// Top-level key `mechanics`: method, plane mode and Shi's DDA controls
// (theory.md 1.7, 7.1), and its consistency with `physics`.
#include <cctype>
#include <limits>

#include "core/scene/read_linear_solver.h"
#include "core/scene/scene_draft.h"
#include "core/scene/scene_keys.h"

namespace fissure {

namespace {

void read_dda(const ConfigNode& node, DdaControls& dda) {
  ConfigMap map(node, scene_keys::dda);
  map.read("time_step", dda.max_time_step, quantity::time, Range::positive());
  map.read("max_displacement_ratio", dda.max_displacement_ratio, quantity::dimensionless,
           Range::open(0, 1));
  if (auto p = map.optional("penalty")) {
    if (p->is_scalar() && p->yaml().Scalar() == "auto") {
      dda.penalty.reset();
    } else if (p->is_scalar() && !p->yaml().Scalar().empty() &&
               std::isalpha(static_cast<unsigned char>(p->yaml().Scalar()[0]))) {
      p->error("found " + p->found() + "; expected 'auto' or " +
               expectation(quantity::stiffness, Range::positive()));
    } else if (auto value = p->quantity(quantity::stiffness, Range::positive())) {
      dda.penalty = *value;
    }
  }
  map.read("penalty_factor", dda.penalty_factor, quantity::dimensionless, Range::positive());
  map.read("shear_penalty_ratio", dda.shear_penalty_ratio, quantity::dimensionless,
           Range::open_closed(0, 10));
  map.read("velocity_carry_over", dda.velocity_carry_over, quantity::dimensionless,
           Range::closed(0, 1));
  map.read("max_open_close_iterations", dda.max_open_close_iterations, 1);
  map.read("exact_rotation", dda.exact_rotation);
  if (auto s = map.optional("solver")) read_linear_solver(*s, scene_keys::solver, dda.solver);
}

}  // namespace

void read_mechanics(ConfigMap& top, SceneDraft& draft) {
  Scene& scene = draft.scene;
  const bool active = scene.has_physics("mechanics");
  std::optional<ConfigNode> node = top.optional("mechanics");
  if (!node) {
    if (active)
      top.report_missing("mechanics",
                         "a mechanics section, because physics lists mechanics (all its keys "
                         "have defaults: `mechanics: {}` will do)");
    return;
  }
  if (!active && draft.physics_read)
    node->error_at_key(
        "found a mechanics section, but physics does not list mechanics; expected 'mechanics' in "
        "physics, or no mechanics section");

  ConfigMap map(*node, scene_keys::mechanics);
  constexpr std::string_view kMethods[] = {"dda"};
  if (auto m = map.optional("method")) m->choice(kMethods);
  constexpr std::string_view kPlanes[] = {"strain", "stress"};
  if (auto p = map.optional("plane"))
    if (auto plane = p->choice(kPlanes))
      scene.mechanics.plane = *plane == "strain" ? PlaneMode::Strain : PlaneMode::Stress;
  if (auto dda = map.optional("dda")) read_dda(*dda, scene.mechanics.dda);
}

}  // namespace fissure
