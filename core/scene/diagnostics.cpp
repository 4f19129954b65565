#include "core/scene/diagnostics.h"

#include <algorithm>
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
  return e;
}

void Diagnostics::error(const SourceLocation& where, std::string_view key_path,
                        std::string_view message) {
  entries_.push_back(entry(where, key_path, message));
}

void Diagnostics::warning(const SourceLocation& where, std::string_view key_path,
                          std::string_view message) {
  warnings_.push_back(entry(where, key_path, message));
}

std::vector<std::string> Diagnostics::ordered(std::vector<Entry> entries) {
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
  std::vector<std::string> lines;
  std::set<std::string> seen;
  for (Entry& e : entries)
    if (seen.insert(e.text).second) lines.push_back(std::move(e.text));
  return lines;
}

std::string Diagnostics::text() const {
  std::string out;
  for (const std::string& line : ordered(entries_)) {
    if (!out.empty()) out += '\n';
    out += line;
  }
  return out;
}

std::vector<std::string> Diagnostics::warnings() const {
  return ordered(warnings_);
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
