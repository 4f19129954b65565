#include "coupling/process_registry.h"

#include "core/base/errors.h"
#include "flow/cubic_law/create_cubic_law_process.h"
#include "mechanics/dda/create_dda_process.h"

namespace fissure {

namespace {

using Factory = std::unique_ptr<Process> (*)(const Scene&);

struct Entry {
  const char* physics;
  Factory create;
};

// Order = order of execution within a coupling step: mechanics, then flow
// (Lie splitting, theory.md 6.1; the flow process sub-cycles on its own step).
constexpr Entry registry[] = {
    {"mechanics", &create_dda_process},
    {"flow", &flow::create_cubic_law_process},
};

}  // namespace

std::vector<std::unique_ptr<Process>> create_processes(const Scene& scene) {
  std::vector<std::unique_ptr<Process>> processes;
  for (const Entry& e : registry)
    if (scene.has_physics(e.physics)) processes.push_back(e.create(scene));
  FISSURE_CHECK(!processes.empty(), SceneError,
                scene.source.string()
                    << ": the scene activates no process (physics list is empty)");
  return processes;
}

std::vector<std::string> known_physics() {
  std::vector<std::string> names;
  for (const Entry& e : registry) names.emplace_back(e.physics);
  return names;
}

}  // namespace fissure
