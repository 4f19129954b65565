// Replacing a small text file so that readers only ever see the old or the new
// content, never half of it (private to core/io; summary.json, results.xdmf).
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string_view>

namespace fissure {

/// Writes `content` to a temporary file next to `file`, then renames it over
/// `file` (rename is atomic within one file system). Throws IoError naming the
/// file and the reason.
void write_file_atomically(const std::filesystem::path& file, std::string_view content);

/// The same for content given in pieces, written one after the other (saves
/// joining a large file in memory first).
void write_file_atomically(const std::filesystem::path& file,
                           std::initializer_list<std::string_view> pieces);

}  // namespace fissure
