#include "core/io/summary_writer.h"

#include "core/io/atomic_file.h"

namespace fissure {

std::string recorded_file_path(const std::filesystem::path& file) {
  if (file.empty()) return {};
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(file, ec);
  if (ec) return file.lexically_normal().string();
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(absolute, ec);
  return (ec ? absolute.lexically_normal() : canonical).string();
}

void write_summary(const std::filesystem::path& file, const RunSummary& summary) {
  // Keys in a fixed, readable order (run identity first, details last).
  nlohmann::ordered_json j;
  j["scene"] = summary.scene;
  if (!summary.scene_file.empty()) j["scene_file"] = summary.scene_file;
  j["status"] = summary.status;
  j["message"] = summary.message;
  j["steps"] = summary.steps;
  j["simulated_time"] = summary.simulated_time;
  j["time_unit"] = {{"name", summary.time_unit.name}, {"seconds", summary.time_unit.seconds}};
  j["wall_seconds"] = summary.wall_seconds;
  j["output_frames"] = summary.output_frames;
  j["processes"] = nlohmann::ordered_json(summary.processes);
  j["monitors"] = nlohmann::ordered_json(summary.monitors);
  j["energy"] = nlohmann::ordered_json(summary.energy);
  if (!summary.rock_mass.empty()) j["rock_mass"] = nlohmann::ordered_json(summary.rock_mass);
  // NaN and infinity are written as null (JSON has no such numbers), and
  // bytes that are not UTF-8 (a message quoting a file name, say) are
  // replaced rather than aborting the summary of a run that failed.
  const std::string text = j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  write_file_atomically(file, text + "\n");
}

}  // namespace fissure
