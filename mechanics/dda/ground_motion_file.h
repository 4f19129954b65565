// Reading a ground-motion record (docs/dda.md section 10, "Record files"):
//  * csv:      a header line naming the columns, then rows of numbers
//              separated by commas; the first column is the time (s);
//  * columns:  whitespace- or comma-separated numbers, `#` starts a comment;
//              the first column is the time (s) (the two- and three-column
//              text files of most strong-motion archives and of ntdda);
//  * peer_at2: the PEER NGA format, one component per file: three lines of
//              text, a fourth with NPTS and DT ("NPTS=  5590, DT=   .0050
//              SEC" or the older "5590 .0050"), then NPTS values, any number
//              per line.
// Every problem is thrown with the file, line and column where it is.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/base/errors.h"
#include "core/scene/scene.h"
#include "mechanics/dda/ground_motion.h"

namespace fissure::dda {

/// A problem in a record file, where it is.
class RecordFileError : public Error {
 public:
  RecordFileError(SourceLocation where, const std::string& message)
      : Error(message), where_(std::move(where)) {}
  const SourceLocation& where() const { return where_; }

 private:
  SourceLocation where_;
};

enum class RecordFormat { Csv, Columns, PeerAt2 };
/// Their names in the scene (`format`).
inline constexpr EnumName<RecordFormat> kRecordFormatNames[] = {
    {"csv", RecordFormat::Csv},
    {"columns", RecordFormat::Columns},
    {"peer_at2", RecordFormat::PeerAt2}};

/// A column of a csv or columns file: by its header name (csv) or 1-based
/// number (>= 2: column 1 is the time; 0 for the default column); `none`
/// for no column (the vertical only).
struct RecordColumn {
  std::string name;
  int number = 0;
  bool none = false;
};

/// Times (as written) and one or two components (as written, unscaled).
struct RecordColumns {
  std::vector<double> time;
  std::vector<double> x, y;  ///< y empty: no vertical component
};

/// The format a file name suggests: .csv; PEER's .at2, .vt2, .dt2 (any
/// case); else columns.
RecordFormat format_of(const std::filesystem::path& file);
/// What a PEER file's name says it holds (.vt2 velocity, .dt2 displacement);
/// acceleration for any other name.
MotionQuantity quantity_of(const std::filesystem::path& file);

/// Reads `x` and `y` (and the time) of a csv or columns file. A column left
/// at its default (number 0) is the second (x) or the third, when present
/// (y). Times must increase strictly from >= 0, every value be finite.
RecordColumns read_record_columns(const std::filesystem::path& file, RecordFormat format,
                                  const RecordColumn& x, const RecordColumn& y);

/// The samples of a PEER AT2 file, at times 0, DT, 2 DT, ...
RecordColumns read_peer_at2(const std::filesystem::path& file);

}  // namespace fissure::dda
