#include "coupling/process_registry.h"

#include <algorithm>

#include "continuum/poroelasticity/create_continuum_process.h"
#include "core/base/errors.h"
#include "core/scene/parse_scene.h"
#include "core/scene/scene_keys.h"
#include "flow/cubic_law/create_cubic_law_process.h"
#include "mechanics/dda/create_dda_process.h"
#include "mechanics/dem/create_dem_process.h"
#include "rockmass/fracture_graph_results.h"
#include "rockmass/joints/read_joint_model.h"
#include "rockmass/read_rock_mass.h"
#include "thermal/conduction/create_thermal_process.h"

namespace fissure {

namespace {

// The order of the rows is the default order of a coupling step (Lie
// splitting, theory.md 6.1): the mechanics moves the blocks, then the flow
// sees the new apertures, then the heat; the continuum (a domain of its
// own) last.
constexpr ProcessType kProcesses[] = {
    {"mechanics", &dda::kMechanicsSection, &dda::create_dda_process},
    {"dem", &dem::kDemSection, &dem::create_dem_process},
    {"flow", &flow::kFlowSection, &flow::create_cubic_law_process},
    {"thermal", &thermal::kThermalSection, &thermal::create_thermal_process},
    {"continuum", &continuum::kContinuumSection, &continuum::create_continuum_process},
};

/// Sections that generate blocks (read before the points are attached).
constexpr const SectionReader* kBlockSources[] = {&kRockMassSection};

/// The rows above and those registered since.
std::vector<ProcessType>& process_types() {
  static std::vector<ProcessType> types(std::begin(kProcesses), std::end(kProcesses));
  return types;
}

}  // namespace

std::vector<SceneSection> scene_sections() {
  std::vector<SceneSection> sections;
  for (const SectionReader* s : kBlockSources) sections.push_back({"", s});
  for (const ProcessType& p : process_types()) sections.push_back({p.name, p.section});
  return sections;
}

namespace {

// Installed before main: a module asks provides() whether a field it reads
// will be written (scene_section.h), for scenes read or built in code; the
// joint laws read the `model` of each `joints[]` entry (joint_models.h).
const bool kSectionsInstalled = [] {
  install_scene_sections(scene_sections());
  install_joint_model_reader(&joints::kJointModelReader);
  return true;
}();

}  // namespace

void register_process_type(const ProcessType& type) {
  for (const ProcessType& p : process_types())
    FISSURE_CHECK(std::string_view(p.name) != type.name, std::logic_error,
                  "a second process type named '" << type.name << "'");
  process_types().push_back(type);
  install_scene_sections(scene_sections());
}

Scene read_scene(const std::filesystem::path& file) {
  return parse_scene(file, scene_sections());
}

Scene read_scene_text(const std::string& yaml, const std::string& file_name) {
  return parse_scene_text(yaml, file_name, scene_sections());
}

std::vector<std::string> known_scene_keys() {
  std::vector<std::string> keys = documented_keys(shared_key_tables());
  const KeyTable* joint_models[] = {&joints::kJointModelKeys};
  for (const std::string& k : documented_keys(joint_models)) keys.push_back(k);
  for (const SceneSection& s : scene_sections()) {
    keys.emplace_back(s.reader->key);
    for (const std::string& k : documented_keys(s.reader->keys)) keys.push_back(k);
  }
  return keys;
}

std::vector<std::string> known_physics() {
  std::vector<std::string> names;
  for (const ProcessType& p : process_types()) names.emplace_back(p.name);
  return names;
}

std::vector<std::unique_ptr<Process>> create_processes(const Scene& scene) {
  std::vector<std::unique_ptr<Process>> processes;
  for (const ProcessType& p : process_types())
    if (scene.has_physics(p.name)) processes.push_back(p.create(scene));
  FISSURE_CHECK(!processes.empty(), SceneError,
                scene.source.string()
                    << ": the scene activates no process (physics list is empty)");
  const std::vector<std::string>& order = scene.coupling.order;
  if (!order.empty()) {
    auto rank = [&order](const std::unique_ptr<Process>& p) {
      return std::find(order.begin(), order.end(), p->name()) - order.begin();
    };
    std::stable_sort(processes.begin(), processes.end(),
                     [&rank](const auto& a, const auto& b) { return rank(a) < rank(b); });
  }
  return processes;
}

std::unique_ptr<Process> create_process(const Scene& scene, std::string_view name) {
  for (const ProcessType& p : process_types())
    if (p.name == name && scene.has_physics(p.name)) return p.create(scene);
  throw SceneError(scene.source.string() + ": physics does not list '" + std::string(name) + "'");
}

std::vector<std::unique_ptr<ResultsPart>> shared_results_parts() {
  std::vector<std::unique_ptr<ResultsPart>> parts;
  parts.push_back(std::make_unique<FractureGraphResults>());
  return parts;
}

}  // namespace fissure
