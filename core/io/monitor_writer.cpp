#include "core/io/monitor_writer.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/base/errors.h"
#include "core/state/monitor_values.h"

namespace fissure {

namespace {

/// A CSV header field, quoted (RFC 4180) only when the name needs it.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string quoted = "\"";
  for (char c : s) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

/// 17 significant digits: every double reads back to the same bits.
void append_value(std::string& row, double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, ",%.17g", v);
  row += buffer;
}

}  // namespace

MonitorWriter::MonitorWriter(const std::filesystem::path& file,
                             const std::vector<Monitor>& monitors, bool mechanics)
    : file_(file), n_monitors_(static_cast<int>(monitors.size())), mechanics_(mechanics) {
  out_.open(file, std::ios::out | std::ios::trunc);
  FISSURE_CHECK(out_.is_open(), IoError,
                file.string() << ": cannot create the file (" << std::strerror(errno) << ")");
  std::string header = "t";
  if (mechanics_) {
    for (const Monitor& m : monitors)
      for (const char* column : {"x", "y", "ux", "uy", "vx", "vy", "sxx", "syy", "sxy"}) {
        header += ',';
        header += csv_field(m.name + "." + column);
      }
  }
  out_ << header << '\n' << std::flush;
  FISSURE_CHECK(out_.good(), IoError, file.string() << ": cannot write the header");
}

void MonitorWriter::write_row(const RockMass& state, double t) {
  // Monitors are the first material points (RockMass::points).
  FISSURE_CHECK(static_cast<int>(state.points.size()) >= n_monitors_, IoError,
                file_.string() << ": the state has " << state.points.size()
                               << " material points, fewer than the " << n_monitors_
                               << " monitors");
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", t);
  std::string row = buffer;
  if (mechanics_) {
    for (int m = 0; m < n_monitors_; ++m) {
      const MonitorValues v = evaluate_monitor(state, m);
      for (double value : {v.position.x(), v.position.y(), v.displacement.x(), v.displacement.y(),
                           v.velocity.x(), v.velocity.y(), v.stress(0), v.stress(1), v.stress(2)})
        append_value(row, value);
    }
  }
  row += '\n';
  // Flushed row by row so that a run that dies keeps every row written.
  out_ << row << std::flush;
  FISSURE_CHECK(out_.good(), IoError,
                file_.string() << ": cannot write the row at t = " << t << " s");
}

}  // namespace fissure
