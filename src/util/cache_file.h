// cache_file.h - what idview's on-disk caches share: the folder they live in, reading a whole
// file, and writing one atomically (a temporary file renamed over it, so that a crash never
// leaves half a file under the file's name). Used by the tessellation cache (cad_cache.h) and
// the pipeline cache (render/pipeline_file.h). Plain C++.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace util {

// $XDG_CACHE_HOME/idview where that variable holds an absolute path (as the XDG base
// directory specification asks), else $HOME/.cache/idview; empty where neither is set.
std::filesystem::path cacheFolder();

// The whole file in one read; nullopt where it cannot be read.
std::optional<std::string> readWholeFile(const std::filesystem::path& file);

// Writes `parts` one after the other as `file`, creating its folder; returns "" or why not.
std::string writeFileAtomically(const std::filesystem::path& file,
                                const std::vector<std::string_view>& parts);

} // namespace util
