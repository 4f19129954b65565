// Where a command writes (docs/output.md, "Output folder"): by default
// out/<input file's stem>/, so that two scenes with the same `name:` in
// different files do not share a folder; and a default folder that holds the
// results of another input file (its summary.json or rev.json names that
// file) is refused before anything is written, rather than overwritten.
// With -o the user chose the folder: the results are replaced, with a
// warning naming the file they came from.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "core/base/errors.h"

namespace fissure {

/// A default output folder that holds another input file's results.
class OutputFolderError : public Error {
 public:
  using Error::Error;
};

/// The record of an output folder: the JSON file a command writes there,
/// and its keys for the input file and for the input's name (the record of
/// older versions, which named no file).
struct OutputRecord {
  std::string_view file;      ///< "summary.json"
  std::string_view file_key;  ///< "scene_file"
  std::string_view name_key;  ///< "scene"
};
inline constexpr OutputRecord kRunRecord{"summary.json", "scene_file", "scene"};
inline constexpr OutputRecord kRevRecord{"rev.json", "study_file", "name"};

/// out/<group>/<stem of input> (out/<stem> without a group).
std::filesystem::path default_output_folder(const std::filesystem::path& input,
                                            std::string_view group = {});

/// Checks that `outdir` may take the results of `input` (whose name, the
/// scene's or study's `name:`, is `name`): it may when it holds no record,
/// or a record of the same file (of an older version: of the same name).
/// Otherwise, for a default folder (`chosen` false) throws OutputFolderError
/// naming both files and what to do; for a chosen one returns the warning
/// to print. Writes nothing.
std::optional<std::string> check_output_folder(const std::filesystem::path& outdir,
                                               const OutputRecord& record,
                                               const std::filesystem::path& input,
                                               std::string_view name, bool chosen);

}  // namespace fissure
