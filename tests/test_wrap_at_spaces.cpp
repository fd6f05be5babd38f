// test_wrap_at_spaces.cpp - the panel's lines of numbers wrap only between words
// (panel_widgets.h wrapAtSpaces), never inside "-49.99" as ImGui's TextWrapped would after its
// '.', measured here in characters (one pixel each).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/viewer/panel/panel_widgets.h"

namespace {

std::vector<std::string> wrapped(const std::string& text, float width) {
    std::vector<std::string> lines;
    for (std::string_view line :
         app::wrapAtSpaces(text, width, [](std::string_view s) { return float(s.size()); }))
        lines.emplace_back(line);
    return lines;
}

TEST(WrapAtSpaces, BreaksBetweenNumbersOnly) {
    const std::string row = "closest point on A (-49.9999, 12.5, 1000.25)";
    // Every width: each line is whole words of the row, in order, none cut.
    for (float width = 1; width <= 50; ++width) {
        std::string joined;
        for (const std::string& line : wrapped(row, width)) {
            EXPECT_FALSE(line.empty());
            EXPECT_NE(line.front(), ' ');
            EXPECT_NE(line.back(), ' ');
            // A line wider than the width is a single word that fits nowhere.
            if (line.size() > width) {
                EXPECT_EQ(line.find(' '), std::string::npos) << line;
            }
            joined += (joined.empty() ? "" : " ") + line;
        }
        EXPECT_EQ(joined, row) << "width " << width;
    }
    EXPECT_EQ(wrapped(row, 24),
              (std::vector<std::string>{"closest point on A", "(-49.9999, 12.5,", "1000.25)"}));
    EXPECT_EQ(wrapped(row, 100), std::vector<std::string>{row});
}

TEST(WrapAtSpaces, KeepsTheFirstLinesIndent) {
    EXPECT_EQ(wrapped("  at (1, 2, 3)", 9), (std::vector<std::string>{"  at (1,", "2, 3)"}));
    EXPECT_EQ(wrapped("", 10), std::vector<std::string>{""});
}

} // namespace
