// Long flow lists read beside yaml-cpp (issue 35, item 2). yaml-cpp's
// scanner keeps every token of a flow list that may still turn out to be a
// map key (`[...]: value`) until the list ends: 2.7 GB for a history of 3.2
// million [t, factor] pairs. The long lists of plain scalars on one line
// (`[[0, 1], [0.01, 1], ...]`) are found in the text, shown to yaml-cpp
// blanked (`[     ]`: same length, so every mark stays), and their items
// read here with a grammar that is a strict subset of YAML's flow syntax.
// A list found where yaml-cpp does not start a flow sequence (in a quoted
// or block scalar, a comment) was not one: YamlDocument::parse parses again
// without blanking it.
#pragma once

#include <cstddef>
#include <optional>
#include <streambuf>
#include <string_view>
#include <vector>

namespace fissure {

/// A flow list in the text: `[` at `begin`, its `]` at `end - 1`; the
/// nodes inside it and the bytes of their scalars (to size the tree).
struct InlineListSpan {
  std::size_t begin;
  std::size_t end;
  std::size_t nodes = 0;
  std::size_t scalar_bytes = 0;
};

/// What read_inline_list finds inside a list, in order (offsets in the text).
class InlineListEvents {
 public:
  virtual ~InlineListEvents() = default;
  /// A plain scalar; `null` for yaml-cpp's null words (null, Null, NULL).
  virtual void scalar(std::size_t offset, std::string_view text, bool null) = 0;
  virtual void list_start(std::size_t offset) = 0;
  virtual void list_end() = 0;
};

/// The end of the flow list whose `[` is at `begin`, when it is one of the
/// lists read here: on one line, nested lists (at most 16 deep) and plain
/// scalars of letters, digits and `._+-/^` (words one space apart, a word
/// not starting with `-` alone), no empty item. Its items go to `events`
/// (not the outer list's own start and end) when given.
std::optional<std::size_t> read_inline_list(std::string_view text, std::size_t begin,
                                            InlineListEvents* events);

/// The lists read_inline_list reads that are at least `min_bytes` long, in
/// text order, none inside another.
std::vector<InlineListSpan> long_inline_lists(std::string_view text, std::size_t min_bytes);

/// The text as a stream, each span's inside blanked (its brackets kept),
/// read in chunks: no copy of the text.
class BlankedListsBuffer : public std::streambuf {
 public:
  BlankedListsBuffer(std::string_view text, const std::vector<InlineListSpan>& spans);

 protected:
  int_type underflow() override;

 private:
  std::string_view text_;
  const std::vector<InlineListSpan>& spans_;
  std::size_t next_ = 0;       // offset of the next chunk in text_
  std::size_t next_span_ = 0;  // first span not wholly before next_
  std::vector<char> chunk_;
};

}  // namespace fissure
