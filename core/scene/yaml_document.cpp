#include "core/scene/yaml_document.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/mark.h>
#include <yaml-cpp/parser.h>

#include <algorithm>
#include <istream>
#include <iterator>

#include "core/scene/yaml_long_lists.h"

namespace fissure {

namespace {

/// Flow lists from this length on are read beside yaml-cpp
/// (yaml_long_lists.h): a scene's ordinary lists are far shorter, and
/// yaml-cpp reads them at no great cost.
constexpr std::size_t kLongListBytes = 4096;

}  // namespace

/// Builds the first document from the parser's events. Children of each
/// open collection gather on one stack and move to `children_` when it
/// closes, so that every collection's children are contiguous. The items of
/// the long lists that yaml-cpp was shown blanked are read from the text.
class YamlDocumentBuilder : public YAML::EventHandler, InlineListEvents {
 public:
  YamlDocumentBuilder(YamlDocument& d, std::string_view text,
                      const std::vector<InlineListSpan>& spans)
      : d_(d), text_(text), spans_(spans), spliced_(spans.size(), false) {
    d_.reserve(spans);
  }

  /// Which blanked lists yaml-cpp started a flow sequence at.
  const std::vector<bool>& spliced() const { return spliced_; }

  /// Where the last two documents started.
  YAML::Mark previous_start = YAML::Mark::null_mark(), last_start = YAML::Mark::null_mark();

  void OnDocumentStart(const YAML::Mark& mark) override {
    previous_start = last_start;
    last_start = mark;
    ++d_.documents_;
    anchors_.clear();
  }
  void OnDocumentEnd() override {}

  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    if (building(mark)) add(new_node(mark, YamlDocument::Kind::null, anchor, false));
  }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    // The anchored node itself (no copy: an alias bomb stays small).
    if (building(mark)) add(anchors_[anchor]);
  }
  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                const std::string& value) override {
    if (!building(mark)) return;
    const YamlDocument::Index i = new_node(mark, YamlDocument::Kind::scalar, anchor, tag == "?");
    d_.nodes_[i].begin = static_cast<std::uint32_t>(d_.arena_.size());
    d_.nodes_[i].size = static_cast<std::uint32_t>(value.size());
    d_.arena_ += value;
    add(i);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    const bool first_document = building(mark);
    open(mark, YamlDocument::Kind::sequence, anchor);
    while (next_span_ < spans_.size() && spans_[next_span_].begin < std::size_t(mark.pos))
      ++next_span_;
    if (next_span_ < spans_.size() && spans_[next_span_].begin == std::size_t(mark.pos)) {
      spliced_[next_span_] = true;
      if (first_document) {
        list_mark_ = mark;
        read_inline_list(text_, mark.pos, this);
      }
      ++next_span_;
    }
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    open(mark, YamlDocument::Kind::map, anchor);
  }
  void OnMapEnd() override { close(); }

 private:
  // The items of a blanked list, at marks on the line of its `[`.
  void scalar(std::size_t offset, std::string_view text, bool null) override {
    const YAML::Mark mark = at(offset);
    if (null) return add(new_node(mark, YamlDocument::Kind::null, YAML::NullAnchor, false));
    const YamlDocument::Index i =
        new_node(mark, YamlDocument::Kind::scalar, YAML::NullAnchor, true);
    d_.nodes_[i].begin = static_cast<std::uint32_t>(d_.arena_.size());
    d_.nodes_[i].size = static_cast<std::uint32_t>(text.size());
    d_.arena_ += text;
    add(i);
  }
  void list_start(std::size_t offset) override {
    open(at(offset), YamlDocument::Kind::sequence, YAML::NullAnchor);
  }
  void list_end() override { close(); }
  YAML::Mark at(std::size_t offset) const {
    YAML::Mark m = list_mark_;
    m.column += static_cast<int>(offset - static_cast<std::size_t>(list_mark_.pos));
    m.pos = static_cast<int>(offset);
    return m;
  }

  /// Whether the events belong to the first document; the second one's
  /// root is noted.
  bool building(const YAML::Mark& mark) {
    if (d_.documents_ == 2 && d_.second_document_.line == -1 && depth_ == 0)
      d_.second_document_ = {mark.line, mark.column};
    return d_.documents_ == 1;
  }

  YamlDocument::Index new_node(const YAML::Mark& mark, YamlDocument::Kind kind,
                               YAML::anchor_t anchor, bool plain) {
    const auto i = static_cast<YamlDocument::Index>(d_.nodes_.size());
    d_.nodes_.push_back({mark.line, mark.column, 0, 0});
    d_.kinds_.push_back(kind);
    d_.plain_.push_back(plain);
    if (anchor != YAML::NullAnchor) {
      if (anchors_.size() <= anchor) anchors_.resize(anchor + 1, YamlDocument::kNone);
      anchors_[anchor] = i;
    }
    return i;
  }

  void add(YamlDocument::Index i) {
    if (open_.empty())
      d_.root_ = i;
    else
      pending_.push_back(i);
  }

  void open(const YAML::Mark& mark, YamlDocument::Kind kind, YAML::anchor_t anchor) {
    if (!building(mark)) {
      ++depth_;
      return;
    }
    // Added to its parent first, so that an alias inside it may name it
    // (yaml-cpp's nodes allow such a cycle too).
    const YamlDocument::Index i = new_node(mark, kind, anchor, false);
    add(i);
    open_.push_back({i, pending_.size()});
  }

  void close() {
    if (d_.documents_ != 1) {
      --depth_;
      return;
    }
    const Open o = open_.back();
    open_.pop_back();
    d_.nodes_[o.node].begin = static_cast<std::uint32_t>(d_.children_.size());
    d_.nodes_[o.node].size = static_cast<std::uint32_t>(pending_.size() - o.first_child);
    d_.children_.insert(d_.children_.end(), pending_.begin() + o.first_child, pending_.end());
    pending_.resize(o.first_child);
  }

  struct Open {
    YamlDocument::Index node;
    std::size_t first_child;  // in pending_
  };
  YamlDocument& d_;
  std::string_view text_;
  const std::vector<InlineListSpan>& spans_;
  std::vector<bool> spliced_;
  std::size_t next_span_ = 0;
  YAML::Mark list_mark_;
  std::vector<YamlDocument::Index> anchors_;  // by yaml-cpp's anchor number
  std::vector<Open> open_;
  std::vector<YamlDocument::Index> pending_;
  int depth_ = 0;  // of open collections in later documents
};

namespace {

/// One parse of `text`, with the inside of `spans` blanked; the spans that
/// yaml-cpp did not start a flow sequence at are left in `unread`.
std::shared_ptr<YamlDocument> parse_blanked(std::string_view text,
                                            const std::vector<InlineListSpan>& spans,
                                            std::vector<InlineListSpan>& unread) {
  auto document = std::make_shared<YamlDocument>();
  BlankedListsBuffer buffer(text, spans);
  std::istream in(&buffer);
  YAML::Parser parser(in);
  YamlDocumentBuilder builder(*document, text, spans);
  while (parser.HandleNextDocument(builder)) {
    // yaml-cpp 0.7 does not consume a ',' where a block-level value starts
    // (`,` alone, `- a` then `,` on the next line): each document it reads
    // there is an empty one at the same place, for ever. Every real
    // document consumes text, so two documents starting at the same place
    // mean the parser is stuck there.
    const YAML::Mark& m = builder.last_start;
    if (document->documents() >= 2 && m.pos == builder.previous_start.pos) {
      const auto pos = static_cast<std::size_t>(std::max(m.pos, 0));
      const std::string c = pos < text.size() ? std::string(1, text[pos]) : std::string();
      throw YAML::ParserException(m, "'" + c + "' where a value should start");
    }
  }
  for (std::size_t s = 0; s < spans.size(); ++s)
    if (!builder.spliced()[s]) unread.push_back(spans[s]);
  return document;
}

}  // namespace

std::shared_ptr<const YamlDocument> YamlDocument::parse(std::string_view text,
                                                        std::size_t long_list_bytes) {
  std::vector<InlineListSpan> spans =
      long_inline_lists(text, long_list_bytes ? long_list_bytes : kLongListBytes);
  while (true) {
    // A span yaml-cpp did not read as a flow sequence was text of another
    // kind (a quoted or block scalar, a comment) that blanking changed: the
    // text is parsed again without blanking it. What comes before a span
    // alone decides how yaml-cpp reads its `[`, so the others stay read.
    std::vector<InlineListSpan> unread;
    std::shared_ptr<YamlDocument> document = parse_blanked(text, spans, unread);
    if (unread.empty()) {
      document->plain_.shrink_to_fit();
      return document;
    }
    std::vector<InlineListSpan> read;
    std::set_difference(
        spans.begin(), spans.end(), unread.begin(), unread.end(), std::back_inserter(read),
        [](const InlineListSpan& a, const InlineListSpan& b) { return a.begin < b.begin; });
    spans = std::move(read);
  }
}

void YamlDocument::reserve(const std::vector<InlineListSpan>& spans) {
  // The long lists hold nearly all of a large text's nodes: sized for them
  // (and a margin for the rest), the vectors do not double past them.
  std::size_t nodes = 1024, bytes = 4096;
  for (const InlineListSpan& s : spans) {
    nodes += s.nodes;
    bytes += s.scalar_bytes;
  }
  nodes_.reserve(nodes);
  kinds_.reserve(nodes);
  plain_.reserve(nodes);
  children_.reserve(nodes);
  arena_.reserve(bytes);
}

std::string_view YamlDocument::text(Index i) const {
  if (kinds_[i] != Kind::scalar) return {};
  return std::string_view(arena_).substr(nodes_[i].begin, nodes_[i].size);
}

std::size_t YamlDocument::size(Index i) const {
  switch (kinds_[i]) {
    case Kind::sequence:
      return nodes_[i].size;
    case Kind::map:
      return nodes_[i].size / 2;
    default:
      return 0;
  }
}

std::size_t YamlDocument::bytes() const {
  return nodes_.capacity() * sizeof(Node) + kinds_.capacity() + plain_.capacity() / 8 +
         children_.capacity() * sizeof(Index) + arena_.capacity();
}

}  // namespace fissure
