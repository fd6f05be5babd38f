// test_kept_view.cpp - what the window keeps between runs beside its settings: its size and
// place as the --size and --window-pos lines (the command line still wins, Reset to defaults
// leaves them), and the viewer. lines of the panel's layout and the recent files
// (app/viewer/state/kept_view.h), read back unchanged, bad ones dropped with one warning each.
#include <gtest/gtest.h>

#include "app/cli.h"
#include "app/cli_values.h"
#include "app/saved_settings.h"
#include "app/viewer/state/kept_view.h"

using app::Options;

namespace {

struct Warnings {
    std::vector<std::string> lines;
    app::Warn warn() {
        return [this](const std::string& line) { lines.push_back(line); };
    }
};

} // namespace

TEST(KeptView, WindowGeometryIsKeptAsFlagsAndTheCommandLineWins) {
    Options o = app::viewerDefaults();
    o.width = 900;
    o.height = 560;
    o.windowPos = std::array<int, 2>{-1200, 40}; // a monitor left of the primary one
    const std::string text = app::savedSettingsText(o.live, app::windowPlace(o));
    EXPECT_NE(text.find("\n--size 900x560\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\n--window-pos -1200,40\n"), std::string::npos) << text;
    Warnings w;
    std::vector<std::string> args = app::savedArgs(text, "t", w.warn());
    EXPECT_TRUE(w.lines.empty());
    const Options back = app::parseArgs(args, app::viewerDefaults());
    EXPECT_EQ(back.width, 900u);
    EXPECT_EQ(back.height, 560u);
    EXPECT_EQ(back.windowPos, o.windowPos);
    args.insert(args.end(), {"--size", "720x450"}); // given when the viewer starts
    EXPECT_EQ(app::parseArgs(args, app::viewerDefaults()).width, 720u);
    // Reset to defaults is about how the scene is drawn, not where the window is.
    app::resetSavedSettings(o.live);
    EXPECT_EQ(o.width, 900u);
    EXPECT_EQ(o.windowPos, (std::array<int, 2>{-1200, 40}));
    // Nothing known: no line.
    EXPECT_EQ(
        app::savedSettingsText(app::viewerDefaults().live, app::windowPlace(app::viewerDefaults()))
            .find("--window-pos"),
        std::string::npos);
}

TEST(KeptView, WindowPosTakesTwoWholeNumbers) {
    EXPECT_EQ(app::parseWindowPos("10,-20"), (std::array<int, 2>{10, -20}));
    for (const char* bad : {"10", "10,", ",5", "1.5,2", "a,b", "1,2,3", "999999,0", ""})
        EXPECT_THROW(app::parseWindowPos(bad), app::UsageError) << bad;
}

TEST(KeptView, PanelAndRecentFilesRoundTrip) {
    app::ViewSettings view;
    view.panelVisible = false;
    view.panelWidth = 512.5f;
    view.recentFiles = {"/models/new.step", "/models/a b.glb", "/models/old.gltf"};
    const std::string text = app::keptViewText(view);
    EXPECT_NE(text.find("viewer.recent = /models/a b.glb\n"), std::string::npos) << text;
    app::ViewSettings back;
    Warnings w;
    app::readKeptView("# a comment\n--msaa 4\n" + text, "viewer.conf", back, w.warn());
    EXPECT_TRUE(w.lines.empty()) << w.lines.front();
    EXPECT_FALSE(back.panelVisible);
    EXPECT_EQ(back.panelWidth, 512.5f);
    EXPECT_EQ(back.recentFiles, view.recentFiles); // newest first, as they were
    // The flag lines skip the viewer's own without a word.
    EXPECT_EQ(app::savedArgs(text + "--msaa 4\n", "viewer.conf", w.warn()),
              (std::vector<std::string>{"--msaa", "4"}));
    EXPECT_TRUE(w.lines.empty());
}

TEST(KeptView, AtMostTenRecentFilesAndBadLinesWarnOnce) {
    std::string text;
    for (int i = 0; i < 12; ++i) text += "viewer.recent = /m/" + std::to_string(i) + ".glb\n";
    text += "viewer.panel = maybe\nviewer.panel-width = 20\nviewer.colour = red\nviewer.panel\n";
    app::ViewSettings view;
    Warnings w;
    app::readKeptView(text, "viewer.conf", view, w.warn());
    ASSERT_EQ(view.recentFiles.size(), app::maxRecentFiles);
    EXPECT_EQ(view.recentFiles.front(), "/m/0.glb");
    EXPECT_TRUE(view.panelVisible); // the bad lines changed nothing
    EXPECT_EQ(view.panelWidth, app::ViewSettings{}.panelWidth);
    ASSERT_EQ(w.lines.size(), 4u);
    EXPECT_EQ(w.lines[0],
              "viewer.conf:13: 'viewer.panel = maybe' expects shown or hidden; ignored");
    EXPECT_EQ(w.lines[1],
              "viewer.conf:14: 'viewer.panel-width = 20' expects a width in pixels; ignored");
    EXPECT_EQ(w.lines[2],
              "viewer.conf:15: 'viewer.colour = red' is not a line the viewer keeps; ignored");
    EXPECT_EQ(w.lines[3], "viewer.conf:16: 'viewer.panel' expects NAME = VALUE; ignored");
}
