#include "core/scene/config_node.h"

#include <fmt/format.h>
#include <cmath>

#include "core/scene/closest_match.h"

namespace fissure {

std::string ConfigNode::located_path() const {
  return fmt::format("{}:{}:{}: {}", location_.file, location_.line, location_.column, path_);
}

namespace {

SourceLocation location_of(const YAML::Node& node, const std::string& file,
                           const SourceLocation& fallback) {
  if (!node.IsDefined() || node.IsNull()) return fallback;
  const YAML::Mark mark = node.Mark();
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
  if (nonzero_bound && !kind.plain_unit.empty()) s += " " + std::string(kind.plain_unit);
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

ConfigNode ConfigNode::root(const YAML::Node& node, Diagnostics& diagnostics) {
  const SourceLocation start{diagnostics.file_name(), 1, 1};
  const SourceLocation where = location_of(node, diagnostics.file_name(), start);
  return ConfigNode(node, "", where, where, &diagnostics);
}

ConfigNode ConfigNode::child(const YAML::Node& node, std::string path,
                             const SourceLocation& key_location) const {
  return ConfigNode(node, std::move(path),
                    location_of(node, diagnostics_->file_name(), key_location), key_location,
                    diagnostics_);
}

void ConfigNode::error(std::string_view message) const {
  diagnostics_->error(location_, path_, message);
}

void ConfigNode::error_at_key(std::string_view message) const {
  diagnostics_->error(key_location_, path_, message);
}

std::string ConfigNode::found() const {
  if (is_null()) return "an empty value";
  if (is_map()) return node_.size() == 0 ? "an empty map" : "a map";
  if (is_list()) {
    const size_t n = node_.size();
    return n == 0 ? "an empty list" : fmt::format("a list of {} value{}", n, n == 1 ? "" : "s");
  }
  if (node_.Scalar().empty()) return "an empty string";
  return "'" + shorten(node_.Scalar()) + "'";
}

std::optional<double> ConfigNode::quantity(const QuantityKind& kind, const Range& range) const {
  if (!is_scalar() || node_.Scalar().empty()) {
    error("found " + found() + "; expected " + expectation(kind, range));
    return std::nullopt;
  }
  double value = 0;
  try {
    value = to_si(node_.Scalar(), kind);
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
  if (!is_scalar() || node_.Scalar().empty()) {
    error("found " + found() + "; expected " + expected);
    return std::nullopt;
  }
  double value = 0;
  try {
    value = to_si(node_.Scalar(), quantity::dimensionless);
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
    const std::string& s = node_.Scalar();
    if (s == "true" || s == "True" || s == "TRUE") return true;
    if (s == "false" || s == "False" || s == "FALSE") return false;
  }
  error("found " + found() + "; expected true or false");
  return std::nullopt;
}

std::optional<std::string> ConfigNode::string(std::string_view what) const {
  if (!is_scalar() || node_.Scalar().empty()) {
    error("found " + found() + "; expected " + std::string(what));
    return std::nullopt;
  }
  return node_.Scalar();
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

std::optional<std::vector<ConfigNode>> ConfigNode::list(std::string_view items_name,
                                                        bool non_empty) const {
  const std::string expected =
      (non_empty ? "a non-empty list of " : "a list of ") + std::string(items_name);
  if (is_null() && !non_empty) return std::vector<ConfigNode>{};
  if (!is_list() || (non_empty && node_.size() == 0)) {
    error("found " + found() + "; expected " + expected);
    return std::nullopt;
  }
  std::vector<ConfigNode> items;
  for (size_t i = 0; i < node_.size(); ++i)
    items.push_back(child(node_[i], fmt::format("{}[{}]", path_, i), location_));
  // A list item's key location is the item itself.
  for (ConfigNode& item : items) item.key_location_ = item.location_;
  return items;
}

std::optional<std::vector<double>> ConfigNode::numbers(std::span<const QuantityKind* const> kinds,
                                                       std::string_view components) const {
  if (!is_list() || node_.size() != kinds.size()) {
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
    const ConfigNode item = child(node_[i], fmt::format("{}[{}]", path_, i), location_);
    const std::optional<double> v = item.quantity(*kinds[i]);
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
  const std::optional<std::vector<ConfigNode>> items = list("vertices [x, y]", non_empty);
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
