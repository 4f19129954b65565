// Collects the problems found in a scene file so that all of them are
// reported together (docs/architecture.md 3). Each reads
//   FILE:LINE:COLUMN: KEY.PATH: what was found; expected WHAT
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/scene/scene.h"  // SourceLocation

namespace fissure {

/// Text from the scene shown in a message: at most `max_length` characters
/// (then "..."), so that a stray multi-line value stays readable.
std::string shorten(std::string_view text, size_t max_length = 60);

class Diagnostics {
 public:
  explicit Diagnostics(std::string file_name) : file_name_(std::move(file_name)) {}

  const std::string& file_name() const { return file_name_; }

  /// Records one problem; `key_path` empty means the whole document. Line
  /// breaks and other control characters are escaped, so that each problem
  /// stays on one line.
  void error(const SourceLocation& where, std::string_view key_path, std::string_view message);
  /// Records a warning (a deprecated key): reported, but the scene is valid.
  void warning(const SourceLocation& where, std::string_view key_path, std::string_view message);

  bool empty() const { return entries_.empty(); }
  /// The problems recorded (kept or only counted).
  size_t size() const { return entries_.size() + counted_only_; }

  /// All problems, one per line, ordered by position in the file (the order
  /// they were found in for equal positions); repeated lines are dropped. A
  /// flood is summarized: of problems that differ only in their list
  /// indices, numbers and place (10,000 copies of one block), the first
  /// kShownOfAKind are shown and one line counts the rest; beyond
  /// kShownInAll lines, one line counts what is left.
  std::string text() const;
  static constexpr std::size_t kShownOfAKind = 3;
  static constexpr std::size_t kShownInAll = 100;

  /// Throws SceneError with text() when there is any problem.
  void throw_if_any() const;

  /// The warnings, one line each, ordered by position in the file.
  std::vector<std::string> warnings() const;

  /// Keys that moved (config_map.h, MovedKey): their old documented path and
  /// the new one, for the unknown-key message of an old scene.
  void add_moved_key(std::string_view from, std::string_view to);
  /// The new path of a key whose old documented path is `from`; empty if it
  /// did not move.
  std::string_view moved_to(std::string_view from) const;

 private:
  struct Entry {
    int line = 0;
    int column = 0;
    std::string text;
    std::string kind;  ///< key path without its list indices, and the message without its numbers
  };
  Entry entry(const SourceLocation& where, std::string_view key_path,
              std::string_view message) const;
  /// By position in the file (in the order found for equal positions),
  /// without repeated lines.
  static std::vector<Entry> ordered(std::vector<Entry> entries);

  /// Per kind of problem, all that were recorded: only the first
  /// kKeptOfAKind of a kind, and kKeptInAll in all, are kept whole; the
  /// rest are counted (2 million "expected strictly increasing times" of a
  /// 47 MB history took 2.5 GB kept whole).
  struct KindCount {
    std::size_t count = 0, kept = 0;
    int last_line = 0;
  };
  static constexpr std::size_t kKeptOfAKind = 16;
  static constexpr std::size_t kKeptInAll = 4096;

  std::string file_name_;
  std::vector<Entry> entries_;
  std::map<std::string, KindCount> kinds_;
  std::size_t counted_only_ = 0;
  std::vector<Entry> warnings_;
  std::vector<std::pair<std::string, std::string>> moved_keys_;
};

}  // namespace fissure
