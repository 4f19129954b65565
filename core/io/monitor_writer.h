// monitors.csv (architecture.md 4): one row per output time, `t` then for each
// monitor m the columns of the active processes: m.x, m.y, m.ux, m.uy, m.vx,
// m.vy (mechanics), m.sxx, m.syy, m.sxy (stress). Flushed after every row.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/state/rock_mass.h"

namespace fissure {

class MonitorWriter {
 public:
  MonitorWriter(const std::filesystem::path& file, const std::vector<Monitor>& monitors,
                bool mechanics);
  void write_row(const RockMass& state, double t);

 private:
  std::filesystem::path file_;  ///< for messages
  std::ofstream out_;
  int n_monitors_ = 0;
  bool mechanics_ = false;
};

}  // namespace fissure
