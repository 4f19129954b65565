// Reading a REV study file (`fissure rev STUDY.yaml`; keys in docs/flow.md
// section 8), with the scene parser's tracked reading: unknown keys,
// units, ranges, all problems reported as file:line:column.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "core/scene/config_node.h"
#include "flow/rev/domain_source.h"
#include "flow/rev/rev_study.h"

namespace fissure::flow {

struct RevStudy {
  RevStudyConfig config;
  std::unique_ptr<DomainSource> source;
};

/// Builds a source for `network.type: dfn` from its `network.dfn` map and the
/// `network.centre` (the DFN generator lives outside flow/, which may not
/// include mechanics/). Returns nothing after reporting problems on the node.
using DfnSourceFactory =
    std::function<std::unique_ptr<DomainSource>(const ConfigNode& dfn, const Vec2& centre)>;

/// What the modules above flow/ read of a study (coupling/upscaling): the
/// sources of `network.type: dfn` and `scene`, and the `mechanics` section
/// (the stress stage, docs/upscaling.md). Each reports its problems on its
/// node; an empty one makes its key unavailable in this build.
struct RevStudyReaders {
  DfnSourceFactory dfn;
  /// `network.scene` (the file, relative to the study's folder), with the
  /// `network.centre` when given.
  std::function<std::unique_ptr<DomainSource>(const ConfigNode& scene,
                                              const std::optional<Vec2>& centre)>
      scene;
  std::function<void(const ConfigNode& mechanics)> mechanics;
};

/// Throws SceneError listing every problem. `dfn` may be empty: then
/// `type: dfn` is reported as unavailable in this build.
RevStudy read_rev_study(const std::filesystem::path& file, const DfnSourceFactory& dfn = {});
RevStudy read_rev_study_text(const std::string& yaml, const std::string& file_name,
                             const DfnSourceFactory& dfn = {});
RevStudy read_rev_study(const std::filesystem::path& file, const RevStudyReaders& readers);
RevStudy read_rev_study_text(const std::string& yaml, const std::string& file_name,
                             const RevStudyReaders& readers);

/// Keys of a study file, with their documented paths ("network.sets[].spacing").
std::vector<std::string> known_rev_study_keys();

}  // namespace fissure::flow
