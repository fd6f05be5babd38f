// test_saved_settings.cpp - the viewer's settings kept between runs (app/saved_settings.h):
// written as flags and read back unchanged, bad lines dropped in one line each, the command
// line winning, Reset to defaults; and the viewer's own defaults and headless-only flags.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "app/cli.h"
#include "app/cli_values.h"
#include "app/saved_settings.h"
#include "render/culling.h"
#include "render/technique.h"

namespace fs = std::filesystem;
using app::Options;

namespace {

// A folder of its own per test, removed afterwards.
struct TempFolder {
    fs::path path = fs::temp_directory_path() /
                    ("idview_saved_" + std::to_string(::getpid()) + "_" +
                     ::testing::UnitTest::GetInstance()->current_test_info()->name());
    TempFolder() { fs::remove_all(path); }
    ~TempFolder() { fs::remove_all(path); }
};

struct Warnings {
    std::vector<std::string> lines;
    app::Warn warn() {
        return [this](const std::string& line) { lines.push_back(line); };
    }
};

// Every kept setting away from its default.
Options changed() {
    Options o = app::viewerDefaults();
    render::PipelineKey& key = o.live.render.pipeline;
    key.technique = render::findTechnique("tri-fs");
    key.mode = render::findDrawMode("push");
    key.msaa = 4;
    o.live.render.clear = render::ClearPath::Compute;
    key.searchBatch = 7;
    key.nsearch = {5, false, 3, 9};
    o.live.render.draws.sortDraws = false;
    o.live.render.shading = {0.3125f, true, true, true};
    o.live.render.edges.on = true;
    o.live.render.edges.width = 2;
    o.live.render.edges.color = app::parseColor("--edge-color", "a0b1c2");
    o.live.render.culling.mode = render::CullMode::Frustum;
    o.live.scene.lodLevels = 4;
    o.live.render.lod.errorPixels = 1.37f;
    o.live.camera.ortho = true;
    return o;
}

} // namespace

// The viewer opens on what README's "Which technique?" recommends; headless does not.
TEST(SavedSettings, ViewerOpensOnTheRecommendedTechnique) {
    const Options viewer = app::viewerDefaults();
    EXPECT_STREQ(viewer.live.render.pipeline.technique->name, "vertex-fs");
    EXPECT_STREQ(viewer.live.render.pipeline.mode->name, "mdi-baseinstance");
    EXPECT_EQ(app::parseArgs(std::vector<std::string>{}).live.render.pipeline.technique,
              &render::defaultTechnique());
    EXPECT_NE(app::usage().find("the viewer opens on vertex-fs"), std::string::npos);
    EXPECT_NE(app::usage().find("the viewer opens on mdi-baseinstance"), std::string::npos);
}

TEST(SavedSettings, HeadlessOnlyFlagsAreNamed) {
    const Options o = app::parseArgs(std::vector<std::string>{
        "--pick", "1,1", "--msaa", "4", "--screenshot", "a.png", "--select-rect", "0,0,2,2"});
    EXPECT_EQ(app::ignoredByViewer(o),
              (std::vector<std::string>{"--screenshot", "--pick", "--select-rect"}));
    EXPECT_TRUE(app::ignoredByViewer(app::parseArgs({"--msaa", "4", "--edges"})).empty());
}

TEST(SavedSettings, RoundTripThroughTheFlagTable) {
    const Options o = changed();
    const std::string text = app::savedSettingsText(o.live, app::windowPlace(o));
    Warnings w;
    const Options back = app::parseArgs(app::savedArgs(text, "t", w.warn()), app::viewerDefaults());
    EXPECT_TRUE(w.lines.empty()) << w.lines.front();
    EXPECT_EQ(back.live.render, o.live.render) << text;
    EXPECT_EQ(back.live.scene.lodLevels, 4u);
    EXPECT_TRUE(back.live.camera.ortho);
    EXPECT_NE(text.find("\n--no-sort-draws\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\n--renderer tri-fs\n"), std::string::npos) << text;
    // The defaults write no setting at all: only the comment line.
    const std::string none =
        app::savedSettingsText(app::viewerDefaults().live, app::windowPlace(app::viewerDefaults()));
    EXPECT_EQ(none.find("\n--"), std::string::npos) << none;
    EXPECT_EQ(none.back(), '\n');
}

TEST(SavedSettings, BadLinesAreDroppedWithOneWarningEach) {
    Warnings w;
    const auto args = app::savedArgs("# kept\n--msaa 4\n--bogus\n--msaa 3\n\ngarbage here\n"
                                     "--screenshot x.png\n  --edges  \n--culling=frustum\n",
                                     "viewer.conf", w.warn());
    EXPECT_EQ(args, (std::vector<std::string>{"--msaa", "4", "--edges", "--culling", "frustum"}));
    ASSERT_EQ(w.lines.size(), 4u);
    EXPECT_EQ(w.lines[0], "viewer.conf:3: '--bogus' is not a setting the viewer keeps; ignored");
    EXPECT_EQ(w.lines[1], "viewer.conf:4: --msaa expects 1, 2, 4 or 8, not 3; ignored");
    EXPECT_EQ(w.lines[2].rfind("viewer.conf:6: 'garbage here'", 0), 0u) << w.lines[2];
    EXPECT_EQ(w.lines[3].rfind("viewer.conf:7: '--screenshot x.png'", 0), 0u) << w.lines[3];
}

TEST(SavedSettings, CommandLineWinsAndNoSavedSettingsIgnoresTheFile) {
    TempFolder folder;
    const std::string path = (folder.path / "idview" / "viewer.conf").string();
    Warnings w;
    // Nothing kept yet: the viewer's defaults.
    EXPECT_EQ(app::viewerOptions({}, path, w.warn()).live.render,
              app::viewerDefaults().live.render);
    app::writeSavedSettings(path, changed().live, app::windowPlace(changed()), w.warn());
    ASSERT_TRUE(w.lines.empty()) << w.lines.front();
    EXPECT_EQ(app::viewerOptions({}, path, w.warn()).live.render, changed().live.render);
    const Options mixed =
        app::viewerOptions({"--msaa", "2", "--renderer", "mesh-fs"}, path, w.warn());
    EXPECT_EQ(mixed.live.render.pipeline.msaa, 2u);
    EXPECT_STREQ(mixed.live.render.pipeline.technique->name, "mesh-fs");
    EXPECT_STREQ(mixed.live.render.pipeline.mode->name, "push"); // kept
    const Options fresh = app::viewerOptions({"--no-saved-settings"}, path, w.warn());
    EXPECT_EQ(fresh.live.render, app::viewerDefaults().live.render);
    EXPECT_FALSE(fresh.savedSettings);
    EXPECT_TRUE(w.lines.empty());
    // Kept settings the command line contradicts (--lod-error against --lod-level) are all
    // left out in one line; the command line is taken as it is.
    const Options level =
        app::viewerOptions({"--lod-levels", "2", "--lod-level", "1"}, path, w.warn());
    ASSERT_EQ(w.lines.size(), 1u);
    EXPECT_NE(w.lines[0].find("do not go with the command line"), std::string::npos);
    EXPECT_EQ(level.live.render, app::viewerDefaults().live.render);
    EXPECT_EQ(level.live.scene.lodLevel, 1u);
    EXPECT_THROW(app::viewerOptions({"--bogus"}, path, w.warn()), app::UsageError);
}

TEST(SavedSettings, ResetPutsBackOnlyTheKeptSettings) {
    Options o = changed();
    o.live.scene.copies = 3;
    o.live.render.draws.visible = 0.5f;
    app::resetSavedSettings(o.live);
    Options want = app::viewerDefaults();
    want.live.render.draws.visible = 0.5f;
    EXPECT_EQ(o.live.render, want.live.render);
    EXPECT_FALSE(o.live.camera.ortho);
    EXPECT_EQ(o.live.scene.lodLevels, 1u);
    EXPECT_EQ(o.live.scene.copies, 3u); // the scene is not a kept setting
}

TEST(SavedSettings, FileLivesUnderXdgConfigHomeElseHome) {
    const std::string oldConfig =
        std::getenv("XDG_CONFIG_HOME") ? std::getenv("XDG_CONFIG_HOME") : "";
    ::setenv("XDG_CONFIG_HOME", "/x/config", 1);
    EXPECT_EQ(app::savedSettingsPath(), "/x/config/idview/viewer.conf");
    ::setenv("XDG_CONFIG_HOME", "", 1);
    ::setenv("HOME", "/home/u", 1);
    EXPECT_EQ(app::savedSettingsPath(), "/home/u/.config/idview/viewer.conf");
    ::setenv("XDG_CONFIG_HOME", oldConfig.c_str(), 1);
}
