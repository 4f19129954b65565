// Tracked reading of a YAML scene (after OpenGeoSys' ConfigTree).
//
// A ConfigNode is a node of a YamlDocument (yaml_document.h) that knows its
// key path ("blocks[2].vertices") and where it sits in the file. Its typed reads check the YAML
// type, the unit and the range, and on a problem record a diagnostic and return nothing, so that
// reading goes on and every problem is reported. A ConfigMap (config_map.h) reads the keys of a map
// and reports the keys nobody read.
#pragma once

#include <Eigen/Core>
#include <climits>
#include <cstddef>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/geometry/vec2.h"
#include "core/scene/diagnostics.h"
#include "core/scene/units.h"
#include "core/scene/yaml_document.h"

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

class ConfigList;

class ConfigNode {
 public:
  /// The document's root; an empty document's is null (an empty file).
  static ConfigNode root(std::shared_ptr<const YamlDocument> document, Diagnostics& diagnostics);
  /// An empty value named `path` at `at`, for messages about what the file
  /// does not hold itself (the blocks a block source generates).
  static ConfigNode absent(std::string path, const SourceLocation& at, Diagnostics& diagnostics);

  const std::string& path() const { return path_; }
  /// Where the value starts (where its key is, for an empty value).
  const SourceLocation& location() const { return location_; }
  /// Where its key is (the value's location for list items and the root).
  const SourceLocation& key_location() const { return key_location_; }
  /// "file:line:column: path" of the value, for messages given after the
  /// scene is read (a run-time check that names the scene line).
  std::string located_path() const;
  Diagnostics& diagnostics() const { return *diagnostics_; }

  bool is_null() const {
    return index_ == YamlDocument::kNone || kind() == YamlDocument::Kind::null;
  }
  bool is_map() const { return kind() == YamlDocument::Kind::map; }
  bool is_list() const { return kind() == YamlDocument::Kind::sequence; }
  bool is_scalar() const { return kind() == YamlDocument::Kind::scalar; }
  /// A scalar's text as written (unquoted); empty for other nodes.
  std::string_view text() const;

  /// A map's entries, in file order (a key given twice is there twice);
  /// 0 for other nodes.
  std::size_t entries() const;
  /// The key of entry `k`, as a node at the key, with this node's path.
  ConfigNode key(std::size_t k) const;
  /// The value of entry `k`, with path `path` and its key's location.
  ConfigNode value(std::size_t k, std::string path) const;

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
  std::optional<ConfigList> list(std::string_view items_name, bool non_empty) const;
  /// A list of exactly kinds.size() quantities; `components` names them for
  /// messages ("[x, y]"). Items are checked one by one.
  std::optional<std::vector<double>> numbers(std::span<const QuantityKind* const> kinds,
                                             std::string_view components) const;
  std::optional<Vec2> vec2(const QuantityKind& kind) const;
  /// A list of points [x, y] (polygon vertices); nothing if any point is
  /// invalid (each one is reported). `non_empty` as for list().
  std::optional<std::vector<Vec2>> points(const QuantityKind& kind, bool non_empty) const;

 private:
  friend class ConfigList;

  ConfigNode(std::shared_ptr<const YamlDocument> document, YamlDocument::Index index,
             std::string path, SourceLocation location, SourceLocation key_location,
             Diagnostics* diagnostics)
      : document_(std::move(document)),
        index_(index),
        path_(std::move(path)),
        location_(std::move(location)),
        key_location_(std::move(key_location)),
        diagnostics_(diagnostics) {}

  /// Node `index` below this one: `path` is its full key path, `key_location`
  /// where its key (or list item) starts.
  ConfigNode child(YamlDocument::Index index, std::string path,
                   const SourceLocation& key_location) const;
  /// Where the key of map entry `k` starts.
  SourceLocation key_at(std::size_t k) const;
  /// Item `i` of a list (its key location is the item itself).
  ConfigNode item(std::size_t i) const;
  std::size_t size() const { return is_null() ? 0 : document_->size(index_); }
  YamlDocument::Kind kind() const {
    return index_ == YamlDocument::kNone ? YamlDocument::Kind::null : document_->kind(index_);
  }

  std::shared_ptr<const YamlDocument> document_;
  YamlDocument::Index index_ = YamlDocument::kNone;
  std::string path_;
  SourceLocation location_;
  SourceLocation key_location_;
  Diagnostics* diagnostics_;
};

/// The items of a list node, made one at a time as they are read: a list
/// of millions of items (a long history) is not copied into as many nodes,
/// each with its path and locations.
class ConfigList {
 public:
  explicit ConfigList(ConfigNode list) : list_(std::move(list)) {}

  std::size_t size() const { return list_.size(); }
  bool empty() const { return size() == 0; }
  ConfigNode operator[](std::size_t i) const { return list_.item(i); }
  ConfigNode front() const { return list_.item(0); }
  ConfigNode back() const { return list_.item(size() - 1); }

  class iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = ConfigNode;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = ConfigNode;

    iterator(const ConfigList* list, std::size_t i) : list_(list), i_(i) {}
    ConfigNode operator*() const { return (*list_)[i_]; }
    iterator& operator++() {
      ++i_;
      return *this;
    }
    bool operator==(const iterator& o) const { return i_ == o.i_; }
    bool operator!=(const iterator& o) const { return i_ != o.i_; }

   private:
    const ConfigList* list_;
    std::size_t i_;
  };
  iterator begin() const { return {this, 0}; }
  iterator end() const { return {this, size()}; }

 private:
  ConfigNode list_;
};

}  // namespace fissure
