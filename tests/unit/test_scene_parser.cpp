// Scene parsing (core/scene): a complete valid scene becomes exactly the
// expected Scene (units converted to SI, defaults, references resolved to
// indices, loops oriented, points attached to blocks); defaults of a minimal
// scene; the documentation lists every key the parser knows, its contents
// list and top-level table name every section, its links resolve, and its
// example parses.
#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/base/errors.h"
#include "core/scene/closest_match.h"
#include "core/scene/config_map.h"
#include "core/scene/diagnostics.h"
#include "core/scene/scene_keys.h"
#include "coupling/process_registry.h"
#include "mechanics/dda/dda_settings.h"

namespace fissure {
namespace {

constexpr double kPi = 3.14159265358979323846;

const char* const kCompleteScene = R"(name: wall_test
physics: [mechanics]
gravity: [0.5, -9.81 m/s^2]
materials:
  - name: granite
    density: 2.65 t/m^3
    young_modulus: 50 GPa
    poisson_ratio: 0.25
  - name: soft
    density: 2000
    young_modulus: 500 MPa
    poisson_ratio: -0.1
joints:
  - name: bedding
    friction_angle: 30
    cohesion: 0.1 MPa
    tensile_strength: 2 kPa
  - name: rough
    friction_angle: 0.7 rad
default_joint: rough
blocks:
  - name: base
    material: granite
    vertices: [[0, 0], [0, 1], [10, 1], [10, 0]]       # clockwise
    holes: [[[4, 0.4], [6, 0.4], [6, 0.6], [4, 0.6]]]  # counter-clockwise
    fixed: true
    initial_stress: [-1 MPa, -2 MPa, 0.5 MPa]
  - material: soft
    joint: bedding
    vertices: [[4, 1], [6, 1], [6, 2], [4, 2]]
    initial_velocity: [0.1, -20 mm/s, 90 deg/s]
fixed_points:
  - point: [0, 0]
  - point: [5, 1]
    block: block1
    directions: [y]
point_loads:
  - point: [5, 2]
    force: [1 kN, -1 MN]
    history: [[0, 0], [100 ms, 1], [1, 1]]
monitors:
  - name: top
    point: [5, 1.5]
  - name: air
    point: [20, 20]
    block: none
  - name: interface
    point: [4.5, 1]
    block: base
mechanics:
  method: dda
  plane: stress
  dda:
    time_step: 2 ms
    max_displacement_ratio: 0.01
    penalty: 1e4 MN/m
    penalty_factor: 20
    shear_penalty_ratio: 0.5
    velocity_carry_over: 0
    damping_ratio: 0.05
    max_open_close_iterations: 8
    exact_rotation: false
    solver:
      type: pcg
      relative_tolerance: 1e-8
      max_iterations: 500
time:
  end: 2 s
  max_steps: 1e5
  min_step: 1 us
output:
  interval: 10 ms
  every_steps: 5
  hdf5: false
)";

const char* const kMinimalScene = R"(physics: [mechanics]
materials:
  - name: rock
    density: 2700
    young_modulus: 10e9
    poisson_ratio: 0.2
joints:
  - name: j
    friction_angle: 35
blocks:
  - vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]
mechanics:
time:
  end: 0.5
)";

std::vector<Vec2> points(std::initializer_list<std::pair<double, double>> xy) {
  std::vector<Vec2> v;
  for (const auto& [x, y] : xy) v.emplace_back(x, y);
  return v;
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A flood of problems is counted, not kept: only the first 16 of a kind and
// 4,096 in all are kept whole (2 million of one problem in a 47 MB history
// took 2.5 GB kept), and the summary counts every one.
TEST(scene_parser, AMillionProblemsAreCountedNotKept) {
  Diagnostics d("flood.yaml");
  for (int i = 1; i <= 1000000; ++i)
    d.error({"flood.yaml", i, 3}, "history[" + std::to_string(i) + "]",
            "found a time that does not increase; expected strictly increasing times");
  for (int i = 1; i <= 10000; ++i)
    d.error({"flood.yaml", 2000000 + i, 1}, "key" + std::to_string(i), "found x; expected y");
  EXPECT_EQ(d.size(), 1010000u);
  const std::string text = d.text();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 101) << "3 + 1 + 97 + 1 lines";
  EXPECT_NE(text.find("flood.yaml:3:3: history[3]: found a time"), std::string::npos);
  EXPECT_NE(text.find("  ... and 999997 more problems like the one above, up to line 1000000"),
            std::string::npos);
  // 4,080 of the other kinds were kept, 97 of them shown; 5,920 were counted.
  EXPECT_NE(text.find("  ... and 9903 more problems (the first 100 are shown)"), std::string::npos)
      << text.substr(text.size() - 200);
}

TEST(scene_parser, CompleteSceneGeneralAndMaterials) {
  const Scene s = read_scene_text(kCompleteScene, "complete.yaml");
  EXPECT_EQ(s.name, "wall_test");
  EXPECT_EQ(s.source, std::filesystem::path("complete.yaml"));
  EXPECT_EQ(s.physics, std::vector<std::string>{"mechanics"});
  EXPECT_EQ(s.gravity, Vec2(0.5, -9.81));

  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].name, "granite");
  EXPECT_DOUBLE_EQ(s.materials[0].density, 2650);
  EXPECT_DOUBLE_EQ(s.materials[0].young_modulus, 50e9);
  EXPECT_DOUBLE_EQ(s.materials[0].poisson_ratio, 0.25);
  EXPECT_EQ(s.materials[1].name, "soft");
  EXPECT_DOUBLE_EQ(s.materials[1].density, 2000);
  EXPECT_DOUBLE_EQ(s.materials[1].young_modulus, 500e6);
  EXPECT_DOUBLE_EQ(s.materials[1].poisson_ratio, -0.1);

  ASSERT_EQ(s.joints.size(), 2u);
  EXPECT_EQ(s.joints[0].name, "bedding");
  EXPECT_DOUBLE_EQ(s.joints[0].friction_angle, kPi / 6);  // plain number: degrees
  EXPECT_DOUBLE_EQ(s.joints[0].cohesion, 0.1e6);
  EXPECT_DOUBLE_EQ(s.joints[0].tensile_strength, 2e3);
  EXPECT_EQ(s.joints[1].name, "rough");
  EXPECT_DOUBLE_EQ(s.joints[1].friction_angle, 0.7);
  EXPECT_DOUBLE_EQ(s.joints[1].cohesion, 0);
  EXPECT_DOUBLE_EQ(s.joints[1].tensile_strength, 0);
  EXPECT_EQ(s.default_joint, 1);
}

TEST(scene_parser, CompleteSceneBlocks) {
  const Scene s = read_scene_text(kCompleteScene, "complete.yaml");
  ASSERT_EQ(s.blocks.size(), 2u);

  const BlockSpec& base = s.blocks[0];
  EXPECT_EQ(base.name, "base");
  EXPECT_EQ(base.material, 0);
  EXPECT_EQ(base.joint, -1);  // the default joint
  EXPECT_TRUE(base.fixed);
  EXPECT_EQ(base.initial_stress, Eigen::Vector3d(-1e6, -2e6, 0.5e6));
  EXPECT_EQ(base.initial_velocity, Eigen::Vector3d::Zero());
  EXPECT_EQ(base.location.file, "complete.yaml");
  EXPECT_EQ(base.location.line, 22);
  EXPECT_EQ(base.location.column, 5);
  // Outer loop made counter-clockwise and the hole clockwise, first vertex kept.
  EXPECT_EQ(base.polygon.loop_offsets, (std::vector<int>{0, 4, 8}));
  EXPECT_EQ(base.polygon.vertices, points({{0, 0},
                                           {10, 0},
                                           {10, 1},
                                           {0, 1},  // outer
                                           {4, 0.4},
                                           {4, 0.6},
                                           {6, 0.6},
                                           {6, 0.4}}));
  EXPECT_GT(signed_area(base.polygon.loop(0)), 0);
  EXPECT_LT(signed_area(base.polygon.loop(1)), 0);

  const BlockSpec& top = s.blocks[1];
  EXPECT_EQ(top.name, "block1");  // default name: block<index>
  EXPECT_EQ(top.material, 1);
  EXPECT_EQ(top.joint, 0);
  EXPECT_FALSE(top.fixed);
  EXPECT_EQ(top.initial_stress, Eigen::Vector3d::Zero());
  EXPECT_DOUBLE_EQ(top.initial_velocity(0), 0.1);
  EXPECT_DOUBLE_EQ(top.initial_velocity(1), -0.02);
  EXPECT_DOUBLE_EQ(top.initial_velocity(2), kPi / 2);
  EXPECT_EQ(top.polygon.loop_offsets, (std::vector<int>{0, 4}));
  EXPECT_EQ(top.polygon.vertices, points({{4, 1}, {6, 1}, {6, 2}, {4, 2}}));
}

TEST(scene_parser, CompleteScenePointsAreAttachedToBlocks) {
  const Scene s = read_scene_text(kCompleteScene, "complete.yaml");
  ASSERT_EQ(s.fixed_points.size(), 2u);
  EXPECT_EQ(s.fixed_points[0].point, Vec2(0, 0));
  EXPECT_EQ(s.fixed_points[0].block, 0);  // a corner of base: on its boundary
  EXPECT_TRUE(s.fixed_points[0].fix_x);
  EXPECT_TRUE(s.fixed_points[0].fix_y);
  EXPECT_EQ(s.fixed_points[1].point, Vec2(5, 1));
  EXPECT_EQ(s.fixed_points[1].block, 1);  // on both blocks, named
  EXPECT_FALSE(s.fixed_points[1].fix_x);
  EXPECT_TRUE(s.fixed_points[1].fix_y);

  ASSERT_EQ(s.point_loads.size(), 1u);
  EXPECT_EQ(s.point_loads[0].point, Vec2(5, 2));
  EXPECT_EQ(s.point_loads[0].block, 1);  // top edge of block1
  EXPECT_EQ(s.point_loads[0].force, Vec2(1e3, -1e6));
  const std::vector<std::pair<double, double>> history = {{0, 0}, {0.1, 1}, {1, 1}};
  EXPECT_EQ(s.point_loads[0].history, history);

  ASSERT_EQ(s.monitors.size(), 3u);
  EXPECT_EQ(s.monitors[0].name, "top");
  EXPECT_EQ(s.monitors[0].point, Vec2(5, 1.5));
  EXPECT_EQ(s.monitors[0].block, 1);  // inside block1
  EXPECT_EQ(s.monitors[1].name, "air");
  EXPECT_EQ(s.monitors[1].block, -1);  // block: none
  EXPECT_EQ(s.monitors[2].name, "interface");
  EXPECT_EQ(s.monitors[2].block, 0);
}

TEST(scene_parser, CompleteSceneControls) {
  const Scene s = read_scene_text(kCompleteScene, "complete.yaml");
  EXPECT_EQ(mechanics_controls(s).plane, PlaneMode::Stress);
  const DdaControls& dda = mechanics_controls(s).dda;
  EXPECT_DOUBLE_EQ(dda.max_time_step, 2e-3);
  EXPECT_DOUBLE_EQ(dda.max_displacement_ratio, 0.01);
  ASSERT_TRUE(dda.penalty.has_value());
  EXPECT_DOUBLE_EQ(*dda.penalty, 1e10);
  EXPECT_DOUBLE_EQ(dda.penalty_factor, 20);
  EXPECT_DOUBLE_EQ(dda.shear_penalty_ratio, 0.5);
  EXPECT_DOUBLE_EQ(dda.velocity_carry_over, 0);
  EXPECT_DOUBLE_EQ(dda.damping_ratio, 0.05);
  EXPECT_EQ(dda.max_open_close_iterations, 8);
  EXPECT_FALSE(dda.exact_rotation);
  EXPECT_EQ(dda.solver.type, LinearSolverControls::Type::Pcg);
  EXPECT_DOUBLE_EQ(dda.solver.relative_tolerance, 1e-8);
  EXPECT_EQ(dda.solver.max_iterations, 500);
  EXPECT_EQ(dda.solver.petsc_options, "");

  EXPECT_DOUBLE_EQ(s.time.end_time, 2);
  EXPECT_EQ(s.time.max_steps, 100000);
  EXPECT_DOUBLE_EQ(s.time.min_step, 1e-6);
  EXPECT_DOUBLE_EQ(s.output.interval, 0.01);
  EXPECT_EQ(s.output.every_steps, 5);
  EXPECT_FALSE(s.output.hdf5);
}

TEST(scene_parser, MinimalSceneTakesTheDefaults) {
  const Scene s = read_scene_text(kMinimalScene, "configs/minimal_case.yaml");
  const Scene defaults;
  EXPECT_EQ(s.name, "minimal_case");  // the file stem
  EXPECT_EQ(s.gravity, Vec2(0, -9.81));
  EXPECT_EQ(s.default_joint, 0);
  ASSERT_EQ(s.blocks.size(), 1u);
  EXPECT_EQ(s.blocks[0].name, "block0");
  EXPECT_EQ(s.blocks[0].material, 0);  // the only material
  EXPECT_EQ(s.blocks[0].joint, -1);
  EXPECT_FALSE(s.blocks[0].fixed);
  EXPECT_DOUBLE_EQ(s.joints[0].friction_angle, 35 * kPi / 180);
  EXPECT_TRUE(s.fixed_points.empty());
  EXPECT_TRUE(s.point_loads.empty());
  EXPECT_TRUE(s.monitors.empty());

  EXPECT_EQ(mechanics_controls(s).plane, PlaneMode::Strain);
  const DdaControls& dda = mechanics_controls(s).dda;
  const DdaControls& d0 = mechanics_controls(defaults).dda;
  EXPECT_EQ(dda.max_time_step, d0.max_time_step);
  EXPECT_EQ(dda.max_time_step, 1e-3);
  EXPECT_EQ(dda.max_displacement_ratio, 0.005);
  EXPECT_FALSE(dda.penalty.has_value());  // auto
  EXPECT_EQ(dda.penalty_factor, 50);
  EXPECT_EQ(dda.shear_penalty_ratio, 1.0);
  EXPECT_EQ(dda.velocity_carry_over, 1.0);
  EXPECT_EQ(dda.damping_ratio, 0.1);
  EXPECT_EQ(dda.max_open_close_iterations, 12);
  EXPECT_TRUE(dda.exact_rotation);
  EXPECT_EQ(dda.solver.type, LinearSolverControls::Type::Auto);
  EXPECT_EQ(dda.solver.relative_tolerance, 1e-10);
  EXPECT_EQ(dda.solver.max_iterations, 2000);

  EXPECT_EQ(s.time.end_time, 0.5);
  EXPECT_EQ(s.time.max_steps, -1);
  EXPECT_EQ(s.time.min_step, 1e-9);
  EXPECT_EQ(s.output.interval, 0);
  EXPECT_EQ(s.output.every_steps, 0);
  EXPECT_TRUE(s.output.hdf5);
}

TEST(scene_parser, PenaltyAutoAndPetscOptions) {
  std::string text = kMinimalScene;
  text.replace(text.find("mechanics:\n"), 11,
               "mechanics:\n  dda:\n    penalty: auto\n    solver:\n      type: auto\n"
               "      petsc_options: \"-ksp_type cg -pc_type gamg\"\n");
  const Scene s = read_scene_text(text, "penalty.yaml");
  EXPECT_FALSE(mechanics_controls(s).dda.penalty.has_value());
  EXPECT_EQ(mechanics_controls(s).dda.solver.petsc_options, "-ksp_type cg -pc_type gamg");
}

TEST(scene_parser, ParseSceneReadsAFile) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("fissure_scene_parser_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / "from_file.yaml";
  std::ofstream(file) << kMinimalScene;
  const Scene s = read_scene(file);
  EXPECT_EQ(s.name, "from_file");
  EXPECT_EQ(s.source, file);
  std::filesystem::remove_all(dir);
  EXPECT_THROW(read_scene(dir / "missing.yaml"), SceneError);
}

TEST(scene_parser, DocumentationListsEveryKnownKey) {
  const std::string doc =
      read_text(std::filesystem::path(FISSURE_SOURCE_DIR) / "docs" / "scene-reference.md");
  ASSERT_FALSE(doc.empty()) << "docs/scene-reference.md not found";
  const std::vector<std::string> keys = known_scene_keys();
  EXPECT_GT(keys.size(), 50u);
  for (const char* k : {"name", "materials[].density", "mechanics.dda.time_step",
                        "mechanics.dda.solver.petsc_options", "monitors[].block"})
    EXPECT_NE(std::find(keys.begin(), keys.end(), k), keys.end()) << k;
  for (const std::string& key : keys)
    EXPECT_NE(doc.find("`" + key + "`"), std::string::npos)
        << "docs/scene-reference.md does not document `" << key << "`";

  // And the other way: every key in the first column of a table is known.
  const std::set<std::string> known(keys.begin(), keys.end());
  std::istringstream lines(doc);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("| `", 0) != 0) continue;
    const std::string key = line.substr(3, line.find('`', 3) - 3);
    EXPECT_TRUE(known.count(key)) << "docs/scene-reference.md documents unknown key `" << key
                                  << "`";
  }
}

/// GitHub's anchor of a Markdown heading: lower case, spaces to '-', other
/// punctuation ('.', ',', ':', '`') dropped.
std::string heading_anchor(const std::string& heading) {
  std::string anchor;
  for (const char c : heading) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '_' || c == '-')
      anchor += static_cast<char>(std::tolower(u));
    else if (c == ' ')
      anchor += '-';
  }
  return anchor;
}

// Issue 34: the contents list named eleven of thirteen sections, one link had
// a stale anchor, and the top-level table lacked `thermal` and `continuum`.
TEST(scene_parser, DocumentationNamesEverySectionAndItsLinksResolve) {
  const std::string doc =
      read_text(std::filesystem::path(FISSURE_SOURCE_DIR) / "docs" / "scene-reference.md");
  ASSERT_FALSE(doc.empty()) << "docs/scene-reference.md not found";
  std::set<std::string> anchors;
  std::vector<std::string> sections;  // the "## " headings
  std::istringstream lines(doc);
  bool in_code = false;  // '#' starts comments in the YAML and shell examples
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("```", 0) == 0) in_code = !in_code;
    if (in_code) continue;
    if (line.rfind("## ", 0) == 0) sections.push_back(line.substr(3));
    if (line.rfind("#", 0) == 0) anchors.insert(heading_anchor(line.substr(line.find(' ') + 1)));
  }
  ASSERT_GE(sections.size(), 13u);
  const size_t contents_end = doc.find("\n## ");
  const std::string contents = doc.substr(0, contents_end);
  for (const std::string& section : sections)
    EXPECT_NE(contents.find("[" + section.substr(section.find(' ') + 1) + "](#" +
                            heading_anchor(section) + ")"),
              std::string::npos)
        << "the contents list does not link section '" << section << "'";
  for (size_t at = doc.find("](#"); at != std::string::npos; at = doc.find("](#", at + 1)) {
    const std::string anchor = doc.substr(at + 3, doc.find(')', at) - at - 3);
    EXPECT_TRUE(anchors.count(anchor)) << "link to #" << anchor << " resolves to no heading";
  }

  // The top-level table: every shared key and every module's section.
  const size_t top = doc.find("## 3. Top-level keys");
  ASSERT_NE(top, std::string::npos);
  const std::string table = doc.substr(top, doc.find("\n## ", top + 1) - top);
  std::vector<std::string> keys(scene_keys::top.keys.begin(), scene_keys::top.keys.end());
  for (const SceneSection& section : scene_sections()) keys.emplace_back(section.reader->key);
  for (const std::string& key : keys)
    EXPECT_NE(table.find("| `" + key + "` |"), std::string::npos)
        << "the top-level keys table has no row for `" << key << "`";
}

TEST(scene_parser, DocumentationExampleIsValid) {
  const std::string doc =
      read_text(std::filesystem::path(FISSURE_SOURCE_DIR) / "docs" / "scene-reference.md");
  const size_t section = doc.find("## 10. Complete example");
  ASSERT_NE(section, std::string::npos);
  const size_t begin = doc.find("```yaml\n", section);
  ASSERT_NE(begin, std::string::npos);
  const size_t end = doc.find("\n```", begin + 8);
  ASSERT_NE(end, std::string::npos);
  const std::string example = doc.substr(begin + 8, end - begin - 8 + 1);
  Scene s;
  ASSERT_NO_THROW(s = read_scene_text(example, "example.yaml"));
  EXPECT_EQ(s.name, "brick_on_base");
  EXPECT_EQ(s.blocks.size(), 2u);
  EXPECT_EQ(s.monitors.size(), 3u);
}

TEST(scene_parser, PhysicsNamesMatchTheProcessRegistry) {
  std::vector<std::string_view> scene_names;  // the physics the parser accepts
  for (const SceneSection& section : scene_sections())
    if (!section.physics.empty()) scene_names.push_back(section.physics);
  const std::vector<std::string> registry = known_physics();
  EXPECT_EQ(std::vector<std::string>(scene_names.begin(), scene_names.end()), registry);
}

TEST(scene_parser, ReadingAKeyOutsideItsTableIsAProgrammingError) {
  Diagnostics diagnostics("x.yaml");
  ConfigMap map(ConfigNode::root(YamlDocument::parse("a: 1"), diagnostics), scene_keys::time);
  EXPECT_THROW(map.optional("a"), std::logic_error);
  map.finish();
  EXPECT_NE(diagnostics.text().find("x.yaml:1:1: a: unknown key 'a'"), std::string::npos);
}

TEST(scene_parser, SuggestionsUseEditDistance) {
  EXPECT_EQ(edit_distance("denisty", "density"), 1);  // a transposition
  EXPECT_EQ(edit_distance("Density", "density"), 0);  // case-insensitive
  EXPECT_EQ(edit_distance("", "abc"), 3);
  EXPECT_EQ(edit_distance("time_stp", "time_step"), 1);
  constexpr std::string_view keys[] = {"name", "density", "young_modulus", "poisson_ratio"};
  EXPECT_EQ(closest_match("denisty", keys), "density");
  EXPECT_EQ(closest_match("youngs_modulus", keys), "young_modulus");
  EXPECT_EQ(closest_match("colour", keys), std::nullopt);
  EXPECT_EQ(closest_match("nmae", keys), "name");
}

}  // namespace
}  // namespace fissure
