#include "core/io/monitor_writer.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <utility>

#include <fmt/format.h>

#include "core/base/errors.h"

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

/// 17 significant digits: every double reads back to the same bits. A
/// missing value (nan) is an empty cell: the file never holds nan or inf
/// (issue 22, item 4).
void append_value(std::string& row, double v) {
  if (!std::isfinite(v)) {
    row += ',';
    return;
  }
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, ",%.17g", v);
  row += buffer;
}

}  // namespace

MonitorLayout::MonitorLayout(const std::vector<const MonitorSource*>& sources) : sources_(sources) {
  struct Ranked {
    Column column;
    int rank;
  };
  std::vector<Ranked> ranked;
  for (int s = 0; s < static_cast<int>(sources_.size()); ++s) {
    first_value_.push_back(n_values_);
    const std::vector<MonitorColumn> columns = sources_[s]->columns();
    for (int v = 0; v < static_cast<int>(columns.size()); ++v) {
      auto same = std::find_if(ranked.begin(), ranked.end(),
                               [&](const Ranked& r) { return r.column.name == columns[v].name; });
      if (same != ranked.end())
        same->column.others.push_back({s, v});
      else
        ranked.push_back({Column{columns[v].name, columns[v].brief, s, v, {}}, columns[v].rank});
    }
    n_values_ += static_cast<int>(columns.size());
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const Ranked& a, const Ranked& b) { return a.rank < b.rank; });
  for (const Ranked& r : ranked) columns_.push_back(r.column);
}

std::vector<double> MonitorLayout::values(const RockMass& state, int point) const {
  std::vector<double> all(n_values_);
  for (int s = 0; s < static_cast<int>(sources_.size()); ++s) {
    const int n = (s + 1 < static_cast<int>(sources_.size()) ? first_value_[s + 1] : n_values_) -
                  first_value_[s];
    sources_[s]->values(state, point, std::span<double>(all).subspan(first_value_[s], n));
  }
  std::vector<double> ordered;
  ordered.reserve(columns_.size());
  for (const Column& c : columns_) {
    double v = all[first_value_[c.source] + c.value];
    for (std::size_t k = 0; k < c.others.size() && std::isnan(v); ++k)
      v = all[first_value_[c.others[k][0]] + c.others[k][1]];
    ordered.push_back(v);
  }
  return ordered;
}

MonitorWriter::MonitorWriter(const std::filesystem::path& file,
                             const std::vector<Monitor>& monitors,
                             const std::vector<const MonitorSource*>& sources, WarningSink warn,
                             std::optional<std::uintmax_t> resume_at)
    : file_(file), layout_(sources), warn_(std::move(warn)) {
  if (!warn_)
    warn_ = [](const std::string& message) {
      std::fprintf(stderr, "warning: %s\n", message.c_str());
      std::fflush(stderr);
    };
  for (const Monitor& m : monitors) names_.push_back(m.name);
  warned_.assign(names_.size() * layout_.columns().size(), false);
  std::string header = "t";
  for (const std::string& name : names_)
    for (const MonitorLayout::Column& column : layout_.columns()) {
      header += ',';
      header += csv_field(name + "." + column.name);
    }
  if (resume_at) {
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(file, ec);
    std::string first_line;
    std::ifstream in(file);
    std::getline(in, first_line);
    FISSURE_CHECK(!ec && size >= *resume_at && first_line == header, IoError,
                  file.string() << ": not the monitors of the checkpointed run ("
                                << (ec                  ? "missing"
                                    : size < *resume_at ? "shorter than at the checkpoint"
                                                        : "other columns")
                                << ")");
    std::filesystem::resize_file(file, *resume_at);
    out_.open(file, std::ios::out | std::ios::app);
    FISSURE_CHECK(out_.is_open(), IoError,
                  file.string() << ": cannot open the file (" << std::strerror(errno) << ")");
    return;
  }
  out_.open(file, std::ios::out | std::ios::trunc);
  FISSURE_CHECK(out_.is_open(), IoError,
                file.string() << ": cannot create the file (" << std::strerror(errno) << ")");
  out_ << header << '\n' << std::flush;
  FISSURE_CHECK(out_.good(), IoError, file.string() << ": cannot write the header");
}

std::uintmax_t MonitorWriter::bytes() const {
  return std::filesystem::file_size(file_);
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
  const std::vector<MonitorLayout::Column>& columns = layout_.columns();
  for (int m = 0; m < n_monitors && !columns.empty(); ++m) {
    const std::vector<double> values = layout_.values(state, m);
    for (std::size_t c = 0; c < columns.size(); ++c) {
      append_value(row, values[c]);
      if (!std::isnan(values[c]) || warned_[m * columns.size() + c]) continue;
      warned_[m * columns.size() + c] = true;
      // Why, from every process that watches it ("is outside the
      // continuum's domain and is not on the fracture network (...)").
      std::string why = layout_.source(columns[c].source).why_missing(state, m, columns[c].name);
      for (const auto& [source, value] : columns[c].others) {
        const std::string more = layout_.source(source).why_missing(state, m, columns[c].name);
        if (!more.empty()) why += (why.empty() ? "" : " and ") + more;
      }
      if (why.empty()) continue;
      const Vec2& x = state.points[m].current;
      warn_(fmt::format("{}: monitor '{}' at ({:g}, {:g}) m {}: its column {}.{} is nan",
                        file_.string(), names_[m], x.x(), x.y(), why, names_[m], columns[c].name));
    }
  }
  row += '\n';
  // Flushed row by row so that a run that dies keeps every row written.
  out_ << row << std::flush;
  FISSURE_CHECK(out_.good(), IoError,
                file_.string() << ": cannot write the row at t = " << t << " s");
}

}  // namespace fissure
