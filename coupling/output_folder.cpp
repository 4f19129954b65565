#include "coupling/output_folder.h"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/io/summary_writer.h"

namespace fissure {

namespace fs = std::filesystem;

fs::path default_output_folder(const fs::path& input, std::string_view group) {
  fs::path folder = "out";
  if (!group.empty()) folder /= std::string(group);
  return folder / input.stem();
}

std::optional<std::string> check_output_folder(const fs::path& outdir, const OutputRecord& record,
                                               const fs::path& input, std::string_view name,
                                               bool chosen) {
  const fs::path record_file = outdir / std::string(record.file);
  std::ifstream in(record_file);
  if (!in) return std::nullopt;  // a new folder, or one no command wrote
  std::ostringstream text;
  text << in.rdbuf();
  const nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, false);
  if (!j.is_object()) return std::nullopt;  // cut short by a crash: nothing to compare

  // Whose results: the file, or for records that name none, the name.
  std::string owner;
  const std::string file_key(record.file_key), name_key(record.name_key);
  if (j.contains(file_key) && j[file_key].is_string()) {
    const std::string recorded = j[file_key].get<std::string>();
    if (recorded == recorded_file_path(input)) return std::nullopt;
    owner = recorded;
  } else if (j.contains(name_key) && j[name_key].is_string()) {
    const std::string recorded = j[name_key].get<std::string>();
    if (recorded == name) return std::nullopt;
    owner = fmt::format("'{}' (by its name; the file is not recorded)", recorded);
  } else {
    return std::nullopt;
  }
  if (chosen)
    return fmt::format("{} held the results of {}; they are replaced by those of {}",
                       outdir.string(), owner, input.string());
  throw OutputFolderError(fmt::format(
      "{} holds the results of {} ({}), not of {}; nothing was written. Expected -o OUTDIR to "
      "choose the folder (a folder given with -o is written into), or that folder removed",
      outdir.string(), owner, record_file.string(), input.string()));
}

}  // namespace fissure
