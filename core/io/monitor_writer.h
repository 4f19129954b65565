// monitors.csv (architecture.md 4): one row per output time, `t` then for each
// monitor m the columns of the active processes: m.x, m.y, m.ux, m.uy, m.vx,
// m.vy (mechanics), m.p (flow; fracture_pressure.h), m.sxx, m.syy, m.sxy
// (stress, with the mechanics). Flushed after every row.
#pragma once

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "core/state/rock_mass.h"

namespace fissure {

/// Where the writer's warnings go (default: a "warning: ..." line on stderr).
using WarningSink = std::function<void(const std::string&)>;

class MonitorWriter {
 public:
  /// `mechanics` and `flow`: which processes are active, hence which columns.
  MonitorWriter(const std::filesystem::path& file, const std::vector<Monitor>& monitors,
                bool mechanics, bool flow = false, WarningSink warn = nullptr);
  void write_row(const RockMass& state, double t);

 private:
  /// m.p of monitor m; warns once per monitor when it has no pressure.
  double pressure(const RockMass& state, int m);

  std::filesystem::path file_;  ///< for messages
  std::ofstream out_;
  std::vector<std::string> names_;
  bool mechanics_ = false;
  bool flow_ = false;
  WarningSink warn_;
  std::vector<bool> warned_;  ///< per monitor: the missing pressure was reported
};

}  // namespace fissure
