#include "core/scene/yaml_long_lists.h"

#include <algorithm>
#include <cstring>

namespace fissure {

namespace {

constexpr int kMaxDepth = 16;
constexpr std::size_t kChunkBytes = 1 << 16;

bool word_char(char c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
         std::strchr("._+-/^", c) != nullptr;
}

/// Whether a word starts at `i`: a word character, and a `-` only before
/// another one (`- ` is a block entry, `-,` not a plain scalar).
bool word_start(std::string_view text, std::size_t i) {
  if (i >= text.size() || !word_char(text[i])) return false;
  return text[i] != '-' || (i + 1 < text.size() && word_char(text[i + 1]));
}

/// The end of the plain scalar starting at `i` (a word there): words one
/// space apart. Nothing when two spaces part words (yaml-cpp would keep
/// them; not worth matching here).
std::optional<std::size_t> scalar_end(std::string_view text, std::size_t i) {
  while (true) {
    while (i < text.size() && word_char(text[i])) ++i;
    if (i < text.size() && text[i] == ' ' && word_start(text, i + 1)) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && text[j] == ' ') ++j;
    if (j > i + 1 && word_start(text, j)) return std::nullopt;
    return i;
  }
}

bool null_word(std::string_view s) {
  return s == "null" || s == "Null" || s == "NULL";
}

/// Counts what a list holds.
class Count : public InlineListEvents {
 public:
  std::size_t nodes = 0, scalar_bytes = 0;
  void scalar(std::size_t, std::string_view text, bool) override {
    ++nodes;
    scalar_bytes += text.size();
  }
  void list_start(std::size_t) override { ++nodes; }
  void list_end() override {}
};

}  // namespace

std::optional<std::size_t> read_inline_list(std::string_view text, std::size_t begin,
                                            InlineListEvents* events) {
  if (begin >= text.size() || text[begin] != '[') return std::nullopt;
  enum { item_or_end, item, entry_or_end } expect = item_or_end;
  int depth = 1;
  std::size_t i = begin + 1;
  while (true) {
    while (i < text.size() && text[i] == ' ') ++i;
    if (i >= text.size()) return std::nullopt;
    const char c = text[i];
    if (expect != entry_or_end && c == '[') {
      if (++depth > kMaxDepth) return std::nullopt;
      if (events) events->list_start(i);
      ++i;
      expect = item_or_end;
    } else if (expect != item && c == ']') {
      ++i;
      if (--depth == 0) return i;
      if (events) events->list_end();
      expect = entry_or_end;
    } else if (expect == entry_or_end && c == ',') {
      ++i;
      expect = item;
    } else if (expect != entry_or_end && word_start(text, i)) {
      const std::optional<std::size_t> end = scalar_end(text, i);
      if (!end) return std::nullopt;
      const std::string_view s = text.substr(i, *end - i);
      if (events) events->scalar(i, s, null_word(s));
      i = *end;
      expect = entry_or_end;
    } else {
      return std::nullopt;  // anything else, a line break included
    }
  }
}

std::vector<InlineListSpan> long_inline_lists(std::string_view text, std::size_t min_bytes) {
  std::vector<InlineListSpan> spans;
  std::size_t i = text.find('[');
  while (i != std::string_view::npos) {
    // Counted only once long: a scene's short lists cost no more than a scan.
    const std::optional<std::size_t> end = read_inline_list(text, i, nullptr);
    if (end && *end - i >= min_bytes) {
      Count count;
      read_inline_list(text, i, &count);
      spans.push_back({i, *end, count.nodes, count.scalar_bytes});
      i = text.find('[', *end);
    } else {
      i = text.find('[', i + 1);
    }
  }
  return spans;
}

BlankedListsBuffer::BlankedListsBuffer(std::string_view text,
                                       const std::vector<InlineListSpan>& spans)
    : text_(text), spans_(spans), chunk_(kChunkBytes) {}

BlankedListsBuffer::int_type BlankedListsBuffer::underflow() {
  if (next_ >= text_.size()) return traits_type::eof();
  const std::size_t n = std::min(kChunkBytes, text_.size() - next_);
  std::copy_n(text_.data() + next_, n, chunk_.data());
  while (next_span_ < spans_.size() && spans_[next_span_].end <= next_) ++next_span_;
  for (std::size_t s = next_span_; s < spans_.size() && spans_[s].begin < next_ + n; ++s) {
    // The inside of the span, [begin + 1, end - 1), within this chunk.
    const std::size_t from = std::max(spans_[s].begin + 1, next_);
    const std::size_t to = std::min(spans_[s].end - 1, next_ + n);
    if (from < to) std::fill(chunk_.data() + (from - next_), chunk_.data() + (to - next_), ' ');
  }
  setg(chunk_.data(), chunk_.data(), chunk_.data() + n);
  next_ += n;
  return traits_type::to_int_type(chunk_[0]);
}

}  // namespace fissure
