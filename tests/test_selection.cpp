// test_selection.cpp - click and Esc semantics of app::Selection, which the viewer keeps across
// technique, mode and MSAA switches because it lives outside the renderer.
#include <gtest/gtest.h>

#include "app/viewer/selection.h"

TEST(Selection, ClickSelectsHoveredAndClickOnEmptySpaceClears) {
    app::Selection s;
    s.hover(42u);
    EXPECT_FALSE(s.selected().has_value());
    s.click();
    EXPECT_EQ(s.selected(), 42u);
    s.hover(7u); // moving on does not change the selection
    EXPECT_EQ(s.selected(), 42u);
    s.hover(std::nullopt);
    s.click();
    EXPECT_FALSE(s.selected().has_value());
}

TEST(Selection, EscapeClearsFirstAndOnlyThenMeansClose) {
    app::Selection s;
    s.hover(3u);
    s.click();
    EXPECT_TRUE(s.escape()); // consumed: cleared the selection
    EXPECT_FALSE(s.selected().has_value());
    EXPECT_FALSE(s.escape()); // nothing selected: the viewer may close
    s.hover(5u);
    s.click();
    s.clear();
    EXPECT_FALSE(s.hovered().has_value());
    EXPECT_FALSE(s.selected().has_value());
}
