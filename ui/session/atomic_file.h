// Writing a file so that readers see either the old contents or the new, never a torn mix.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace gbl::ui {

// Writes `contents` to a temporary file in the destination's directory, flushes it to the disk
// (fsync), then renames it over `path` and syncs the directory. On any failure the temporary
// file is removed, `path` keeps its previous contents, and one sentence naming the file and
// the reason is returned.
std::optional<std::string> writeFileAtomically(std::string const& path, std::string_view contents);

// Reads a whole file; nullopt with a sentence naming the file when it cannot be read.
std::optional<std::string> readWholeFile(std::string const& path, std::string* error);

}  // namespace gbl::ui
