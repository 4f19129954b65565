// Tracked reading of a YAML scene (after OpenGeoSys' ConfigTree).
//
// A ConfigNode is a YAML node that knows its key path ("blocks[2].vertices")
// and where it sits in the file. Its typed reads check the YAML type, the unit
// and the range, and on a problem record a diagnostic and return nothing, so
// that reading goes on and every problem is reported. A ConfigMap (config_map.h)
// reads the keys of a map and reports the keys nobody read.
#pragma once

#include <yaml-cpp/yaml.h>
#include <Eigen/Core>
#include <climits>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/geometry/vec2.h"
#include "core/scene/diagnostics.h"
#include "core/scene/units.h"

namespace fissure {

/// An interval of allowed values, in SI units. Bounds are open or closed.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  static Range any() { return {}; }
  static Range positive() { return {0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range non_negative() { return {0, std::numeric_limits<double>::infinity(), false, false}; }
  /// (lo, hi), [lo, hi], [lo, hi), (lo, hi]
  static Range open(double lo, double hi) { return {lo, hi, true, true}; }
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  static Range closed_open(double lo, double hi) { return {lo, hi, false, true}; }
  static Range open_closed(double lo, double hi) { return {lo, hi, true, false}; }

  bool contains(double x) const;
  /// "> 0", ">= 1", "in (-1, 0.5)", in the unit of a plain number of `kind`
  /// (degrees for angles); empty for any().
  std::string describe(const QuantityKind& kind) const;
};

/// What a key expects, for messages: "a density > 0 (kg/m^3, g/cm^3, t/m^3)".
std::string expectation(const QuantityKind& kind, const Range& range);

class ConfigNode {
 public:
  /// The document root; `node` may be null (an empty file).
  static ConfigNode root(const YAML::Node& node, Diagnostics& diagnostics);

  /// A node below this one: `path` is its full key path, `key_location` where
  /// its key (or list item) starts.
  ConfigNode child(const YAML::Node& node, std::string path,
                   const SourceLocation& key_location) const;

  const std::string& path() const { return path_; }
  /// Where the value starts (where its key is, for an empty value).
  const SourceLocation& location() const { return location_; }
  /// Where its key is (the value's location for list items and the root).
  const SourceLocation& key_location() const { return key_location_; }
  /// "file:line:column: path" of the value, for messages given after the
  /// scene is read (a run-time check that names the scene line).
  std::string located_path() const;
  const YAML::Node& yaml() const { return node_; }
  Diagnostics& diagnostics() const { return *diagnostics_; }

  bool is_null() const { return !node_.IsDefined() || node_.IsNull(); }
  bool is_map() const { return node_.IsMap(); }
  bool is_list() const { return node_.IsSequence(); }
  bool is_scalar() const { return node_.IsScalar(); }

  /// Records a problem here; `message` reads "what was found; expected what".
  void error(std::string_view message) const;
  /// Same, at the key rather than the value.
  void error_at_key(std::string_view message) const;

  /// How the value looks, for messages: "'2650 kg/m^3'", "a map", "a list of
  /// 3 values", "an empty value".
  std::string found() const;

  // Typed reads. Each checks the YAML type (and unit and range), records a
  // diagnostic and returns nothing on a problem.

  /// A quantity in SI units (a number, or "NUMBER UNIT").
  std::optional<double> quantity(const QuantityKind& kind, const Range& range = {}) const;
  /// An integer in [min, max] (an integral number such as 100000 or 1e5).
  std::optional<long> integer(long min, long max = LONG_MAX) const;
  /// true or false.
  std::optional<bool> boolean() const;
  /// A non-empty scalar; `what` names it in messages ("a material name").
  std::optional<std::string> string(std::string_view what) const;
  /// One of `options`, with a suggestion when the text is close to one.
  std::optional<std::string> choice(std::span<const std::string_view> options) const;
  /// The items of a list; an empty value counts as an empty list unless
  /// `non_empty`. `items_name` names the items in messages ("materials").
  std::optional<std::vector<ConfigNode>> list(std::string_view items_name, bool non_empty) const;
  /// A list of exactly kinds.size() quantities; `components` names them for
  /// messages ("[x, y]"). Items are checked one by one.
  std::optional<std::vector<double>> numbers(std::span<const QuantityKind* const> kinds,
                                             std::string_view components) const;
  std::optional<Vec2> vec2(const QuantityKind& kind) const;
  /// A list of points [x, y] (polygon vertices); nothing if any point is
  /// invalid (each one is reported). `non_empty` as for list().
  std::optional<std::vector<Vec2>> points(const QuantityKind& kind, bool non_empty) const;

 private:
  ConfigNode(YAML::Node node, std::string path, SourceLocation location,
             SourceLocation key_location, Diagnostics* diagnostics)
      : node_(std::move(node)),
        path_(std::move(path)),
        location_(std::move(location)),
        key_location_(std::move(key_location)),
        diagnostics_(diagnostics) {}

  YAML::Node node_;
  std::string path_;
  SourceLocation location_;
  SourceLocation key_location_;
  Diagnostics* diagnostics_;
};

}  // namespace fissure
