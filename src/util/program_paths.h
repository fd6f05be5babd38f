// program_paths.h - where the running idview finds its files: its shaders and default model
// (beside it in a build folder, in share/idview once installed, else in the source tree it was
// built from) and its helper programs (beside it, or libexec/idview once installed).
#pragma once

#include <filesystem>

namespace util {

// The folder of the running program (/proc/self/exe); empty where it cannot be read.
std::filesystem::path programDir();

// Where an installed idview keeps its helper programs (idview-load-worker): the libexec
// folder relative to programDir(), as `cmake --install` lays it out (bin/../libexec/idview).
std::filesystem::path installedHelperDir();

// The first copy of one of idview's data files, `relative` to a data root ("shaders/shared.h",
// "assets/default.glb"): beside the program, in the installed data folder relative to it
// (bin/../share/idview), then the source tree. The installed folder comes before the source
// tree so an installed idview reads its own copy even where its source tree is still there.
// Where none exists, the source tree's path (so an error names where it was looked for).
std::filesystem::path dataPath(const std::filesystem::path& relative);

} // namespace util
