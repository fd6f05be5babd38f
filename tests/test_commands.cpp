// test_commands.cpp - the viewer's command table (app/viewer/commands.h): the help overlay
// lists every binding the key dispatch knows, no chord runs two commands, and the keys this
// issue moved are where the help says (F1 help, F9 panel, Esc cancels, Ctrl+Q quits); and
// the empty view's reasons (overlays.h).
#include <set>
#include <utility>

#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/viewer/commands.h"
#include "app/viewer/overlays.h"

namespace {

// Each row's keys and description appear on one line of the help, in the table's order.
TEST(Commands, HelpListsEveryBindingOfTheTable) {
    const auto& rows = app::commands();
    const auto lines = app::helpLines();
    ASSERT_EQ(lines.size(), rows.size());
    size_t keys = 0;
    for (size_t i = 0; i < rows.size(); ++i) {
        const app::Command& row = rows[i];
        SCOPED_TRACE(row.name);
        EXPECT_EQ(lines[i].description, row.description);
        EXPECT_FALSE(lines[i].description.empty());
        EXPECT_TRUE(row.keys.empty() != (row.mouse == nullptr)) << "a key or a gesture, not both";
        EXPECT_TRUE(row.keys.empty() == (row.run == nullptr)) << "a key command runs something";
        if (row.mouse) {
            EXPECT_NE(lines[i].keys.find(row.mouse), std::string::npos);
        }
        for (const app::Chord& chord : row.keys) {
            ++keys;
            EXPECT_NE(lines[i].keys.find(app::chordText(chord)), std::string::npos)
                << app::chordText(chord) << " missing from '" << lines[i].keys << "'";
            // The dispatch finds this very row for the chord.
            EXPECT_EQ(app::commandOfKey(chord.key, chord.mods), &row);
        }
    }
    EXPECT_GT(keys, 30u);
}

TEST(Commands, NoTwoRowsShareAChord) {
    std::set<std::pair<int, int>> seen;
    std::set<std::string> names, texts;
    for (const app::Command& row : app::commands()) {
        EXPECT_TRUE(names.insert(row.name).second) << row.name;
        for (const app::Chord& chord : row.keys) {
            EXPECT_TRUE(seen.insert({chord.key, chord.mods}).second)
                << app::chordText(chord) << " is bound twice";
            EXPECT_TRUE(texts.insert(app::chordText(chord)).second)
                << app::chordText(chord) << ": two chords read alike";
        }
    }
}

TEST(Commands, KeysOfThisIssue) {
    auto name = [](int key, int mods) {
        const app::Command* c = app::commandOfKey(key, mods);
        return std::string(c ? c->name : "none");
    };
    EXPECT_EQ(name(GLFW_KEY_F1, 0), "help");
    EXPECT_EQ(name(GLFW_KEY_SLASH, GLFW_MOD_SHIFT), "help");
    EXPECT_EQ(name(GLFW_KEY_F9, 0), "toggle-panel");
    EXPECT_EQ(name(GLFW_KEY_ESCAPE, 0), "cancel");
    EXPECT_EQ(name(GLFW_KEY_Q, GLFW_MOD_CONTROL), "quit");
    EXPECT_EQ(name(GLFW_KEY_Q, 0), "none");
    EXPECT_EQ(name(GLFW_KEY_Z, GLFW_MOD_CONTROL), "undo");
    EXPECT_EQ(name(GLFW_KEY_Z, GLFW_MOD_CONTROL | GLFW_MOD_SHIFT), "redo");
    EXPECT_EQ(name(GLFW_KEY_Y, GLFW_MOD_CONTROL), "redo");
    EXPECT_EQ(name(GLFW_KEY_F12, 0), "screenshot");
    EXPECT_EQ(name(GLFW_KEY_O, GLFW_MOD_CONTROL), "open");
    EXPECT_EQ(name(GLFW_KEY_O, 0), "projection");
    // Caps Lock and Num Lock do not change what a key does; an extra modifier does.
    EXPECT_EQ(name(GLFW_KEY_H, GLFW_MOD_CAPS_LOCK), "hide");
    EXPECT_EQ(name(GLFW_KEY_KP_7, GLFW_MOD_NUM_LOCK), "view-top");
    EXPECT_EQ(name(GLFW_KEY_H, GLFW_MOD_ALT), "none");
    // The panel's hide, isolate and show all buttons run these rows by name (frame.cpp).
    for (const char* button : {"hide", "isolate", "show-all"})
        EXPECT_NE(app::findCommand(button), nullptr) << button;
}

TEST(Commands, ChordText) {
    EXPECT_EQ(app::chordText({GLFW_KEY_Z, GLFW_MOD_CONTROL | GLFW_MOD_SHIFT}), "Ctrl+Shift+Z");
    EXPECT_EQ(app::chordText({GLFW_KEY_SLASH, GLFW_MOD_SHIFT}), "?");
    EXPECT_EQ(app::chordText({GLFW_KEY_KP_1, GLFW_MOD_CONTROL}), "Ctrl+Num 1");
    EXPECT_EQ(app::chordText({GLFW_KEY_F12, 0}), "F12");
    EXPECT_EQ(app::chordText({GLFW_KEY_ESCAPE, 0}), "Esc");
}

// Why the view is empty: the hidden set and an empty model need no count; the section and
// an empty view only a fresh count of zero (nullopt: none yet).
TEST(Commands, WhyTheViewIsEmpty) {
    auto event = [](uint32_t parts, uint32_t hidden, bool section,
                    std::optional<uint32_t> visible) {
        const auto why = app::whyEmpty(parts, hidden, section, visible);
        return why ? why->event : std::string("drawn");
    };
    EXPECT_EQ(event(0, 0, false, std::nullopt), "no parts");
    EXPECT_EQ(event(12, 12, true, 0), "all hidden");
    EXPECT_EQ(app::whyEmpty(12, 12, false, 0)->message,
              "All 12 parts are hidden - Shift+H shows them");
    EXPECT_EQ(event(12, 3, true, 0), "section");
    EXPECT_EQ(event(12, 3, false, 0), "out of view");
    EXPECT_EQ(event(12, 3, true, std::nullopt), "drawn");
    EXPECT_EQ(event(12, 3, true, 5), "drawn");
}

} // namespace
