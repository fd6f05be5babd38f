// shader_copy.h - a copy of the shader folder that a test edits, to show that a check in the
// shaders matters: the test breaks it there and expects the result to change.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace testing_support {

// A fresh copy of the source shaders in the temporary folder, named after `name`.
inline std::filesystem::path shaderCopy(const std::string& name) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("idview-culling-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::copy(IDVIEW_SOURCE_SHADER_DIR, dir, std::filesystem::copy_options::recursive);
    return dir;
}

// Replaces the first `from` in `path` with `to`; fails the test where there is none.
inline void replaceInFile(const std::filesystem::path& path, const std::string& from,
                          const std::string& to) {
    std::stringstream text;
    text << std::ifstream(path).rdbuf();
    std::string s = text.str();
    const size_t at = s.find(from);
    ASSERT_NE(at, std::string::npos) << from << " not in " << path;
    s.replace(at, from.size(), to);
    std::ofstream(path) << s;
}

} // namespace testing_support
