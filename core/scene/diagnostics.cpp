#include "core/scene/diagnostics.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "core/base/errors.h"

namespace fissure {

namespace {

std::string escape_controls(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '\n')
      out += "\\n";
    else if (c == '\r')
      out += "\\r";
    else if (c == '\t')
      out += "\\t";
    else if (static_cast<unsigned char>(c) < 0x20)
      out += '?';
    else
      out += c;
  }
  return out;
}

/// "blocks[12].vertices[3]" -> "blocks[].vertices[]".
std::string without_indices(std::string_view path) {
  std::string out;
  bool in_index = false;
  for (const char c : path) {
    if (c == '[') in_index = true;
    if (c == ']') in_index = false;
    if (!in_index || c == '[') out += c;
  }
  return out;
}

/// The message with every run of digits outside quotes as '#': problems
/// that differ only in their numbers ("found t = 10003.3 s after t =
/// 10003.3 s", two million times in a history) are one kind; quoted names
/// ('copy12') still tell problems apart.
std::string without_numbers(std::string_view message) {
  std::string out;
  bool quoted = false;
  for (std::size_t i = 0; i < message.size(); ++i) {
    const char c = message[i];
    if (c == '\'') quoted = !quoted;
    const bool digit = !quoted && std::isdigit(static_cast<unsigned char>(c)) != 0;
    if (!digit)
      out += c;
    else if (i == 0 || !std::isdigit(static_cast<unsigned char>(message[i - 1])))
      out += '#';
  }
  return out;
}

}  // namespace

std::string shorten(std::string_view text, size_t max_length) {
  if (text.size() <= max_length) return std::string(text);
  return std::string(text.substr(0, max_length)) + "...";
}

Diagnostics::Entry Diagnostics::entry(const SourceLocation& where, std::string_view key_path,
                                      std::string_view message) const {
  Entry e;
  e.line = where.line;
  e.column = where.column;
  e.text = escape_controls(file_name_ + ":" + std::to_string(where.line) + ":" +
                           std::to_string(where.column) + ": " +
                           (key_path.empty() ? std::string("(document)") : std::string(key_path)) +
                           ": " + std::string(message));
  e.kind = without_indices(key_path) + ": " + without_numbers(message);
  return e;
}

void Diagnostics::error(const SourceLocation& where, std::string_view key_path,
                        std::string_view message) {
  Entry e = entry(where, key_path, message);
  KindCount& k = kinds_[e.kind];
  ++k.count;
  k.last_line = std::max(k.last_line, e.line);
  if (k.kept < kKeptOfAKind && entries_.size() < kKeptInAll) {
    ++k.kept;
    entries_.push_back(std::move(e));
  } else {
    ++counted_only_;
  }
}

void Diagnostics::warning(const SourceLocation& where, std::string_view key_path,
                          std::string_view message) {
  warnings_.push_back(entry(where, key_path, message));
}

std::vector<Diagnostics::Entry> Diagnostics::ordered(std::vector<Entry> entries) {
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
  std::vector<Entry> unique;
  std::set<std::string> seen;
  for (Entry& e : entries)
    if (seen.insert(e.text).second) unique.push_back(std::move(e));
  return unique;
}

std::string Diagnostics::text() const {
  const std::vector<Entry> entries = ordered(entries_);
  struct Kind {
    std::size_t count = 0, shown = 0;
    int last_line = 0;
  };
  std::map<std::string_view, Kind> kinds;
  for (const Entry& e : entries) {
    Kind& k = kinds[e.kind];
    ++k.count;
    k.last_line = std::max(k.last_line, e.line);
  }
  // The problems only counted join their kind (those of a kind with none
  // kept are in the last line's count).
  for (const auto& [name, all] : kinds_) {
    if (const auto it = kinds.find(name); it != kinds.end()) {
      it->second.count += all.count - all.kept;
      it->second.last_line = std::max(it->second.last_line, all.last_line);
    }
  }
  const std::size_t total = entries.size() + counted_only_;
  std::string out;
  std::size_t shown = 0, covered = 0;  // covered: shown, or counted by a kind's line
  auto add = [&out](const std::string& line) { out += (out.empty() ? "" : "\n") + line; };
  for (const Entry& e : entries) {
    Kind& k = kinds[e.kind];
    if (k.shown >= kShownOfAKind) continue;  // counted by the line after the kind's last shown
    if (shown == kShownInAll) break;
    add(e.text);
    ++shown;
    ++covered;
    if (++k.shown == kShownOfAKind && k.count > kShownOfAKind) {
      add(fmt::format("  ... and {} more problems like the one above, up to line {}",
                      k.count - kShownOfAKind, k.last_line));
      covered += k.count - kShownOfAKind;
    }
  }
  if (total > covered)
    add(fmt::format("  ... and {} more problems (the first {} are shown)", total - covered,
                    kShownInAll));
  return out;
}

std::vector<std::string> Diagnostics::warnings() const {
  std::vector<std::string> lines;
  for (Entry& e : ordered(warnings_)) lines.push_back(std::move(e.text));
  return lines;
}

void Diagnostics::throw_if_any() const {
  if (!empty()) throw SceneError(text());
}

void Diagnostics::add_moved_key(std::string_view from, std::string_view to) {
  moved_keys_.emplace_back(from, to);
}

std::string_view Diagnostics::moved_to(std::string_view from) const {
  for (const auto& [old_path, new_path] : moved_keys_)
    if (old_path == from) return new_path;
  return {};
}

}  // namespace fissure
