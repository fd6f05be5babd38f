// test_data_present.cpp - every file or folder of Debian's test data that a test names is
// installed, in one list (each test whose file is missing fails too, naming the package:
// test_data.h). The paths are read from the tests' own sources, every string literal in them
// that starts with /usr/share/, so a new one is checked without a list to keep.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "test_data.h"

namespace fs = std::filesystem;

namespace {

std::set<std::string> namedDataPaths() {
    const std::regex quoted("\"(/usr/share/[^\"]+)\"");
    std::set<std::string> paths;
    for (const auto& entry : fs::directory_iterator(IDVIEW_TESTS_DIR)) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".cpp" && ext != ".h") continue;
        std::stringstream text;
        text << std::ifstream(entry.path()).rdbuf();
        const std::string s = text.str();
        for (auto it = std::sregex_iterator(s.begin(), s.end(), quoted);
             it != std::sregex_iterator(); ++it)
            paths.insert((*it)[1].str());
    }
    return paths;
}

} // namespace

TEST(TestData, EveryDataFileTheTestsNameIsInstalled) {
    const std::set<std::string> paths = namedDataPaths();
    // Not vacuous: bearing.iges, Motor-c.brep and 2CylinderEngine.glb at least.
    EXPECT_GE(paths.size(), 3u);
    EXPECT_TRUE(paths.count("/usr/share/opencascade/data/iges/bearing.iges"));
    for (const std::string& path : paths)
        EXPECT_TRUE(fs::exists(path)) << testing_support::missingData(path);
}
