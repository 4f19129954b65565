// Shared checks of the bad-scene tests (tests/robustness/test_bad_scene*.cpp):
// a valid scene to break, text edits, the expected FILE:LINE:COLUMN of a
// piece of text, and a matcher for the error lines of a SceneError.
#pragma once

#include <string>
#include <vector>

namespace fissure::testing {

/// A small valid scene (two blocks, one monitor) that each test breaks.
extern const std::string kValid;

/// A scene with several errors in several sections (all reported, in file order).
extern const std::string kSeveralErrors;

/// `text` with the one occurrence of `from` replaced by `to`.
std::string replace(std::string text, const std::string& from, const std::string& to);

/// "bad.yaml:LINE:COLUMN" of character `pos` of `text`.
std::string at(const std::string& text, size_t pos);

/// "bad.yaml:LINE:COLUMN" of the first occurrence of `needle` in `text`,
/// moved right by `offset` characters.
std::string at(const std::string& text, const std::string& needle, size_t offset = 0);

/// The lines of the SceneError thrown for `yaml` (empty, with a failure, if
/// the scene is accepted).
std::vector<std::string> errors(const std::string& yaml);

/// The message of the SceneError that reading `yaml` as `file` throws (the
/// files it names are looked for beside `file`), or "" when the scene is
/// accepted.
std::string parse_error(const std::string& yaml, const std::string& file = "bad.yaml");

/// The message of the SceneError that the processes' initialize throws for
/// `yaml` (the checks that need the meshes or the network), or "".
std::string start_error(const std::string& yaml);

/// Expects `part` in `text`, printing the text when it is not.
void expect_contains(const std::string& text, const std::string& part);

/// Checks that one error line starts with "WHERE: PATH: " and contains every
/// fragment (what was found, what was expected).
void expect_error(const std::vector<std::string>& lines, const std::string& where,
                  const std::string& path, const std::vector<std::string>& fragments);

}  // namespace fissure::testing
