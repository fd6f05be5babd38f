// test_file_browser.cpp - the panel's file browser (app/viewer/state/file_browser.h) over a folder
// tree made for the test: what it lists and in which order, the filter, the highlight and the
// arrows, entering folders, choosing a model, typed paths and the recent folders.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "app/viewer/state/file_browser.h"

namespace fs = std::filesystem;

namespace {

class FileBrowserTest : public ::testing::Test {
  protected:
    void SetUp() override {
        root = fs::temp_directory_path() / ("idview-browser-" + std::to_string(getpid()));
        fs::remove_all(root);
        for (const char* folder : {"Parts", "assemblies", ".hidden", "assemblies/deep"})
            fs::create_directories(root / folder);
        for (const char* file : {"b.STEP", "a.glb", "notes.txt", "Z.stl", "c.brep", ".x.glb",
                                 "assemblies/deep/pump.step", "picture.png"})
            std::ofstream(root / file) << "x";
    }
    void TearDown() override { fs::remove_all(root); }
    static std::vector<std::string> names(const app::FileBrowser& browser) {
        std::vector<std::string> out;
        for (const auto& entry : browser.shown())
            out.push_back(entry.name + (entry.folder ? "/" : ""));
        return out;
    }
    fs::path root;
};

TEST_F(FileBrowserTest, ListsFoldersThenModelFilesByNameWithoutHiddenOrOtherFiles) {
    app::FileBrowser browser(root.string(), {});
    EXPECT_EQ(browser.folder(), root.string());
    EXPECT_EQ(names(browser), (std::vector<std::string>{"../", "assemblies/", "Parts/", "a.glb",
                                                        "b.STEP", "c.brep", "Z.stl"}));
    EXPECT_EQ(browser.shown()[browser.highlighted()].name, "assemblies"); // below ".."
    EXPECT_TRUE(browser.problem().empty());
}

TEST_F(FileBrowserTest, FilterKeepsNamesHoldingItInAnyCaseAndArrowsStopAtTheEnds) {
    app::FileBrowser browser(root.string(), {});
    browser.filterText() = "S";
    browser.filterChanged();
    EXPECT_EQ(names(browser),
              (std::vector<std::string>{"assemblies/", "Parts/", "b.STEP", "Z.stl"}));
    EXPECT_EQ(browser.highlighted(), 0u);
    browser.move(1);
    browser.move(5);
    EXPECT_EQ(browser.shown()[browser.highlighted()].name, "Z.stl");
    browser.move(-9);
    EXPECT_EQ(browser.highlighted(), 0u);
    browser.filterText() = "nothing like it";
    browser.filterChanged();
    EXPECT_TRUE(browser.shown().empty());
    browser.move(1); // nothing to move over
    EXPECT_FALSE(browser.activate().open);
}

TEST_F(FileBrowserTest, EnteringFoldersGoingUpAndChoosingAModel) {
    app::FileBrowser browser(root.string(), {});
    EXPECT_FALSE(browser.activate().open); // "assemblies", highlighted
    EXPECT_EQ(browser.folder(), (root / "assemblies").string());
    browser.filterText() = "deep";
    browser.filterChanged();
    EXPECT_FALSE(browser.activate().open);
    EXPECT_EQ(browser.folder(), (root / "assemblies" / "deep").string());
    EXPECT_TRUE(browser.filterText().empty()); // a new folder starts unfiltered
    const auto chosen = browser.activate();
    ASSERT_TRUE(chosen.open);
    EXPECT_EQ(*chosen.open, (root / "assemblies" / "deep" / "pump.step").string());
    browser.highlight(0); // ".."
    EXPECT_FALSE(browser.activate().open);
    EXPECT_EQ(browser.folder(), (root / "assemblies").string());
    browser.up();
    EXPECT_EQ(browser.folder(), root.string());
}

TEST_F(FileBrowserTest, TypedPathsGoToFoldersOpenFilesOrSayWhyNot) {
    app::FileBrowser browser("/", {});
    EXPECT_NE(browser.shown().empty() ? "" : browser.shown()[0].name, ".."); // the root
    browser.filterText() = (root / "assemblies").string();
    browser.filterChanged();
    EXPECT_FALSE(browser.activate().open);
    EXPECT_EQ(browser.folder(), (root / "assemblies").string());
    // A typed file opens whatever its name: its reader says if it is no model.
    browser.filterText() = (root / "notes.txt").string();
    browser.filterChanged();
    const auto file = browser.activate();
    ASSERT_TRUE(file.open);
    EXPECT_EQ(*file.open, (root / "notes.txt").string());
    browser.filterText() = (root / "missing.step").string();
    browser.filterChanged();
    const auto missing = browser.activate();
    EXPECT_FALSE(missing.open);
    EXPECT_EQ(missing.problem, (root / "missing.step").string() + ": no such file or folder");
}

TEST_F(FileBrowserTest, MissingFolderOpensAtItsNearestParentAndRecentFoldersComeOnce) {
    const std::vector<std::string> recent = {(root / "a.glb").string(), (root / "b.STEP").string(),
                                             (root / "assemblies/deep/pump.step").string(),
                                             "/no/such/folder/x.glb"};
    app::FileBrowser browser((root / "gone" / "deeper").string(), recent);
    EXPECT_EQ(browser.folder(), root.string());
    EXPECT_EQ(browser.recentFolders(),
              (std::vector<std::string>{root.string(), (root / "assemblies/deep").string()}));
}

TEST_F(FileBrowserTest, NewsSaysEachChangeOnce) {
    app::FileBrowser browser(root.string(), {});
    const auto first = browser.news();
    ASSERT_TRUE(first);
    EXPECT_EQ(*first, root.string() + ": 7 of 7 entries: ../, assemblies/, Parts/, a.glb, "
                                      "b.STEP, c.brep, Z.stl; highlighted assemblies");
    EXPECT_FALSE(browser.news());
    browser.move(1);
    const auto moved = browser.news();
    ASSERT_TRUE(moved);
    EXPECT_NE(moved->find("highlighted Parts"), std::string::npos);
}

} // namespace
