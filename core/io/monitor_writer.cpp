#include "core/io/monitor_writer.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <utility>

#include <fmt/format.h>

#include "core/base/errors.h"
#include "core/io/fracture_pressure.h"
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
                             const std::vector<Monitor>& monitors, bool mechanics, bool flow,
                             WarningSink warn)
    : file_(file),
      mechanics_(mechanics),
      flow_(flow),
      warn_(std::move(warn)),
      warned_(monitors.size(), false) {
  if (!warn_)
    warn_ = [](const std::string& message) {
      std::fprintf(stderr, "warning: %s\n", message.c_str());
      std::fflush(stderr);
    };
  for (const Monitor& m : monitors) names_.push_back(m.name);
  out_.open(file, std::ios::out | std::ios::trunc);
  FISSURE_CHECK(out_.is_open(), IoError,
                file.string() << ": cannot create the file (" << std::strerror(errno) << ")");
  // Per monitor, in the order of architecture.md 4.
  std::vector<const char*> columns;
  if (mechanics_) columns.insert(columns.end(), {"x", "y", "ux", "uy", "vx", "vy"});
  if (flow_) columns.push_back("p");
  if (mechanics_) columns.insert(columns.end(), {"sxx", "syy", "sxy"});
  std::string header = "t";
  for (const std::string& name : names_)
    for (const char* column : columns) {
      header += ',';
      header += csv_field(name + "." + column);
    }
  out_ << header << '\n' << std::flush;
  FISSURE_CHECK(out_.good(), IoError, file.string() << ": cannot write the header");
}

double MonitorWriter::pressure(const RockMass& state, int m) {
  const Vec2& x = state.points[m].current;
  const double p = fracture_pressure_at(state, x);
  if (std::isnan(p) && !warned_[m]) {
    warned_[m] = true;
    warn_(fmt::format(
        "{}: monitor '{}' at ({:g}, {:g}) m is not on the fracture network (no segment within "
        "{:g} m, {:g} x the network's size): its column {}.p is nan",
        file_.string(), names_[m], x.x(), x.y(), pressure_search_distance(state.fractures),
        kPressureSearchFraction, names_[m]));
  }
  return p;
}

void MonitorWriter::write_row(const RockMass& state, double t) {
  // Monitors are the first material points (RockMass::points).
  const int n_monitors = static_cast<int>(names_.size());
  FISSURE_CHECK(static_cast<int>(state.points.size()) >= n_monitors, IoError,
                file_.string() << ": the state has " << state.points.size()
                               << " material points, fewer than the " << n_monitors << " monitors");
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", t);
  std::string row = buffer;
  for (int m = 0; m < n_monitors && (mechanics_ || flow_); ++m) {
    const MonitorValues v = evaluate_monitor(state, m);
    if (mechanics_)
      for (double value : {v.position.x(), v.position.y(), v.displacement.x(), v.displacement.y(),
                           v.velocity.x(), v.velocity.y()})
        append_value(row, value);
    if (flow_) append_value(row, pressure(state, m));
    if (mechanics_)
      for (double value : {v.stress(0), v.stress(1), v.stress(2)}) append_value(row, value);
  }
  row += '\n';
  // Flushed row by row so that a run that dies keeps every row written.
  out_ << row << std::flush;
  FISSURE_CHECK(out_.good(), IoError,
                file_.string() << ": cannot write the row at t = " << t << " s");
}

}  // namespace fissure
