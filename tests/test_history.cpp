// test_history.cpp - undo and redo of hidden parts and section planes
// (app/viewer/state/history.h): steps come back exactly, a change held by a widget is one step when
// it settles, a new step forgets redo, and a reset forgets all.
#include <gtest/gtest.h>

#include "app/viewer/state/history.h"

namespace {

app::ShownState hiding(std::initializer_list<uint32_t> ids, bool section = false) {
    app::ShownState s{scene::PartSet(64), {}};
    for (uint32_t id : ids) s.hidden.insert(id);
    if (section) s.section.add(scene::axisPlane(0, 1.5f));
    return s;
}

TEST(History, UndoAndRedoRestoreExactly) {
    app::History h;
    h.reset(hiding({}));
    EXPECT_FALSE(h.undo());
    EXPECT_TRUE(h.observe(hiding({3, 4}), true));
    EXPECT_FALSE(h.observe(hiding({3, 4}), true)); // unchanged: no step
    EXPECT_TRUE(h.observe(hiding({3, 4}, true), true));
    EXPECT_EQ(h.undoSteps(), 2u);
    EXPECT_EQ(h.undo(), hiding({3, 4}));
    EXPECT_EQ(h.undo(), hiding({}));
    EXPECT_FALSE(h.undo());
    EXPECT_EQ(h.redo(), hiding({3, 4}));
    EXPECT_EQ(h.redo(), hiding({3, 4}, true));
    EXPECT_FALSE(h.redo());
}

TEST(History, AHeldChangeIsOneStepWhenItSettles) {
    app::History h;
    h.reset(hiding({}));
    app::ShownState s = hiding({}, true);
    for (float offset : {0.1f, 0.2f, 0.3f}) { // a slider dragged over three frames
        s.section.planes[0].offset = offset;
        EXPECT_FALSE(h.observe(s, false));
    }
    EXPECT_TRUE(h.observe(s, true)); // released
    EXPECT_EQ(h.undoSteps(), 1u);
    EXPECT_EQ(h.undo(), hiding({}));
}

TEST(History, ANewStepForgetsRedoAndResetForgetsAll) {
    app::History h;
    h.reset(hiding({}));
    h.observe(hiding({1}), true);
    h.undo();
    EXPECT_EQ(h.redoSteps(), 1u);
    h.observe(hiding({2}), true);
    EXPECT_EQ(h.redoSteps(), 0u);
    h.reset(hiding({}));
    EXPECT_EQ(h.undoSteps(), 0u);
    EXPECT_FALSE(h.undo());
}

TEST(History, KeepsItsLimit) {
    app::History h;
    h.reset(hiding({}));
    for (uint32_t i = 0; i < app::History::limit + 20; ++i) h.observe(hiding({i % 64, 63}), true);
    EXPECT_EQ(h.undoSteps(), app::History::limit);
}

std::string shown(const app::ShownState& state) {
    util::JsonWriter json;
    json.beginObject();
    app::shownMembers(json, state);
    return json.endObject().text();
}

TEST(History, ShownMembersNameTheSet) {
    const std::string a = shown(hiding({1, 2})), b = shown(hiding({1, 3}));
    EXPECT_NE(a, b); // same count, other parts
    EXPECT_EQ(a.substr(0, 27), "{\"hidden\":2,\"hidden_hash\":\"");
    EXPECT_EQ(a.size(), 27 + 16 + 18u); // 16 hex digits, then ","section":false}
    EXPECT_NE(shown(hiding({1}, true)).find("\"section\":true}"), std::string::npos);
}

} // namespace
