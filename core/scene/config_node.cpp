#include "core/scene/config_node.h"

#include <fmt/format.h>
#include <cmath>

#include "core/scene/closest_match.h"

namespace fissure {

std::string ConfigNode::located_path() const {
  return fmt::format("{}:{}:{}: {}", location_.file, location_.line, location_.column, path_);
}

namespace {

/// Where node `i` starts; `fallback` for an empty value, which has no text.
SourceLocation location_of(const YamlDocument* document, YamlDocument::Index i,
                           const std::string& file, const SourceLocation& fallback) {
  if (i == YamlDocument::kNone || document->kind(i) == YamlDocument::Kind::null) return fallback;
  const YamlDocument::Mark mark = document->mark(i);
  if (mark.line < 0) return fallback;
  return {file, mark.line + 1, mark.column + 1};
}

std::string join(std::span<const std::string_view> words) {
  std::string s;
  for (std::string_view w : words) {
    if (!s.empty()) s += ", ";
    s += w;
  }
  return s;
}

std::string format_bound(double x, const QuantityKind& kind) {
  return fmt::format("{:.6g}", x / kind.plain_scale);
}

}  // namespace

// --- Range -------------------------------------------------------------------

bool Range::contains(double x) const {
  const bool above = lo_open ? x > lo : x >= lo;
  const bool below = hi_open ? x < hi : x <= hi;
  return above && below;
}

std::string Range::describe(const QuantityKind& kind) const {
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  std::string s;
  if (has_lo && has_hi)
    s = fmt::format("in {}{}, {}{}", lo_open ? "(" : "[", format_bound(lo, kind),
                    format_bound(hi, kind), hi_open ? ")" : "]");
  else if (has_lo)
    s = fmt::format("{} {}", lo_open ? ">" : ">=", format_bound(lo, kind));
  else if (has_hi)
    s = fmt::format("{} {}", hi_open ? "<" : "<=", format_bound(hi, kind));
  else
    return s;
  const bool nonzero_bound = (has_lo && lo != 0) || (has_hi && hi != 0);
  if (nonzero_bound && !kind.plain_unit.empty()) {
    s += ' ';
    s += kind.plain_unit;
  }
  return s;
}

std::string expectation(const QuantityKind& kind, const Range& range) {
  const std::string r = range.describe(kind);
  if (r.empty()) return describe(kind);
  QuantityKind name_only = kind;  // "a density", then the range, then the examples
  name_only.examples = {};
  std::string s = describe(name_only) + " " + r;
  if (!kind.examples.empty()) s += " (" + std::string(kind.examples) + ")";
  return s;
}

// --- ConfigNode --------------------------------------------------------------

ConfigNode ConfigNode::root(std::shared_ptr<const YamlDocument> document,
                            Diagnostics& diagnostics) {
  const SourceLocation start{diagnostics.file_name(), 1, 1};
  const YamlDocument::Index i = document ? document->root() : YamlDocument::kNone;
  const SourceLocation where = location_of(document.get(), i, diagnostics.file_name(), start);
  return ConfigNode(std::move(document), i, "", where, where, &diagnostics);
}

ConfigNode ConfigNode::absent(std::string path, const SourceLocation& at,
                              Diagnostics& diagnostics) {
  return ConfigNode(nullptr, YamlDocument::kNone, std::move(path), at, at, &diagnostics);
}

ConfigNode ConfigNode::child(YamlDocument::Index index, std::string path,
                             const SourceLocation& key_location) const {
  return ConfigNode(document_, index, std::move(path),
                    location_of(document_.get(), index, diagnostics_->file_name(), key_location),
                    key_location, diagnostics_);
}

ConfigNode ConfigNode::item(std::size_t i) const {
  ConfigNode item = child(document_->item(index_, i), fmt::format("{}[{}]", path_, i), location_);
  item.key_location_ = item.location_;
  return item;
}

std::string_view ConfigNode::text() const {
  return is_scalar() ? document_->text(index_) : std::string_view();
}

std::size_t ConfigNode::entries() const {
  return is_map() ? document_->size(index_) : 0;
}

SourceLocation ConfigNode::key_at(std::size_t k) const {
  // yaml-cpp's mark, even for an empty key (`: 1`), which has one.
  const YamlDocument::Mark mark = document_->mark(document_->key(index_, k));
  return {diagnostics_->file_name(), mark.line + 1, mark.column + 1};
}

ConfigNode ConfigNode::key(std::size_t k) const {
  return child(document_->key(index_, k), path_, key_at(k));
}

ConfigNode ConfigNode::value(std::size_t k, std::string path) const {
  return child(document_->value(index_, k), std::move(path), key_at(k));
}

void ConfigNode::error(std::string_view message) const {
  diagnostics_->error(location_, path_, message);
}

void ConfigNode::error_at_key(std::string_view message) const {
  diagnostics_->error(key_location_, path_, message);
}

std::string ConfigNode::found() const {
  if (is_null()) return "an empty value";
  if (is_map()) return size() == 0 ? "an empty map" : "a map";
  if (is_list()) {
    const size_t n = size();
    return n == 0 ? "an empty list" : fmt::format("a list of {} value{}", n, n == 1 ? "" : "s");
  }
  if (text().empty()) return "an empty string";
  return fmt::format("'{}'", shorten(text()));
}

std::optional<double> ConfigNode::quantity(const QuantityKind& kind, const Range& range) const {
  if (!is_scalar() || text().empty()) {
    error("found " + found() + "; expected " + expectation(kind, range));
    return std::nullopt;
  }
  double value = 0;
  try {
    value = to_si(text(), kind);
  } catch (const UnitError& e) {
    error(e.what());
    return std::nullopt;
  }
  if (!range.contains(value)) {
    error("found " + found() + "; expected " + expectation(kind, range));
    return std::nullopt;
  }
  if (value != 0 && std::abs(value) < kSmallestMagnitude) {
    error(
        fmt::format("found {}; expected {}, of magnitude at least {:g} (SI) or 0 (smaller is "
                    "outside physics; docs/scene-reference.md, \"Limits\")",
                    found(), expectation(kind, range), kSmallestMagnitude));
    return std::nullopt;
  }
  if (std::abs(value) > kind.largest) {
    QuantityKind name_only = kind;
    name_only.examples = {};
    error(
        fmt::format("found {}; expected {} of magnitude at most {:g}{}{} (larger is outside "
                    "physics; docs/scene-reference.md, \"Limits\")",
                    found(), describe(name_only), kind.largest / kind.plain_scale,
                    kind.plain_unit.empty() ? "" : " ", kind.plain_unit));
    return std::nullopt;
  }
  return value;
}

std::optional<long> ConfigNode::integer(long min, long max) const {
  // A bound at the limit of the integer type is no bound for the reader.
  const std::string expected = max >= std::numeric_limits<int>::max()
                                   ? fmt::format("an integer >= {}", min)
                                   : fmt::format("an integer in [{}, {}]", min, max);
  if (!is_scalar() || text().empty()) {
    error("found " + found() + "; expected " + expected);
    return std::nullopt;
  }
  double value = 0;
  try {
    value = to_si(text(), quantity::dimensionless);
  } catch (const UnitError&) {
    error("found " + found() + ", which is not a number; expected " + expected);
    return std::nullopt;
  }
  if (value != std::floor(value)) {
    error("found " + found() + ", which is not an integer; expected " + expected);
    return std::nullopt;
  }
  // From 2^63 on a double does not fit a long (the conversion would be
  // undefined; LONG_MAX itself converts to 2^63, so `max` does not catch it).
  if (value >= 0x1p63 || value < -0x1p63) {
    error("found " + found() + ", which is out of the range of integers; expected " + expected);
    return std::nullopt;
  }
  if (value < static_cast<double>(min) || value > static_cast<double>(max)) {
    error("found " + found() + "; expected " + expected);
    return std::nullopt;
  }
  return static_cast<long>(value);
}

std::optional<bool> ConfigNode::boolean() const {
  if (is_scalar()) {
    const std::string_view s = text();
    if (s == "true" || s == "True" || s == "TRUE") return true;
    if (s == "false" || s == "False" || s == "FALSE") return false;
  }
  error("found " + found() + "; expected true or false");
  return std::nullopt;
}

std::optional<std::string> ConfigNode::string(std::string_view what) const {
  if (!is_scalar() || text().empty()) {
    error("found " + found() + "; expected " + std::string(what));
    return std::nullopt;
  }
  return std::string(text());
}

std::optional<std::string> ConfigNode::choice(std::span<const std::string_view> options) const {
  const std::string expected = "one of: " + join(options);
  std::optional<std::string> s = string(expected);
  if (!s) return std::nullopt;
  for (std::string_view o : options)
    if (*s == o) return s;
  std::string message = "found " + found();
  if (const auto m = closest_match(*s, options)) message += " (did you mean '" + *m + "'?)";
  error(message + "; expected " + expected);
  return std::nullopt;
}

std::optional<ConfigList> ConfigNode::list(std::string_view items_name, bool non_empty) const {
  if (is_null() && !non_empty) return ConfigList(*this);
  if (!is_list() || (non_empty && size() == 0)) {
    error("found " + found() + "; expected " + (non_empty ? "a non-empty list of " : "a list of ") +
          std::string(items_name));
    return std::nullopt;
  }
  return ConfigList(*this);
}

std::optional<std::vector<double>> ConfigNode::numbers(std::span<const QuantityKind* const> kinds,
                                                       std::string_view components) const {
  if (!is_list() || size() != kinds.size()) {
    std::string kinds_text;
    bool same = true;
    for (const QuantityKind* k : kinds) same = same && k == kinds.front();
    kinds_text = same ? std::string(kinds.front()->name) + "s" : "values";
    error(fmt::format("found {}; expected a list of {} {} {}", found(), kinds.size(), kinds_text,
                      components));
    return std::nullopt;
  }
  std::vector<double> values;
  bool ok = true;
  for (size_t i = 0; i < kinds.size(); ++i) {
    const std::optional<double> v =
        child(document_->item(index_, i), fmt::format("{}[{}]", path_, i), location_)
            .quantity(*kinds[i]);
    ok = ok && v.has_value();
    values.push_back(v.value_or(0));
  }
  if (!ok) return std::nullopt;
  return values;
}

std::optional<Vec2> ConfigNode::vec2(const QuantityKind& kind) const {
  const QuantityKind* kinds[] = {&kind, &kind};
  const std::optional<std::vector<double>> v = numbers(kinds, "[x, y]");
  if (!v) return std::nullopt;
  return Vec2((*v)[0], (*v)[1]);
}

std::optional<std::vector<Vec2>> ConfigNode::points(const QuantityKind& kind,
                                                    bool non_empty) const {
  const std::optional<ConfigList> items = list("vertices [x, y]", non_empty);
  if (!items) return std::nullopt;
  std::vector<Vec2> out;
  bool ok = true;
  for (const ConfigNode& item : *items) {
    if (std::optional<Vec2> p = item.vec2(kind))
      out.push_back(*p);
    else
      ok = false;
  }
  if (!ok) return std::nullopt;
  return out;
}

}  // namespace fissure
