// test_selection.cpp - click, box, Esc, hide and isolate semantics of app::Selection, which
// the viewer keeps across technique, mode and MSAA switches because it lives outside the
// renderer; and scene::PartSet, the bitset the GPU reads.
#include <gtest/gtest.h>

#include "app/viewer/state/selection.h"

namespace {

scene::PartSet setOf(uint32_t count, std::initializer_list<uint32_t> ids) {
    scene::PartSet set(count);
    for (uint32_t id : ids) set.insert(id);
    return set;
}

} // namespace

TEST(PartSet, BitsAsTheGpuReadsThem) {
    scene::PartSet s(70);
    s.insert(0);
    s.insert(33);
    s.insert(69);
    s.insert(70); // outside: ignored
    ASSERT_EQ(s.words().size(), 3u);
    EXPECT_EQ(s.words()[0], 1u);
    EXPECT_EQ(s.words()[1], 2u);
    EXPECT_EQ(s.words()[2], 1u << 5);
    EXPECT_EQ(s.ids(), (std::vector<uint32_t>{0, 33, 69}));
    EXPECT_EQ(s.size(), 3u);
    EXPECT_FALSE(s.contains(70));
    s.invert();
    EXPECT_EQ(s.size(), 67u); // bits past the last part stay clear
    EXPECT_FALSE(s.contains(33));
    EXPECT_TRUE(s.contains(68));
    const uint32_t words[3] = {~0u, 0u, ~0u};
    EXPECT_EQ(scene::PartSet(70, words).size(), 32u + 6u);
}

TEST(Selection, ClickSelectsHoveredAndClickOnEmptySpaceClears) {
    app::Selection s;
    s.reset(100);
    s.hover(42u);
    EXPECT_TRUE(s.selected().empty());
    s.click();
    EXPECT_EQ(s.primary(), 42u);
    EXPECT_EQ(s.selected().ids(), std::vector<uint32_t>{42});
    s.hover(7u); // moving on does not change the selection
    EXPECT_EQ(s.primary(), 42u);
    s.hover(std::nullopt);
    s.click();
    EXPECT_FALSE(s.primary().has_value());
    EXPECT_TRUE(s.selected().empty());
}

TEST(Selection, BoxReplacesAddsAndRemoves) {
    app::Selection s;
    s.reset(100);
    s.select(setOf(100, {1, 2, 3}), app::SelectMode::Replace);
    EXPECT_EQ(s.selected().ids(), (std::vector<uint32_t>{1, 2, 3}));
    EXPECT_FALSE(s.primary().has_value()); // several: no single part to detail
    s.select(setOf(100, {3, 9}), app::SelectMode::Add);
    EXPECT_EQ(s.selected().ids(), (std::vector<uint32_t>{1, 2, 3, 9}));
    s.select(setOf(100, {1, 2, 3, 50}), app::SelectMode::Remove);
    EXPECT_EQ(s.selected().ids(), std::vector<uint32_t>{9});
    EXPECT_EQ(s.primary(), 9u); // one left: the panel details it
    s.select(setOf(100, {5}), app::SelectMode::Replace);
    EXPECT_EQ(s.selected().ids(), std::vector<uint32_t>{5});
}

TEST(Selection, EscapeClearsAndSaysWhetherThereWasOne) {
    app::Selection s;
    s.reset(10);
    s.hover(3u);
    s.click();
    EXPECT_TRUE(s.escape()); // consumed: cleared the selection
    EXPECT_TRUE(s.selected().empty());
    EXPECT_FALSE(s.escape()); // nothing selected: Esc had nothing to cancel (commands.h)
    s.hover(5u);
    s.click();
    s.reset(10);
    EXPECT_FALSE(s.hovered().has_value());
    EXPECT_TRUE(s.selected().empty());
}

TEST(Selection, HideIsolateAndShowAll) {
    app::Selection s;
    s.reset(8);
    s.select(setOf(8, {1, 2}), app::SelectMode::Replace);
    s.hideSelected();
    EXPECT_EQ(s.hidden().ids(), (std::vector<uint32_t>{1, 2}));
    EXPECT_TRUE(s.selected().empty()); // hidden parts are not selected any more
    s.select(setOf(8, {5}), app::SelectMode::Replace);
    s.isolateSelected();
    EXPECT_EQ(s.hidden().ids(), (std::vector<uint32_t>{0, 1, 2, 3, 4, 6, 7}));
    EXPECT_EQ(s.selected().ids(), std::vector<uint32_t>{5});
    s.escape();
    s.isolateSelected(); // nothing selected: nothing changes
    EXPECT_EQ(s.hidden().size(), 7u);
    s.showAll();
    EXPECT_TRUE(s.hidden().empty());
}

// The hovered B-rep edge: a click while one is hovered selects it with its part, a click away
// from every edge leaves none; a box, Esc, hiding its part and a new scene clear it.
TEST(Selection, AClickSelectsTheHoveredEdgeAndEscOrANewSceneClearsIt) {
    app::Selection s;
    s.reset(10);
    s.hover(3);
    s.hoverEdge(scene::EdgeRef{3, 7});
    EXPECT_EQ(s.hoveredEdge(), (scene::EdgeRef{3, 7}));
    EXPECT_FALSE(s.selectedEdge());
    s.click();
    EXPECT_EQ(s.selectedEdge(), (scene::EdgeRef{3, 7}));
    EXPECT_TRUE(s.selected().contains(3));
    s.hoverEdge(std::nullopt);
    s.click();
    EXPECT_FALSE(s.selectedEdge());
    s.hoverEdge(scene::EdgeRef{3, 2});
    s.click();
    EXPECT_TRUE(s.escape());
    EXPECT_FALSE(s.selectedEdge());
    s.click();
    s.select(setOf(10, {1, 2}), app::SelectMode::Replace);
    EXPECT_FALSE(s.selectedEdge());
    s.click();
    s.hide(setOf(10, {3}));
    EXPECT_FALSE(s.selectedEdge());
    s.click();
    s.reset(10);
    EXPECT_FALSE(s.selectedEdge());
    EXPECT_FALSE(s.hoveredEdge());
}
