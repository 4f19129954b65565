// Bad scene files (docs/architecture.md 3): each problem is reported as
// FILE:LINE:COLUMN: KEY.PATH: what was found; expected WHAT, all problems are
// reported together, and nothing runs. Each test starts from a valid scene,
// breaks one thing, and checks the file name, the position of the offending
// text, the key path and the expectation.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "core/base/errors.h"
#include "coupling/process_registry.h"
#include "tests/support/bad_scene_checks.h"

namespace fissure::testing {
namespace {

TEST(bad_scenes, TheValidSceneIsValid) {
  EXPECT_NO_THROW(read_scene_text(kValid, "bad.yaml"));
}

// A flood of one problem (10,000 copies of one block, issue 35) is
// summarized: three of each kind, then one line that counts the rest.
TEST(bad_scenes, AFloodOfOneProblemIsSummarized) {
  std::string s = kValid;
  std::string copies;
  for (int i = 0; i < 10000; ++i)
    copies += "  - {name: dup, vertices: [[0, 50], [1, 50], [1, 51], [0, 51]]}\n";
  s.insert(s.find("blocks:\n") + 8, copies);
  const std::string e = parse_error(s);
  EXPECT_LT(e.size(), 20000u) << "the message of 10,000 duplicate names";
  expect_contains(e, "found '");
  const auto last_copy = 1 + std::count(s.begin(), s.begin() + s.find("blocks:\n"), '\n') + 10000;
  expect_contains(e, "  ... and 9996 more problems like the one above, up to line " +
                         std::to_string(last_copy));
  std::istringstream lines(e);
  int shown = 0;
  for (std::string line; std::getline(lines, line);)
    shown += line.find("already the name") != std::string::npos;
  EXPECT_EQ(shown, 3);
}

// --- syntax, keys -------------------------------------------------------------

TEST(bad_scenes, MalformedYamlIsOneErrorAtTheParserPosition) {
  const std::string yaml = replace(kValid, "    density: 2650 kg/m^3\n", "    density: [2650\n");
  const std::vector<std::string> lines = errors(yaml);
  ASSERT_EQ(lines.size(), 1u);
  // yaml-cpp notices the unclosed '[' at the ':' of the next key.
  expect_error(
      lines, "bad.yaml:5:18", "(document)",
      {"found malformed YAML (end of sequence flow not found)", "expected valid YAML syntax"});

  const std::string bad_indent = replace(kValid, "    poisson_ratio", "   poisson_ratio");
  expect_error(errors(bad_indent), at(bad_indent, "poisson_ratio"), "(document)",
               {"found malformed YAML", "expected valid YAML syntax"});
}

TEST(bad_scenes, StrayCommaIsMalformedYamlNotAnEndlessLoop) {
  // yaml-cpp 0.7 reads a ',' where a block value starts as empty documents
  // without end, allocating until memory runs out (found by
  // tests/robustness/fuzz_scenes.py: `fissure validate` on a 5-byte file
  // took 2 GB and ended in std::bad_alloc).
  for (const std::string& yaml :
       {std::string(",\n"), std::string(", *a\n") + kValid, std::string("# comment\n  ,\n")}) {
    const std::vector<std::string> lines = errors(yaml);
    ASSERT_EQ(lines.size(), 1u) << yaml;
    expect_error(
        lines, at(yaml, ","), "(document)",
        {"found malformed YAML (',' where a value should start)", "expected valid YAML syntax"});
  }
  // After a first document: the stuck place is reported, not "a second document".
  const std::vector<std::string> after_list = errors("- a\n,\n");
  ASSERT_EQ(after_list.size(), 1u);
  expect_error(after_list, "bad.yaml:2:1", "(document)",
               {"found malformed YAML (',' where a value should start)"});
}

TEST(bad_scenes, BytesThatAreNotUtf8AreOneErrorAtTheByte) {
  // A name with a stray byte went into summary.json, which JSON cannot hold
  // ("invalid UTF-8 byte", unlocated; found by tests/robustness/fuzz_scenes.py).
  for (const std::string& bad :
       {std::string("\xAD"), std::string("\xC3("), std::string("\xE0\x80\x80"),
        std::string("\xED\xA0\x80"), std::string("\xF4\x90\x80\x80"), std::string("\xC3")}) {
    const std::string yaml = replace(kValid, "granite", "gra" + bad + "nite");
    const std::vector<std::string> lines = errors(yaml);
    ASSERT_EQ(lines.size(), 1u) << yaml;
    expect_error(lines, at(yaml, bad), "(document)",
                 {"which is not UTF-8 text", "expected a file in UTF-8"});
  }
  // Well-formed UTF-8 of two to four bytes is text like any other.
  EXPECT_NO_THROW(read_scene_text(replace(kValid, "granite",
                                          "gr\xC3\xA4n\xE2\x82\xACit\xF0\x9F\x98\x80"
                                          "e"),
                                  "bad.yaml"));
}

TEST(bad_scenes, CarriageReturnsWithoutLineFeedsAreRefusedNotReadAsOneLine) {
  // yaml-cpp 0.7 does not end a line at a lone CR (classic Mac OS line
  // ends): the scene was one line, its first comment hid every key, and the
  // keys were reported missing (found by tests/robustness/fuzz_scenes.py).
  std::string mac = "# a comment first\n" + kValid;
  std::replace(mac.begin(), mac.end(), '\n', '\r');
  std::vector<std::string> lines = errors(mac);
  ASSERT_EQ(lines.size(), 1u) << lines.front();
  expect_error(
      lines, at(mac, "\r"), "(document)",
      {"found a carriage return (CR) without a line feed", "expected LF or CR LF line ends"});
  // One lone CR among LF lines is refused at its place.
  const std::string one = replace(kValid, "granite", "gran\rite");
  lines = errors(one);
  ASSERT_EQ(lines.size(), 1u);
  expect_error(lines, at(one, "\r"), "(document)", {"without a line feed"});
  // CR LF (Windows) line ends are line ends like any other.
  std::string windows;
  for (char c : kValid) windows += c == '\n' ? std::string("\r\n") : std::string(1, c);
  EXPECT_NO_THROW(read_scene_text(windows, "bad.yaml"));
}

TEST(bad_scenes, UnknownKeyWithSuggestion) {
  const std::string yaml = replace(kValid, "    density:", "    denisty:");
  const std::vector<std::string> lines = errors(yaml);
  expect_error(lines, at(yaml, "denisty"), "materials[0].denisty",
               {"unknown key 'denisty' (did you mean 'density'?)",
                "expected one of: name, density, young_modulus, poisson_ratio"});
  ASSERT_EQ(lines.size(), 1u) << "the misspelling is not also reported as a missing 'density'";

  const std::string top = replace(kValid, "monitors:", "monitor:");
  expect_error(errors(top), at(top, "monitor:"), "monitor",
               {"unknown key 'monitor' (did you mean 'monitors'?)", "expected one of: name, "});

  const std::string nested = replace(kValid, "    time_step: 1 ms", "    time_stp: 1 ms");
  expect_error(errors(nested), at(nested, "time_stp"), "mechanics.dda.time_stp",
               {"did you mean 'time_step'?", "expected one of: time_step, "});
}

TEST(bad_scenes, UnknownKeyWithoutSuggestion) {
  const std::string yaml = kValid + "colour: red\n";
  const std::vector<std::string> lines = errors(yaml);
  ASSERT_EQ(lines.size(), 1u);
  expect_error(lines, at(yaml, "colour"), "colour",
               {"unknown key 'colour'; expected one of: name, physics, gravity, materials"});
  EXPECT_EQ(lines[0].find("did you mean"), std::string::npos);
}

TEST(bad_scenes, KeyGivenTwice) {
  const std::string yaml =
      replace(kValid, "    poisson_ratio: 0.25\n", "    poisson_ratio: 0.25\n    density: 2000\n");
  expect_error(errors(yaml), at(yaml, "density: 2000"), "materials[0].density",
               {"found a second 'density' (the first is on line 4)", "expected each key once"});
}

TEST(bad_scenes, MissingRequiredKeys) {
  const std::string yaml = replace(kValid, "    poisson_ratio: 0.25\n", "");
  // A missing key is reported at the map that should hold it.
  expect_error(errors(yaml), at(yaml, "name: granite"), "materials[0].poisson_ratio",
               {"key is missing", "expected a number in (-1, 0.5)"});

  const std::string no_time = replace(kValid, "time:\n  end: 1\n", "");
  expect_error(errors(no_time), "bad.yaml:1:1", "time", {"key is missing", "expected a time"});

  const std::string no_end = replace(kValid, "  end: 1\n", "  max_steps: 10\n");
  expect_error(errors(no_end), at(no_end, "max_steps"), "time.end",
               {"key is missing", "expected a time > 0"});

  const std::string no_vertices =
      replace(kValid, "    vertices: [[4, 1], [6, 1], [6, 2], [4, 2]]\n", "");
  expect_error(errors(no_vertices), at(no_vertices, "name: top"), "blocks[1].vertices",
               {"key is missing", "expected a list of at least 3 vertices [x, y]"});

  const std::string no_physics = replace(kValid, "physics: [mechanics]\n", "");
  expect_error(
      errors(no_physics), "bad.yaml:1:1", "physics",
      {"key is missing",
       "expected a non-empty list of physics names (mechanics, dem, flow, thermal, continuum)"});
}

// --- types, units, ranges -------------------------------------------------------

/// Replaces `from` by `to` in the valid scene and expects an error at the
/// first occurrence of `needle` (moved right by `offset`) with `path` and
/// `fragments`.
void expect_broken(const std::string& from, const std::string& to, const std::string& needle,
                   size_t offset, const std::string& path,
                   const std::vector<std::string>& fragments) {
  SCOPED_TRACE(to);
  const std::string yaml = replace(kValid, from, to);
  expect_error(errors(yaml), at(yaml, needle, offset), path, fragments);
}

TEST(bad_scenes, WrongYamlTypes) {
  expect_broken("density: 2650 kg/m^3", "density: {value: 2650}", "{value", 0,
                "materials[0].density",
                {"found a map", "expected a density > 0 (kg/m^3, g/cm^3, t/m^3)"});
  expect_broken("density: 2650 kg/m^3", "density: heavy", "heavy", 0, "materials[0].density",
                {"found 'heavy', which is not a number", "expected a density"});
  expect_broken(
      "physics: [mechanics]", "physics: mechanics", "physics: mechanics", 9, "physics",
      {"found 'mechanics'",
       "expected a non-empty list of physics names (mechanics, dem, flow, thermal, continuum)"});
  expect_broken("joints:\n  - name: bedding\n    friction_angle: 30", "joints:\n  - bedding",
                "- bedding", 2, "joints[0]",
                {"found 'bedding'", "expected a map with keys: name, friction_angle"});
  expect_broken("time_step: 1 ms", "time_step: [1, 2]", "[1, 2]", 0, "mechanics.dda.time_step",
                {"found a list of 2 values", "expected a time > 0 (s, ms, min, h, d, yr)"});
  expect_broken("fixed: true", "fixed: yes", "yes", 0, "blocks[0].fixed",
                {"found 'yes'", "expected true or false"});
  expect_broken("end: 1", "end: 1\n  max_steps: 2.5", "2.5", 0, "time.max_steps",
                {"found '2.5', which is not an integer", "expected an integer >= 1"});
  // 2^63 passes `<= LONG_MAX` as a double but does not fit a long (fuzz_scenes.py).
  expect_broken("end: 1", "end: 1\n  max_steps: 9223372036854775808", "9223372036854775808", 0,
                "time.max_steps",
                {"found '9223372036854775808', which is out of the range of integers",
                 "expected an integer >= 1"});
  expect_broken("point: [5, 1.5]", "point: [5, 1.5, 0]", "[5, 1.5, 0]", 0, "monitors[0].point",
                {"found a list of 3 values", "expected a list of 2 lengths [x, y]"});
  expect_broken("vertices: [[0, 0], [10, 0]", "vertices: [[0, 0], [10, zero]", "zero", 0,
                "blocks[0].vertices[1][1]",
                {"found 'zero', which is not a number", "expected a length"});
  expect_broken("time:\n  end: 1", "time: 1", "time: 1", 6, "time",
                {"found '1'", "expected a map with keys: end, max_steps, min_step"});
  expect_broken("materials:", "materials: granite\nmaterial_list:", "granite", 0, "materials",
                {"found 'granite'", "expected a non-empty list of materials"});
}

TEST(bad_scenes, WrongUnitDimension) {
  const std::string yaml = replace(kValid, "young_modulus: 50 GPa", "young_modulus: 2650 kg/m^3");
  expect_error(errors(yaml), at(yaml, "2650 kg/m^3\n    poisson"), "materials[0].young_modulus",
               {"found '2650 kg/m^3', a density", "expected a pressure (Pa, kPa, MPa, GPa)"});

  const std::string time = replace(kValid, "time_step: 1 ms", "time_step: 1 mm");
  expect_error(errors(time), at(time, "1 mm"), "mechanics.dda.time_step",
               {"found '1 mm', a length", "expected a time (s, ms, min, h, d, yr)"});

  const std::string angle = replace(kValid, "friction_angle: 30", "friction_angle: 30 Pa");
  expect_error(errors(angle), at(angle, "30 Pa"), "joints[0].friction_angle",
               {"found '30 Pa', a pressure", "expected an angle (deg, rad)"});

  const std::string unknown = replace(kValid, "young_modulus: 50 GPa", "young_modulus: 50 GPA");
  expect_error(errors(unknown), at(unknown, "50 GPA"), "materials[0].young_modulus",
               {"unknown unit 'GPA' (did you mean 'GPa'?)", "expected a pressure"});
}

TEST(bad_scenes, NonFiniteNumbers) {
  for (const char* value : {".nan", ".inf", "-.inf"}) {
    const std::string yaml =
        replace(kValid, "density: 2650 kg/m^3", std::string("density: ") + value);
    expect_error(errors(yaml), at(yaml, value), "materials[0].density",
                 {"which is not a finite number", "expected a density"});
  }
}

TEST(bad_scenes, NonPositiveDensityAndModulus) {
  for (const std::string value : {"0", "-2650", "-2.65 t/m^3"}) {
    const std::string yaml = replace(kValid, "density: 2650 kg/m^3", "density: " + value);
    expect_error(errors(yaml), at(yaml, "density: " + value, 9), "materials[0].density",
                 {"found '" + value + "'", "expected a density > 0"});
  }
  for (const std::string value : {"0", "-50 GPa"}) {
    const std::string yaml = replace(kValid, "young_modulus: 50 GPa", "young_modulus: " + value);
    expect_error(errors(yaml), at(yaml, "young_modulus: " + value, 15),
                 "materials[0].young_modulus",
                 {"found '" + value + "'", "expected a pressure > 0"});
  }
}

TEST(bad_scenes, PoissonRatioOutsideItsOpenInterval) {
  for (const char* value : {"0.5", "-1", "0.7", "-1.5"}) {
    SCOPED_TRACE(value);
    const std::string yaml =
        replace(kValid, "poisson_ratio: 0.25", std::string("poisson_ratio: ") + value);
    expect_error(errors(yaml), at(yaml, value + std::string("\njoints")),
                 "materials[0].poisson_ratio",
                 {"found '" + std::string(value) + "'", "expected a number in (-1, 0.5)"});
  }
  for (const char* value : {"0.49", "-0.99"}) {
    const std::string yaml =
        replace(kValid, "poisson_ratio: 0.25", std::string("poisson_ratio: ") + value);
    EXPECT_NO_THROW(read_scene_text(yaml, "bad.yaml")) << value;
  }
}

TEST(bad_scenes, OtherRanges) {
  // `to` ends with the offending value.
  const auto expect_range = [](const std::string& from, const std::string& to,
                               const std::string& value, const std::string& path,
                               const std::string& expected) {
    expect_broken(from, to, to, to.size() - value.size(), path,
                  {"found '" + value + "'", expected});
  };
  expect_range("friction_angle: 30", "friction_angle: 90", "90", "joints[0].friction_angle",
               "expected an angle in [0, 90) deg");
  expect_range("friction_angle: 30", "friction_angle: 1.6 rad", "1.6 rad",
               "joints[0].friction_angle", "expected an angle in [0, 90) deg");
  expect_range("friction_angle: 30", "friction_angle: -1", "-1", "joints[0].friction_angle",
               "expected an angle in [0, 90) deg");
  expect_range("friction_angle: 30", "friction_angle: 30\n    cohesion: -1 kPa", "-1 kPa",
               "joints[0].cohesion", "expected a pressure >= 0");
  expect_range("time_step: 1 ms", "time_step: 0", "0", "mechanics.dda.time_step",
               "expected a time > 0");
  expect_range("time_step: 1 ms", "time_step: 1 ms\n    velocity_carry_over: 1.5", "1.5",
               "mechanics.dda.velocity_carry_over", "expected a number in [0, 1]");
  expect_range("time_step: 1 ms", "time_step: 1 ms\n    damping_ratio: 1", "1",
               "mechanics.dda.damping_ratio", "expected a number in [0, 1)");
  expect_range("time_step: 1 ms", "time_step: 1 ms\n    shear_penalty_ratio: 0", "0",
               "mechanics.dda.shear_penalty_ratio", "expected a number in (0, 10]");
  expect_range("time_step: 1 ms", "time_step: 1 ms\n    max_displacement_ratio: 1", "1",
               "mechanics.dda.max_displacement_ratio", "expected a number in (0, 1)");
  expect_range("time_step: 1 ms", "time_step: 1 ms\n    max_open_close_iterations: 0", "0",
               "mechanics.dda.max_open_close_iterations", "expected an integer in [1, 1000]");
  // 1e6 kept one step busy for minutes (the fuzzer's HANG, case 6777).
  expect_range("time_step: 1 ms", "time_step: 1 ms\n    max_open_close_iterations: 1e6", "1e6",
               "mechanics.dda.max_open_close_iterations", "expected an integer in [1, 1000]");
  expect_range("time_step: 1 ms", "time_step: 1 ms\n    penalty: -1", "-1", "mechanics.dda.penalty",
               "expected a stiffness > 0");
  expect_range("time_step: 1 ms", "time_step: 1 ms\n    penalty: automatic", "automatic",
               "mechanics.dda.penalty", "expected 'auto' or a stiffness > 0");
  expect_range("end: 1", "end: 1\n  min_step: 2", "2", "time.min_step",
               "expected a time shorter than time.end (1 s)");
  expect_range("end: 1", "end: 1\noutput:\n  interval: -1 s", "-1 s", "output.interval",
               "expected a time >= 0");
  expect_range("end: 1", "end: 1\noutput:\n  every_steps: -1", "-1", "output.every_steps",
               "expected an integer >= 0");
}

// --- references and consistency ----------------------------------------------------

TEST(bad_scenes, UnknownReferences) {
  const std::string material = replace(kValid, "  - name: top\n    vertices",
                                       "  - name: top\n    material: granit\n    vertices");
  expect_error(errors(material), at(material, "granit\n"), "blocks[1].material",
               {"found 'granit' (did you mean 'granite'?), which is not defined",
                "expected the name of a material: granite"});

  const std::string joint = replace(kValid, "  - name: top\n    vertices",
                                    "  - name: top\n    joint: faults\n    vertices");
  expect_error(errors(joint), at(joint, "faults"), "blocks[1].joint",
               {"found 'faults'", "expected the name of a joint: bedding"});

  const std::string default_joint = kValid + "default_joint: fault\n";
  expect_error(errors(default_joint), at(default_joint, "fault\n"), "default_joint",
               {"found 'fault'", "expected the name of a joint: bedding"});

  const std::string block = replace(kValid, "point: [5, 1.5]", "point: [5, 1.5]\n    block: tops");
  expect_error(errors(block), at(block, "tops"), "monitors[0].block",
               {"found 'tops' (did you mean 'top'?)", "expected the name of a block: base, top"});

  const std::string second_material =
      replace(kValid, "joints:",
              "  - name: sandstone\n    density: 2400\n    young_modulus: 20 GPa\n"
              "    poisson_ratio: 0.2\njoints:");
  expect_error(errors(second_material), at(second_material, "name: base"), "blocks[0].material",
               {"key is missing", "required when the scene has more than one"});
}

TEST(bad_scenes, DuplicateNames) {
  const std::string yaml =
      replace(kValid, "  - name: top\n    vertices", "  - name: base\n    vertices");
  expect_error(errors(yaml), at(yaml, "base\n    vertices: [[4"), "blocks[1].name",
               {"found 'base' again (already the name of block 0 on line 11)",
                "expected a unique block name"});

  const std::string monitors = replace(kValid, "    point: [5, 1.5]\n",
                                       "    point: [5, 1.5]\n  - name: top\n    point: [5, 1.6]\n");
  expect_error(errors(monitors), at(monitors, "top\n    point: [5, 1.6]"), "monitors[1].name",
               {"found 'top' again (already the name of monitor 0 on line 17)",
                "expected a unique monitor name"});

  const std::string materials = replace(kValid, "joints:",
                                        "  - name: granite\n    density: 1\n    young_modulus: 1\n"
                                        "    poisson_ratio: 0\njoints:");
  expect_error(errors(materials), at(materials, "granite\n    density: 1\n"), "materials[1].name",
               {"found 'granite' again", "expected a unique material name"});
}

TEST(bad_scenes, PhysicsNames) {
  const std::string unknown = replace(kValid, "[mechanics]", "[mechanics, hydraulics]");
  expect_error(errors(unknown), at(unknown, "hydraulics"), "physics[1]",
               {"found 'hydraulics'", "expected one of: mechanics, dem, flow"});
  const std::string twice = replace(kValid, "[mechanics]", "[mechanics, mechanics]");
  expect_error(errors(twice), at(twice, "mechanics]"), "physics[1]",
               {"a second time", "expected each physics name once"});
  const std::string empty = replace(kValid, "[mechanics]", "[]");
  expect_error(errors(empty), at(empty, "[]"), "physics",
               {"found an empty list", "expected a non-empty list of physics names"});
}

TEST(bad_scenes, MechanicsSectionAndPhysicsMustAgree) {
  // A mechanics section, but physics does not list mechanics.
  const std::string extra = replace(kValid, "[mechanics]", "[flow]");
  const std::vector<std::string> lines = errors(extra);
  expect_error(lines, at(extra, "mechanics:\n  dda"), "mechanics",
               {"found a mechanics section, but physics does not list mechanics",
                "expected 'mechanics' in physics, or no mechanics section"});
  // physics lists mechanics, but there is no mechanics section.
  const std::string missing = replace(kValid, "mechanics:\n  dda:\n    time_step: 1 ms\n", "");
  expect_error(errors(missing), "bad.yaml:1:1", "mechanics",
               {"key is missing", "expected a mechanics section, because physics lists mechanics"});
  // ... and no joints.
  const std::string no_joints =
      replace(kValid, "joints:\n  - name: bedding\n    friction_angle: 30\n", "");
  expect_error(errors(no_joints), "bad.yaml:1:1", "joints",
               {"key is missing", "expected a non-empty list of joints (physics lists mechanics)"});
}

TEST(bad_scenes, OtherInconsistencies) {
  const std::string moving =
      replace(kValid, "    fixed: true\n", "    fixed: true\n    initial_velocity: [1, 0, 0]\n");
  expect_error(errors(moving), at(moving, "[1, 0, 0]"), "blocks[0].initial_velocity",
               {"on a fixed block", "expected [0, 0, 0]"});

  const std::string petsc = replace(kValid, "time_step: 1 ms",
                                    "time_step: 1 ms\n    solver:\n      type: direct\n"
                                    "      petsc_options: \"-ksp_type cg\"");
  expect_error(errors(petsc), at(petsc, "petsc_options"), "mechanics.dda.solver.petsc_options",
               {"found PETSc options with solver type 'direct'", "expected type petsc or auto"});

  const std::string history = kValid +
                              "point_loads:\n  - point: [5, 2]\n    force: [0, -1 kN]\n"
                              "    history: [[0, 0], [1, 1], [1, 2]]\n";
  expect_error(errors(history), at(history, "[1, 2]"), "point_loads[0].history[2]",
               {"found t = 1 s after t = 1 s", "expected strictly increasing times"});

  const std::string name =
      replace(kValid, "  - name: top\n    point", "  - name: top.x\n    point");
  expect_error(errors(name), at(name, "top.x"), "monitors[0].name",
               {"found 'top.x'", "expected a name without commas, dots"});

  const std::string directions =
      kValid + "fixed_points:\n  - point: [0, 0]\n    directions: [x, z]\n";
  expect_error(errors(directions), at(directions, "z]"), "fixed_points[0].directions[1]",
               {"found 'z'", "expected one of: x, y"});
}

// --- several problems --------------------------------------------------------------

TEST(bad_scenes, SeveralErrorsAreAllReportedInFileOrder) {
  const std::vector<std::string> lines = errors(kSeveralErrors);
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0],
            "bad.yaml:4:14: materials[0].density: found '-1'; expected a density > 0 "
            "(kg/m^3, g/cm^3, t/m^3)");
  EXPECT_EQ(lines[1],
            "bad.yaml:5:20: materials[0].young_modulus: found '50 kg', a mass; "
            "expected a pressure (Pa, kPa, MPa, GPa)");
  EXPECT_EQ(lines[2],
            "bad.yaml:6:20: materials[0].poisson_ratio: found '0.5'; expected a "
            "number in (-1, 0.5)");
  EXPECT_EQ(lines[3],
            "bad.yaml:10:5: joints[0].cohesoin: unknown key 'cohesoin' (did you mean "
            "'cohesion'?); expected one of: name, friction_angle, cohesion, "
            "tensile_strength, model, normal_stiffness, shear_stiffness, dilation_angle, "
            "zero_dilation_displacement");
  EXPECT_EQ(lines[4],
            "bad.yaml:15:15: blocks[1].material: found 'basalt', which is not "
            "defined; expected the name of a material: granite");
  EXPECT_EQ(lines[5].rfind("bad.yaml:16:5: blocks[1].vertices: ", 0), 0u) << lines[5];
  EXPECT_NE(lines[5].find("intersect"), std::string::npos) << lines[5];
}

TEST(bad_scenes, EmptyFileAndWrongRoot) {
  expect_error(errors(""), "bad.yaml:1:1", "(document)",
               {"found an empty file", "expected a scene"});
  expect_error(errors("- 1\n- 2\n"), "bad.yaml:1:1", "(document)",
               {"found a list of 2 values", "expected a map with keys: name, physics"});
}

}  // namespace
}  // namespace fissure::testing
