// test_screenshot_path.cpp - where F12 writes (app/viewer/window/screenshot_path.h): XDG_PICTURES_DIR
// from the environment or user-dirs.dirs, else ~/Pictures, else the current folder; a name
// with the date and time that never overwrites.
#include <fstream>
#include <map>

#include <gtest/gtest.h>

#include "app/viewer/window/screenshot_path.h"

namespace fs = std::filesystem;

namespace {

struct ScreenshotPath : ::testing::Test {
    fs::path home = fs::temp_directory_path() / ("idview-shot-" + std::to_string(::getpid()));
    std::map<std::string, std::string> vars{{"HOME", home.string()}};
    app::Environment env = [this](const char* name) -> std::optional<std::string> {
        const auto it = vars.find(name);
        if (it == vars.end()) return std::nullopt;
        return it->second;
    };
    void SetUp() override { fs::create_directories(home); }
    void TearDown() override { fs::remove_all(home); }
};

TEST_F(ScreenshotPath, FallsBackFromUserDirsToPicturesToHere) {
    EXPECT_EQ(app::picturesFolder(env), fs::path("."));
    fs::create_directories(home / "Pictures");
    EXPECT_EQ(app::picturesFolder(env), home / "Pictures");
    fs::create_directories(home / ".config");
    fs::create_directories(home / "Bilder");
    std::ofstream(home / ".config/user-dirs.dirs")
        << "# written by xdg-user-dirs-update\nXDG_PICTURES_DIR=\"$HOME/Bilder\"\n";
    EXPECT_EQ(app::picturesFolder(env), home / "Bilder");
    vars["XDG_PICTURES_DIR"] = (home / "missing").string(); // not a folder: passed over
    EXPECT_EQ(app::picturesFolder(env), home / "Bilder");
    vars["XDG_PICTURES_DIR"] = (home / "Pictures").string();
    EXPECT_EQ(app::picturesFolder(env), home / "Pictures");
}

TEST_F(ScreenshotPath, NamedByTimeAndNeverOverwrites) {
    std::tm t{};
    t.tm_year = 2026 - 1900, t.tm_mon = 10, t.tm_mday = 26, t.tm_hour = 9, t.tm_min = 5,
    t.tm_sec = 7, t.tm_isdst = -1;
    const std::time_t when = std::mktime(&t); // local time, as the name is
    const fs::path first = app::screenshotPath(home, when);
    EXPECT_EQ(first, home / "idview-20261126-090507.png");
    std::ofstream(first) << "x";
    EXPECT_EQ(app::screenshotPath(home, when), home / "idview-20261126-090507-2.png");
}

} // namespace
