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

void Diagnostics::error(const SourceLocation& where, std::string_view key_path,
                        std::string_view message) {
  Entry e;
  e.line = where.line;
  e.column = where.column;
  e.text = escape_controls(file_name_ + ":" + std::to_string(where.line) + ":" +
                           std::to_string(where.column) + ": " +
                           (key_path.empty() ? std::string("(document)") : std::string(key_path)) +
                           ": " + std::string(message));
  entries_.push_back(std::move(e));
}

std::string Diagnostics::text() const {
  std::vector<Entry> sorted = entries_;
  std::stable_sort(sorted.begin(), sorted.end(), [](const Entry& a, const Entry& b) {
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
  std::string out;
  std::set<std::string_view> seen;
  for (const Entry& e : sorted) {
    if (!seen.insert(e.text).second) continue;
    if (!out.empty()) out += '\n';
    out += e.text;
  }
  return out;
}

void Diagnostics::throw_if_any() const {
  if (!empty()) throw SceneError(text());
}

}  // namespace fissure
