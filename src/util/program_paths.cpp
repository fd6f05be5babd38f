// program_paths.cpp - the running program's folder and the install layout relative to it;
// IDVIEW_DATA_FROM_BIN and IDVIEW_HELPERS_FROM_BIN come from cmake/install.cmake.
#include "util/program_paths.h"

#include <system_error>

namespace util {

std::filesystem::path programDir() {
    std::error_code failed;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", failed);
    return failed ? std::filesystem::path() : self.parent_path();
}

std::filesystem::path installedHelperDir() {
    const std::filesystem::path dir = programDir();
    return dir.empty() ? dir : (dir / IDVIEW_HELPERS_FROM_BIN).lexically_normal();
}

std::filesystem::path dataPath(const std::filesystem::path& relative) {
    // The source tree: the folder above its assets/ (IDVIEW_SOURCE_ASSET_DIR, CMakeLists.txt).
    const std::filesystem::path source =
        std::filesystem::path(IDVIEW_SOURCE_ASSET_DIR).parent_path() / relative;
    const std::filesystem::path dir = programDir();
    if (dir.empty()) return source;
    for (const std::filesystem::path& root :
         {dir, (dir / IDVIEW_DATA_FROM_BIN).lexically_normal()}) {
        std::error_code ignored;
        if (std::filesystem::exists(root / relative, ignored)) return root / relative;
    }
    return source;
}

} // namespace util
