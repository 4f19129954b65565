#include "mechanics/dda/ground_motion_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <regex>
#include <string_view>

#include <fmt/format.h>

#include "core/scene/parse_scene.h"  // read_input_file

namespace fissure::dda {

namespace {

/// A field of a line and the 1-based column where it starts.
struct Field {
  std::string_view text;
  int column = 1;
};

/// The fields of `line` separated by any of `separators` (blanks around
/// them trimmed); with `keep_empty` an empty field between two commas counts.
std::vector<Field> split(std::string_view line, std::string_view separators, bool keep_empty) {
  std::vector<Field> fields;
  std::size_t pos = 0;
  while (pos <= line.size()) {
    std::size_t end = line.find_first_of(separators, pos);
    if (end == std::string_view::npos) end = line.size();
    std::size_t a = pos, b = end;
    while (a < b && std::isspace(static_cast<unsigned char>(line[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(line[b - 1]))) --b;
    if (b > a || keep_empty) fields.push_back({line.substr(a, b - a), static_cast<int>(a) + 1});
    pos = end + 1;
  }
  return fields;
}

class Lines {
 public:
  Lines(const std::filesystem::path& file, std::string_view what)
      : file_(file.string()), text_(read_input_file(file, what)) {}

  /// The next line (without its end), or nothing at the end of the file.
  std::optional<std::string_view> next() {
    if (pos_ >= text_.size()) return std::nullopt;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string::npos) end = text_.size();
    std::string_view line(text_.data() + pos_, end - pos_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos_ = end + 1;
    ++line_;
    return line;
  }
  int line() const { return line_; }
  [[noreturn]] void fail(int column, const std::string& message) const {
    throw RecordFileError({file_, line_, column}, message);
  }
  /// The number in `f`, finite, or a located error.
  double number(const Field& f, std::string_view what) const {
    const std::string text(f.text);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size())
      fail(f.column, fmt::format("found '{}'; expected {} (a number)", text, what));
    if (!std::isfinite(value))
      fail(f.column, fmt::format("found '{}'; expected {} (a finite number)", text, what));
    return value;
  }

 private:
  std::string file_;
  std::string text_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

/// A line with nothing but blanks or a comment.
bool blank(std::string_view line) {
  const auto first = line.find_first_not_of(" \t");
  return first == std::string_view::npos || line[first] == '#';
}

/// Adds a time, checking that times increase strictly from >= 0.
void add_time(RecordColumns& r, double t, const Lines& lines, int column) {
  if (r.time.empty() && t < 0)
    lines.fail(column, fmt::format("found the time {:g} s; expected a record that starts at a "
                                   "time >= 0 (the record's t = 0 is the scene time `start`)",
                                   t));
  if (!r.time.empty() && !(t > r.time.back()))
    lines.fail(column, fmt::format("found the time {:g} s after {:g} s; expected times that "
                                   "increase strictly",
                                   t, r.time.back()));
  r.time.push_back(t);
}

std::string lower_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}
}  // namespace

RecordFormat format_of(const std::filesystem::path& file) {
  const std::string ext = lower_extension(file);
  if (ext == ".csv") return RecordFormat::Csv;
  if (ext == ".at2" || ext == ".vt2" || ext == ".dt2") return RecordFormat::PeerAt2;
  return RecordFormat::Columns;
}

MotionQuantity quantity_of(const std::filesystem::path& file) {
  const std::string ext = lower_extension(file);
  return ext == ".vt2"   ? MotionQuantity::Velocity
         : ext == ".dt2" ? MotionQuantity::Displacement
                         : MotionQuantity::Acceleration;
}

RecordColumns read_record_columns(const std::filesystem::path& file, RecordFormat format,
                                  const RecordColumn& x, const RecordColumn& y) {
  const bool csv = format == RecordFormat::Csv;
  Lines lines(file, csv ? "a ground-motion record (csv)" : "a ground-motion record (columns)");
  std::vector<std::string> header;
  int header_line = 0;
  RecordColumns r;
  int n_columns = 0, x_index = -1, y_index = -1;
  // The index of a chosen column (or -1), once the count is known.
  const auto resolve = [&](const RecordColumn& c, int fallback, bool required,
                           std::string_view which) {
    if (c.none) return -1;
    if (!c.name.empty()) {
      const auto at = std::find(header.begin(), header.end(), c.name);
      if (at == header.end())
        throw RecordFileError(
            {file.string(), header_line, 1},
            fmt::format("found no column '{}' in the header ({}); expected the {} column's name",
                        c.name, fmt::join(header, ", "), which));
      return static_cast<int>(at - header.begin());
    }
    const int number = c.number > 0 ? c.number : fallback;
    if (number > n_columns) {
      if (!required && c.number == 0) return -1;
      lines.fail(1, fmt::format("found {} columns; expected at least {} (the time and the {} "
                                "component in column {})",
                                n_columns, number, which, number));
    }
    return number - 1;
  };
  while (auto line = lines.next()) {
    if (!csv) line = line->substr(0, line->find('#'));  // a comment to the line's end
    if (blank(*line)) continue;
    const std::vector<Field> fields = split(*line, csv ? "," : ", \t", csv);
    if (csv && header.empty()) {
      for (const Field& f : fields) header.emplace_back(f.text);
      header_line = lines.line();
      n_columns = static_cast<int>(header.size());
      continue;
    }
    if (n_columns == 0) n_columns = static_cast<int>(fields.size());
    if (r.time.empty()) {  // the first row: the column count is known
      x_index = resolve(x, 2, true, "horizontal (x)");
      y_index = resolve(y, 3, false, "vertical (y)");
    }
    if (static_cast<int>(fields.size()) != n_columns)
      lines.fail(1, fmt::format("found {} values; expected {} as in {}", fields.size(), n_columns,
                                csv ? "the header" : "the first row"));
    add_time(r, lines.number(fields[0], "a time (s)"), lines, fields[0].column);
    r.x.push_back(lines.number(fields[x_index], "a value of the record"));
    if (y_index >= 0) r.y.push_back(lines.number(fields[y_index], "a value of the record"));
  }
  if (r.time.size() < 2)
    throw RecordFileError(
        {file.string(), std::max(lines.line(), 1), 1},
        fmt::format("found {} samples; expected a record of at least two", r.time.size()));
  return r;
}

RecordColumns read_peer_at2(const std::filesystem::path& file) {
  Lines lines(file, "a ground-motion record (PEER AT2)");
  for (int k = 0; k < 3; ++k)
    if (!lines.next()) lines.fail(1, "found the end of the file; expected the AT2 header");
  const auto header = lines.next();
  if (!header) lines.fail(1, "found the end of the file; expected the line with NPTS and DT");
  // "NPTS=  5590, DT=   .0050 SEC" (NGA-West2) or "5590  .0050  NPTS, DT" (older).
  static const std::regex kNamed(R"(NPTS\s*=\s*([0-9]+)\s*,?\s*DT\s*=\s*([0-9.eE+-]+))",
                                 std::regex::icase);
  static const std::regex kPlain(R"(^\s*([0-9]+)\s+([0-9.eE+-]+))");
  std::cmatch m;
  const std::string text(*header);
  if (!std::regex_search(text.c_str(), m, kNamed) && !std::regex_search(text.c_str(), m, kPlain))
    lines.fail(
        1, fmt::format("found '{}'; expected NPTS and DT (\"NPTS= 5590, DT= .0050 SEC\")", text));
  const long npts = std::strtol(m[1].str().c_str(), nullptr, 10);
  const double dt = std::strtod(m[2].str().c_str(), nullptr);
  if (!(npts >= 2) || !(dt > 0) || !std::isfinite(dt))
    lines.fail(static_cast<int>(m.position(1)) + 1,
               fmt::format("found NPTS = {} and DT = {:g}; expected at least two points and "
                           "DT > 0 s",
                           npts, dt));
  RecordColumns r;
  while (const auto line = lines.next()) {
    for (const Field& f : split(*line, " \t,", false)) {
      if (static_cast<long>(r.x.size()) == npts)
        lines.fail(f.column, fmt::format("found more values than NPTS = {}", npts));
      r.x.push_back(lines.number(f, "an acceleration value"));
      r.time.push_back(dt * static_cast<double>(r.time.size()));
    }
  }
  if (static_cast<long>(r.x.size()) != npts)
    throw RecordFileError({file.string(), std::max(lines.line(), 1), 1},
                          fmt::format("found {} values; expected NPTS = {}", r.x.size(), npts));
  return r;
}

}  // namespace fissure::dda
