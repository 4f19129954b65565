// The compact YAML tree that scenes are read through (core/scene/yaml_document.h):
// the same values, kinds and marks as yaml-cpp's node tree (YAML::Load is
// the reference here), duplicate keys kept, aliases shared, and the
// document errors of load_document.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "core/scene/parse_scene.h"
#include "core/scene/yaml_document.h"

namespace fissure {
namespace {

using Kind = YamlDocument::Kind;

/// Node `i` of `d` and yaml-cpp's `n` hold the same: kind, mark, text,
/// plainness (Tag() "?"), children in order.
void expect_same(const YamlDocument& d, YamlDocument::Index i, const YAML::Node& n,
                 const std::string& where) {
  SCOPED_TRACE(where);
  ASSERT_NE(i, YamlDocument::kNone);
  const Kind expected = n.IsNull()       ? Kind::null
                        : n.IsScalar()   ? Kind::scalar
                        : n.IsSequence() ? Kind::sequence
                                         : Kind::map;
  ASSERT_EQ(d.kind(i), expected);
  EXPECT_EQ(d.mark(i).line, n.Mark().line);
  EXPECT_EQ(d.mark(i).column, n.Mark().column);
  if (n.IsScalar()) {
    EXPECT_EQ(d.text(i), n.Scalar());
    EXPECT_EQ(d.plain(i), n.Tag() == "?");
  }
  if (n.IsSequence()) {
    ASSERT_EQ(d.size(i), n.size());
    for (std::size_t k = 0; k < n.size(); ++k)
      expect_same(d, d.item(i, k), n[k], where + "[" + std::to_string(k) + "]");
  }
  if (n.IsMap()) {
    ASSERT_EQ(d.size(i), n.size());
    std::size_t k = 0;
    for (auto it = n.begin(); it != n.end(); ++it, ++k) {
      expect_same(d, d.key(i, k), it->first, where + " key " + std::to_string(k));
      expect_same(d, d.value(i, k), it->second, where + " value " + std::to_string(k));
    }
  }
}

/// Parsed with the default threshold of long lists, and with every flow
/// list read as a long one (yaml_long_lists.h).
void expect_as_yaml_cpp(const std::string& text) {
  const YAML::Node reference = YAML::Load(text);
  for (std::size_t long_list_bytes : {std::size_t{0}, std::size_t{1}}) {
    const auto d = YamlDocument::parse(text, long_list_bytes);
    EXPECT_EQ(d->documents(), 1);
    expect_same(*d, d->root(), reference,
                text + " (long lists from " + std::to_string(long_list_bytes) + " bytes)");
  }
}

TEST(YamlDocument, ScalarsAndNullsAsYamlCpp) {
  expect_as_yaml_cpp("42");
  expect_as_yaml_cpp("a: 1\nb: ~\nc:\nd: null\ne: ''\nf: \"x y\"\ng: 2650 kg/m^3\n");
  expect_as_yaml_cpp("- ~\n-\n- 'quoted'\n- !!str tagged\n- plain text\n");
  const auto d = YamlDocument::parse("[~, '', plain, \"q\"]");
  const auto r = d->root();
  EXPECT_EQ(d->kind(d->item(r, 0)), Kind::null);
  EXPECT_EQ(d->kind(d->item(r, 1)), Kind::scalar);
  EXPECT_EQ(d->text(d->item(r, 1)), "");
  EXPECT_TRUE(d->plain(d->item(r, 2)));
  EXPECT_FALSE(d->plain(d->item(r, 3)));
}

TEST(YamlDocument, NestedFlowAndBlockCollectionsAsYamlCpp) {
  expect_as_yaml_cpp(
      "materials:\n  - {name: granite, density: 2650 kg/m^3}\n  - name: basalt\n"
      "    joints: [[0, 1], [2, 3]]\nblocks:\n  - vertices:\n      - [0, 0]\n      - [1, 0]\n"
      "    holes: []\nmap: {}\n");
  expect_as_yaml_cpp("[[[1]], {a: [2, {b: 3}]}, [], {}]");
  expect_as_yaml_cpp("text: |\n  two\n  lines\nfolded: >\n  one\n  line\n");
}

TEST(YamlDocument, DuplicateKeysAreKeptInOrder) {
  const std::string text = "a: 1\nb: 2\na: 3\n";
  expect_as_yaml_cpp(text);
  const auto d = YamlDocument::parse(text);
  ASSERT_EQ(d->size(d->root()), 3u);
  EXPECT_EQ(d->text(d->key(d->root(), 2)), "a");
  EXPECT_EQ(d->text(d->value(d->root(), 2)), "3");
}

TEST(YamlDocument, AnAliasIsTheAnchoredNode) {
  expect_as_yaml_cpp("a: &x [1, 2]\nb: *x\nc: &y 3\nd: *y\n");
  // Nine levels of nine aliases: 9^9 values for a tree that copies them.
  std::string bomb = "a0: &a0 [x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i < 10; ++i) {
    std::string items;
    for (int k = 0; k < 9; ++k) items += (k ? ", *a" : "*a") + std::to_string(i - 1);
    bomb += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [" + items + "]\n";
  }
  const auto d = YamlDocument::parse(bomb);
  EXPECT_LT(d->node_count(), 200u);
  const auto r = d->root();
  EXPECT_EQ(d->item(d->value(r, 9), 0), d->value(r, 8));
}

TEST(YamlDocument, LongListsAsYamlCpp) {
  expect_as_yaml_cpp("history: [[0, 1], [0.5 yr, 2 MW/m^2], [1e-3, -1.5e+3], [x, null]]\n");
  expect_as_yaml_cpp("- {name: c, history: [[0, 1],[1,2] ,[ 2 , 3 ]], power: 1 W}\n- [a b c, d]\n");
  expect_as_yaml_cpp("a: [[[1, [2]]], []]\nb: [ ]\nc: [Null, NULL, nothing, -1, +2, .5, _x]\n");
  // Brackets that yaml-cpp reads as text: a span found there is parsed again.
  expect_as_yaml_cpp("a: '[1, 2]'\nb: \"[3, 4]\" # [5, 6]\nc: x [7, 8]\nd: |\n  [9, 10]\n");
  expect_as_yaml_cpp("a: [1, 2]\nb: 'x [3, 4]'\nc: [5, 6]\n");
  // A list as a key, anchors and tags around lists, line ends.
  expect_as_yaml_cpp("? [1, 2]\n: a\nb: &x [3, 4]\nc: *x\nd: !!seq [5]\n");
  expect_as_yaml_cpp("a: [1, 2]\r\nb: [3, [4]]\r\n");
  expect_as_yaml_cpp(
      "\xEF\xBB\xBF"
      "a: [1, 2]\nb: [3]\n");  // a byte-order mark
  expect_as_yaml_cpp("a: [1,\n  2]\nb: [1  kg, 2]\nd: [1, 2, ]\n");
}

TEST(YamlDocument, LongListsAreReadBesideYamlCpp) {
  // 100,000 pairs: read here, yaml-cpp shown "[   ...   ]".
  std::string text = "history: [";
  for (int i = 0; i < 100000; ++i) text += (i ? ", [" : "[") + std::to_string(i) + ", 1]";
  text += "]\nend: 1\n";
  const auto d = YamlDocument::parse(text);
  const auto history = d->value(d->root(), 0);
  ASSERT_EQ(d->size(history), 100000u);
  const auto last = d->item(history, 99999);
  EXPECT_EQ(d->text(d->item(last, 0)), "99999");
  EXPECT_EQ(d->mark(d->item(last, 0)).column, static_cast<int>(text.find("[99999,") + 1));
  EXPECT_EQ(d->mark(d->value(d->root(), 1)).line, 1);
  // Compact: nodes, children and text in well under 100 bytes a value.
  EXPECT_LT(d->bytes(), 100u * 300000u);
}

TEST(YamlDocument, EmptyTextHasNoDocument) {
  for (const char* text : {"", "# only a comment\n", "\n\n"}) {
    const auto d = YamlDocument::parse(text);
    EXPECT_EQ(d->documents(), 0);
    EXPECT_EQ(d->root(), YamlDocument::kNone);
  }
}

TEST(YamlDocument, SyntaxErrorsThrowWithTheirMark) {
  for (const char* text : {"a: [1, 2\nb: 3\n", "a: b: c\n", "a: *nowhere\n", "{a: 1",
                           "a: [1, 2]]\n", "a: [1, 2] x\n", "a: [- 1, 2]\n", "[1, 2]: a: b\n"}) {
    int line = -2, column = -2;
    try {
      YAML::LoadAll(text);
    } catch (const YAML::Exception& e) {
      line = e.mark.line;
      column = e.mark.column;
    }
    try {
      YamlDocument::parse(text, 1);
      ADD_FAILURE() << text;
    } catch (const YAML::Exception& e) {
      EXPECT_EQ(e.mark.line, line) << text;
      EXPECT_EQ(e.mark.column, column) << text;
    }
  }
}

TEST(YamlDocument, SecondDocumentIsCountedAtItsRoot) {
  const std::string text = "a: 1\n---\n  b: 2\n---\nc: 3\n";
  const auto d = YamlDocument::parse(text);
  EXPECT_EQ(d->documents(), 3);
  const YAML::Mark m = YAML::LoadAll(text)[1].Mark();
  EXPECT_EQ(d->second_document().line, m.line);
  EXPECT_EQ(d->second_document().column, m.column);
  EXPECT_EQ(d->size(d->root()), 1u);  // the first document only

  Diagnostics diagnostics("s.yaml");
  EXPECT_FALSE(load_document(text, "scene", diagnostics));
  EXPECT_EQ(diagnostics.text(),
            "s.yaml:3:3: (document): found a second YAML document; expected one scene per file");
}

TEST(YamlDocument, StuckParserIsASyntaxError) {
  // yaml-cpp 0.7 reads these as empty documents without end (issue 1040).
  for (const char* text : {",", "- a\n,\n"}) {
    EXPECT_THROW(YamlDocument::parse(text), YAML::Exception) << text;
    Diagnostics diagnostics("s.yaml");
    EXPECT_FALSE(load_document(text, "scene", diagnostics));
    EXPECT_NE(diagnostics.text().find(
                  "found malformed YAML (',' where a value should start); expected valid YAML"),
              std::string::npos)
        << diagnostics.text();
  }
}

}  // namespace
}  // namespace fissure
