// monitors.csv (docs/architecture.md 6): one row per output time, `t` then for each
// monitor m the columns of the active processes (monitor_source.h), ordered
// by rank: m.x, m.y, m.ux, m.uy, m.vx, m.vy (motion), m.p (fluid), m.sxx,
// m.syy, m.sxy (stress) where those processes are active. Two processes
// that watch the same quantity (the blocks' ux and the continuum's, a
// monitor in one or the other) share one column: the first finite value in
// the processes' order. Flushed after every row.
#pragma once

#include <array>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/io/monitor_source.h"
#include "core/scene/scene.h"
#include "core/state/rock_mass.h"

namespace fissure {

/// Where the writer's warnings go (default: a "warning: ..." line on stderr).
using WarningSink = std::function<void(const std::string&)>;

/// The columns of every monitor: which source, which of its values.
class MonitorLayout {
 public:
  explicit MonitorLayout(const std::vector<const MonitorSource*>& sources);

  struct Column {
    std::string name;
    bool brief = false;
    int source = 0;  ///< index into the sources
    int value = 0;   ///< index into that source's values
    /// The same-named values of later sources {source, value}: the column
    /// takes the first finite one where the first is NaN.
    std::vector<std::array<int, 2>> others;
  };
  const std::vector<Column>& columns() const { return columns_; }
  /// The values of every column at material point `point`, in column order.
  std::vector<double> values(const RockMass& state, int point) const;
  const MonitorSource& source(int s) const { return *sources_[s]; }

 private:
  std::vector<const MonitorSource*> sources_;
  std::vector<Column> columns_;
  std::vector<int> first_value_;  ///< per source: where its values start
  int n_values_ = 0;
};

class MonitorWriter {
 public:
  /// `sources`: the active processes' columns (they must outlive the writer).
  /// With `resume_at` (bytes), continues a restarted run's file: it is cut
  /// back to that length, the rows written after the checkpoint.
  MonitorWriter(const std::filesystem::path& file, const std::vector<Monitor>& monitors,
                const std::vector<const MonitorSource*>& sources, WarningSink warn = nullptr,
                std::optional<std::uintmax_t> resume_at = std::nullopt);
  void write_row(const RockMass& state, double t);
  /// Bytes written so far (every row is flushed): where a restart resumes.
  std::uintmax_t bytes() const;

 private:
  std::filesystem::path file_;  ///< for messages
  std::ofstream out_;
  std::vector<std::string> names_;
  MonitorLayout layout_;
  WarningSink warn_;
  std::vector<bool> warned_;  ///< per monitor and column: its missing value was reported
};

}  // namespace fissure
