#include "tests/support/bad_scene_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "core/base/errors.h"
#include "coupling/process_registry.h"

namespace fissure::testing {

extern const std::string kValid = R"(physics: [mechanics]
materials:
  - name: granite
    density: 2650 kg/m^3
    young_modulus: 50 GPa
    poisson_ratio: 0.25
joints:
  - name: bedding
    friction_angle: 30
blocks:
  - name: base
    vertices: [[0, 0], [10, 0], [10, 1], [0, 1]]
    fixed: true
  - name: top
    vertices: [[4, 1], [6, 1], [6, 2], [4, 2]]
monitors:
  - name: top
    point: [5, 1.5]
mechanics:
  dda:
    time_step: 1 ms
time:
  end: 1
)";

/// `text` with the one occurrence of `from` replaced by `to`.
std::string replace(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "'" << from << "' not in the scene";
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << "'" << from << "' is not unique";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// "bad.yaml:LINE:COLUMN" of character `pos` of `text`.
std::string at(const std::string& text, size_t pos) {
  const size_t line = 1 + std::count(text.begin(), text.begin() + pos, '\n');
  const size_t newline = pos == 0 ? std::string::npos : text.rfind('\n', pos - 1);
  const size_t column = newline == std::string::npos ? pos + 1 : pos - newline;
  return "bad.yaml:" + std::to_string(line) + ":" + std::to_string(column);
}

/// "bad.yaml:LINE:COLUMN" of the first occurrence of `needle` in `text`,
/// moved right by `offset` characters.
std::string at(const std::string& text, const std::string& needle, size_t offset) {
  const size_t pos = text.find(needle);
  EXPECT_NE(pos, std::string::npos) << "'" << needle << "' not in the scene";
  return pos == std::string::npos ? "?" : at(text, pos + offset);
}

/// The lines of the SceneError thrown for `yaml` (empty, with a failure, if
/// the scene is accepted).
std::string parse_error(const std::string& yaml, const std::string& file) {
  try {
    read_scene_text(yaml, file);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

std::string start_error(const std::string& yaml) {
  const Scene scene = read_scene_text(yaml, "bad.yaml");
  RockMass state = RockMass::from_scene(scene);
  try {
    for (auto& p : create_processes(scene)) p->initialize(state);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

void expect_contains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' not in:\n" << text;
}

std::vector<std::string> errors(const std::string& yaml) {
  try {
    read_scene_text(yaml, "bad.yaml");
  } catch (const SceneError& e) {
    std::vector<std::string> lines;
    std::istringstream in(e.what());
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  }
  ADD_FAILURE() << "the scene was accepted:\n" << yaml;
  return {};
}

/// Checks that one error line starts with "WHERE: PATH: " and contains every
/// fragment (what was found, what was expected).
void expect_error(const std::vector<std::string>& lines, const std::string& where,
                  const std::string& path, const std::vector<std::string>& fragments) {
  const std::string prefix = where + ": " + path + ": ";
  for (const std::string& line : lines) {
    if (line.rfind(prefix, 0) != 0) continue;
    bool all = true;
    for (const std::string& f : fragments) all = all && line.find(f) != std::string::npos;
    if (all) return;
  }
  std::string got;
  for (const std::string& line : lines) got += "  " + line + "\n";
  std::string want;
  for (const std::string& f : fragments) want += " [" + f + "]";
  ADD_FAILURE() << "no error '" << prefix << "...' with" << want << "; got:\n" << got;
}

extern const std::string kSeveralErrors = R"(physics: [mechanics]
materials:
  - name: granite
    density: -1
    young_modulus: 50 kg
    poisson_ratio: 0.5
joints:
  - name: bedding
    friction_angle: 30
    cohesoin: 1 MPa
blocks:
  - name: base
    vertices: [[0, 0], [10, 0], [10, 1], [0, 1]]
  - name: top
    material: basalt
    vertices: [[4, 1], [6, 2], [6, 1], [4, 3]]
mechanics: {}
time:
  end: 1
)";

}  // namespace fissure::testing
