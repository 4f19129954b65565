// An immutable, compact YAML tree (issue 35, item 2). yaml-cpp's node tree
// costs about 710 bytes per value (a history of 3.2 million [t, factor]
// pairs took 6.85 GB); this one is built from yaml-cpp's parser events (so
// yaml-cpp still checks the syntax) into flat vectors: a 16-byte record and
// a kind byte per node, one index per child, one arena for the scalar text.
// ConfigNode (config_node.h) reads scenes through it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace fissure {

struct InlineListSpan;

class YamlDocument {
 public:
  using Index = std::uint32_t;
  /// No node: an empty text has no root.
  static constexpr Index kNone = UINT32_MAX;

  enum class Kind : std::uint8_t { null, scalar, sequence, map };

  /// Where a node starts, as yaml-cpp gives it: 0-based line and column,
  /// or -1 when it has no place.
  struct Mark {
    int line = -1;
    int column = -1;
  };

  /// The first document of `text` (the other documents are parsed, to find
  /// their syntax errors, and counted, not kept). Syntax errors throw
  /// YAML::Exception with their mark, as YAML::LoadAll does; so does a text
  /// that yaml-cpp 0.7 would read as empty documents without end (at the
  /// ',' where a value should start; yaml-cpp issue 1040). Flow lists of
  /// at least `long_list_bytes` (0: the default, 4 kB) are read beside
  /// yaml-cpp (yaml_long_lists.h).
  static std::shared_ptr<const YamlDocument> parse(std::string_view text,
                                                   std::size_t long_list_bytes = 0);

  /// The first document's root; kNone for a text without a document.
  Index root() const { return root_; }
  /// How many documents the text holds, and where the second one's root is.
  int documents() const { return documents_; }
  Mark second_document() const { return second_document_; }

  Kind kind(Index i) const { return kinds_[i]; }
  Mark mark(Index i) const { return {nodes_[i].line, nodes_[i].column}; }
  /// Whether a scalar was plain (unquoted, untagged): yaml-cpp's Tag() "?".
  bool plain(Index i) const { return plain_[i]; }
  /// A scalar's text; empty for other nodes.
  std::string_view text(Index i) const;
  /// A sequence's items or a map's entries; 0 for other nodes.
  std::size_t size(Index i) const;
  /// Item `k` of a sequence.
  Index item(Index i, std::size_t k) const { return children_[nodes_[i].begin + k]; }
  /// Key and value of entry `k` of a map, in file order (duplicate keys kept).
  Index key(Index i, std::size_t k) const { return children_[nodes_[i].begin + 2 * k]; }
  Index value(Index i, std::size_t k) const { return children_[nodes_[i].begin + 2 * k + 1]; }

  /// Nodes and bytes held, for the memory check's measurements.
  std::size_t node_count() const { return nodes_.size(); }
  std::size_t bytes() const;

 private:
  friend class YamlDocumentBuilder;
  void reserve(const std::vector<InlineListSpan>& spans);

  /// A scalar's text is arena_[begin, begin + size); a collection's
  /// children are children_[begin, begin + size) (maps: key, value, ...).
  struct Node {
    std::int32_t line;
    std::int32_t column;
    std::uint32_t begin;
    std::uint32_t size;
  };
  std::vector<Node> nodes_;
  std::vector<Kind> kinds_;
  std::vector<bool> plain_;
  std::vector<Index> children_;
  std::string arena_;
  Index root_ = kNone;
  int documents_ = 0;
  Mark second_document_;
};

}  // namespace fissure
