// test_data.h - Debian's test data (occt-misc's /usr/share/opencascade/data, assimp-testmodels'
// /usr/share/assimp): a test whose file is missing fails and names the package to install,
// never skips and never leaves its cases out, so that a green run means every test ran.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace testing_support {

// The Debian package that installs what lies under `path`.
inline std::string dataPackage(const std::filesystem::path& path) {
    const std::string text = path.string();
    if (text.rfind("/usr/share/opencascade/", 0) == 0) return "occt-misc";
    if (text.rfind("/usr/share/assimp/", 0) == 0) return "assimp-testmodels";
    return "the package that installs it";
}

// "needs /usr/share/... from Debian's occt-misc: apt-get install occt-misc".
inline std::string missingData(const std::filesystem::path& path) {
    const std::string package = dataPackage(path);
    return "needs " + path.string() + " from Debian's " + package + ": apt-get install " + package +
           " (scripts/setup.sh does)";
}

// `path`, or for a caller that cannot return a failure (a fixture, a helper that returns a
// scene) an exception the test reports with that line.
inline std::string requiredData(const std::filesystem::path& path) {
    if (!std::filesystem::exists(path)) throw std::runtime_error(missingData(path));
    return path.string();
}

} // namespace testing_support

// Fails the test (a fatal failure: the test function returns) when `path` is missing.
#define REQUIRE_DATA(data_path)                                                                    \
    if (const std::filesystem::path required_ = (data_path); !std::filesystem::exists(required_))  \
    FAIL() << testing_support::missingData(required_)
