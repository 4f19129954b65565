// Reading a scene: load the YAML, read the shared keys and every module's
// section (collecting problems), generate the blocks of block sources, check
// the geometry and attach points to blocks, then throw once with every
// problem, or return the validated Scene.
#include "core/scene/parse_scene.h"

#include <fmt/format.h>
#include <yaml-cpp/exceptions.h>

#include <algorithm>
#include <fstream>

#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "core/scene/scene_draft.h"
#include "core/scene/scene_keys.h"

namespace fissure {

namespace {

/// The top-level keys: the shared ones and one per module section.
std::vector<std::string_view> top_keys(std::span<const SceneSection> sections) {
  std::vector<std::string_view> keys(scene_keys::top.keys.begin(), scene_keys::top.keys.end());
  for (const SceneSection& s : sections) keys.push_back(s.reader->key);
  return keys;
}

}  // namespace

std::string read_input_file(const std::filesystem::path& file, std::string_view what) {
  namespace fs = std::filesystem;
  auto refuse = [&](const std::string& found) {
    throw SceneError(file.string() + ":1:1: (document): found " + found + "; expected " +
                     std::string(what));
  };
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (ec || !fs::exists(status)) refuse("no readable file");
  if (fs::is_directory(status)) refuse("a folder");
  // A pipe is read (up to the limit); a device (/dev/zero, a terminal) has
  // no end to wait for, and is refused at once.
  if (!fs::is_regular_file(status) && !fs::is_fifo(status)) refuse("a device, not a file");
  const std::string limit =
      fmt::format("; Fissure reads input files of at most {} MB", kMaxInputFileBytes >> 20);
  if (fs::is_regular_file(status) && fs::file_size(file, ec) > kMaxInputFileBytes && !ec)
    refuse(fmt::format("a file of {} MB", fs::file_size(file) >> 20) + limit);
  std::ifstream in(file, std::ios::binary);
  if (!in) refuse("no readable file");
  std::string text;
  std::vector<char> chunk(1 << 20);
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxInputFileBytes)
      refuse(fmt::format("more than {} MB", kMaxInputFileBytes >> 20) + limit);
  }
  return text;
}

namespace {

/// A lower bound of the values a YAML text holds, from its bytes alone:
/// its commas (n items of a flow list have n - 1) and its lines that hold
/// more than a comment (at least one value each), outside quotes and
/// comments. Costs no allocation, unlike any parse.
double values_at_least(std::string_view text) {
  double values = 0;
  char quote = 0;
  bool comment = false, line_has_value = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      values += line_has_value;
      comment = line_has_value = false;
      if (quote == '\'') quote = 0;  // a single-quoted scalar may span lines; count it once
      continue;
    }
    if (comment) continue;
    if (quote) {
      if (c == quote && (quote == '\'' || text[i - 1] != '\\')) quote = 0;
      continue;
    }
    if (c == '#' && (i == 0 || text[i - 1] == ' ' || text[i - 1] == '\t')) {
      comment = true;
    } else if (c == '"' || c == '\'') {
      quote = c;
      line_has_value = true;
    } else if (c == ',') {
      ++values;
    } else if (c != ' ' && c != '\t' && c != '\r') {
      line_has_value = true;
    }
  }
  return values + line_has_value;
}

/// The YAML tree (yaml_document.h) takes 21 bytes a value and its text;
/// reading a scene with a long history measured 28-42 bytes a value in all
/// (peak resident memory less the program's 40 MB: 100,000 to 3.2 million
/// [t, factor] pairs, 403 MB for 3.2 million). The memory check counts 20
/// per value counted (a pair counts as 2: its 2 commas).
constexpr double kYamlBytesPerValue = 20;

/// Offset of the first byte of `text` that does not belong to a well-formed
/// UTF-8 sequence (RFC 3629: no overlong forms, no surrogates, at most
/// U+10FFFF), if any. yaml-cpp passes such bytes through, and the names
/// they end up in cannot be written to summary.json (JSON is UTF-8).
std::optional<std::size_t> first_invalid_utf8(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto b = static_cast<unsigned char>(text[i]);
    int length = 0;
    unsigned char lo = 0x80, hi = 0xBF;  // range of the second byte
    if (b < 0x80)
      length = 1;
    else if (b >= 0xC2 && b <= 0xDF)
      length = 2;
    else if (b >= 0xE0 && b <= 0xEF) {
      length = 3;
      if (b == 0xE0) lo = 0xA0;
      if (b == 0xED) hi = 0x9F;
    } else if (b >= 0xF0 && b <= 0xF4) {
      length = 4;
      if (b == 0xF0) lo = 0x90;
      if (b == 0xF4) hi = 0x8F;
    } else {
      return i;
    }
    for (int k = 1; k < length; ++k) {
      if (i + k >= text.size()) return i;
      const auto c = static_cast<unsigned char>(text[i + k]);
      if (c < (k == 1 ? lo : 0x80) || c > (k == 1 ? hi : 0xBF)) return i;
    }
    i += static_cast<std::size_t>(length);
  }
  return std::nullopt;
}

/// Offset of the first carriage return that no line feed follows, if any.
/// YAML counts a lone CR as a line break, yaml-cpp 0.7 does not: a file with
/// classic Mac OS line ends is one line to it, and its first comment hides
/// every key (found by the scene fuzzer as "key is missing" for keys that
/// are there).
std::optional<std::size_t> first_lone_carriage_return(std::string_view text) {
  for (std::size_t i = text.find('\r'); i != std::string_view::npos; i = text.find('\r', i + 1))
    if (i + 1 == text.size() || text[i + 1] != '\n') return i;
  return std::nullopt;
}

/// Line and column (1-based) of byte `offset` of `text`.
SourceLocation location_of(std::string_view text, std::size_t offset, const std::string& file) {
  const std::string_view before = text.substr(0, offset);
  const auto line = static_cast<int>(std::count(before.begin(), before.end(), '\n'));
  const std::size_t line_start = before.rfind('\n');
  const auto column =
      static_cast<int>(line_start == std::string_view::npos ? offset : offset - line_start - 1);
  return {file, line + 1, column + 1};
}

}  // namespace

std::optional<ConfigNode> load_document(const std::string& yaml, std::string_view what,
                                        Diagnostics& diagnostics) {
  if (const std::optional<std::size_t> bad = first_invalid_utf8(yaml)) {
    diagnostics.error(location_of(yaml, *bad, diagnostics.file_name()), "",
                      fmt::format("found the byte 0x{:02X}, which is not UTF-8 text; expected a "
                                  "file in UTF-8 (ASCII is)",
                                  static_cast<unsigned char>(yaml[*bad])));
    return std::nullopt;
  }
  if (const std::optional<std::size_t> cr = first_lone_carriage_return(yaml)) {
    diagnostics.error(location_of(yaml, *cr, diagnostics.file_name()), "",
                      "found a carriage return (CR) without a line feed; expected LF or CR LF "
                      "line ends (a lone CR would not end the line here)");
    return std::nullopt;
  }
  try {
    // Before any parse: a tree that cannot fit is refused unbuilt.
    const double values = values_at_least(yaml);
    check_memory(values * kYamlBytesPerValue, diagnostics.file_name() + ":1:1: (document)",
                 fmt::format("a YAML document of at least {:.3g} values", values));
    std::shared_ptr<const YamlDocument> document = YamlDocument::parse(yaml);
    if (document->documents() > 1) {
      const YamlDocument::Mark m = document->second_document();
      diagnostics.error(
          {diagnostics.file_name(), m.line >= 0 ? m.line + 1 : 1, m.line >= 0 ? m.column + 1 : 1},
          "", "found a second YAML document; expected one " + std::string(what) + " per file");
      return std::nullopt;
    }
    return ConfigNode::root(std::move(document), diagnostics);
  } catch (const YAML::Exception& e) {  // syntax errors, nesting too deep, ...
    diagnostics.error({diagnostics.file_name(), e.mark.line + 1, e.mark.column + 1}, "",
                      "found malformed YAML (" + e.msg + "); expected valid YAML syntax");
    return std::nullopt;
  }
}

Scene parse_scene_text(const std::string& yaml, const std::string& file_name,
                       std::span<const SceneSection> sections) {
  Diagnostics diagnostics(file_name);
  const std::optional<ConfigNode> document = load_document(yaml, "scene", diagnostics);
  diagnostics.throw_if_any();

  for (const SceneSection& s : sections)
    for (const MovedKey& k : s.reader->moved_keys) diagnostics.add_moved_key(k.from, k.to);

  SceneDraft draft;
  draft.scene.source = file_name;
  draft.scene.name = std::filesystem::path(file_name).stem().string();

  // 1. Read the shared keys and every module's section; each problem is
  // recorded and reading goes on.
  if (document->is_null()) {
    document->error("found an empty file; expected a scene (see docs/scene-reference.md)");
    diagnostics.throw_if_any();
  }
  {
    const std::vector<std::string_view> keys = top_keys(sections);
    ConfigMap top(*document, KeyTable{"", keys});
    draft.top = &top;
    read_general(top, draft, sections);
    read_materials(top, draft);
    std::vector<std::string_view> other_sources;
    for (const SceneSection& s : sections)
      if ((s.reader->generate || s.reader->own_geometry) && top.contains(s.reader->key))
        other_sources.push_back(s.reader->key);
    read_blocks(top, draft, other_sources);
    for (const SceneSection& s : sections)  // block sources (the rock mass)
      if (s.reader->generate) read_module_section(top, draft, s);
    read_points(top, draft);
    read_coupling(top, draft);
    read_time_output(top, draft);           // before the processes check their steps against it
    for (const SceneSection& s : sections)  // the processes' sections
      if (!s.reader->generate) read_module_section(top, draft, s);
    draft.top = nullptr;
  }  // unknown top-level keys are reported here

  // 2. Blocks generated by the block sources, appended to the blocks read.
  generate_blocks(draft, diagnostics);

  // 3. Geometry, which needs all blocks: polygons, overlaps, points on blocks.
  const double tolerance = check_geometry(draft, diagnostics);
  resolve_points(draft, tolerance, diagnostics);

  // 4. Nothing may run on an invalid scene.
  diagnostics.throw_if_any();
  draft.scene.warnings = diagnostics.warnings();
  return std::move(draft.scene);
}

Scene parse_scene(const std::filesystem::path& file, std::span<const SceneSection> sections) {
  Scene scene =
      parse_scene_text(read_input_file(file, "a scene file (YAML)"), file.string(), sections);
  scene.source = file;
  return scene;
}

}  // namespace fissure
