// test_visibility_tint.cpp - the Visibility section's tint by visibility (visibility_tint.h):
// never-seen parts in their own colour, the ramp's ends at the least and most seen parts,
// the ramp rising with the pixels, and parts the census could not see left untouched.
#include <gtest/gtest.h>

#include <glm/gtc/packing.hpp>

#include "app/viewer/state/visibility_tint.h"

namespace {

glm::ivec4 bytes(uint32_t rgba) {
    return glm::ivec4(glm::round(glm::unpackUnorm4x8(rgba) * 255.0f));
}

// Parts 0..4 seen with these pixels, 5 never seen, 6 neither (hidden or without triangles).
scene::Census census() {
    scene::Census c;
    c.views = 4;
    c.width = c.height = 64;
    for (uint64_t pixels : {1ull, 10ull, 1000ull, 100000ull, 500ull, 0ull, 0ull})
        c.parts.push_back({pixels, pixels ? 1u : 0u, uint32_t(pixels)});
    return c;
}

TEST(VisibilityTint, NeverSeenPartsTakeAColourOfTheirOwnAndUncountedOnesNone) {
    scene::PartSet never(7);
    never.insert(5);
    const std::vector<uint32_t> tint = app::visibilityTint(census(), never);
    ASSERT_EQ(tint.size(), 7u);
    EXPECT_EQ(tint[5], app::neverSeenTint);
    EXPECT_EQ(bytes(tint[5]), glm::ivec4(255, 0, 255, app::tintStrength));
    EXPECT_EQ(tint[6], 0u) << "a part the census could not see is left as it is";
    for (uint32_t id = 0; id < 5; ++id) {
        EXPECT_NE(tint[id], app::neverSeenTint) << id;
        EXPECT_EQ(bytes(tint[id]).a, app::tintStrength) << id;
    }
    // No point of the ramp is the never-seen colour, nor close to it.
    for (int i = 0; i <= 1000; ++i) {
        const glm::ivec4 c = bytes(app::tintRamp(i / 1000.0));
        EXPECT_FALSE(c.r > 200 && c.g < 60 && c.b > 200) << i;
    }
}

TEST(VisibilityTint, TheRampRunsFromBlueAtTheLeastToRedAtTheMostSeen) {
    EXPECT_EQ(bytes(app::tintRamp(0.0)), glm::ivec4(0, 0, 255, app::tintStrength));
    EXPECT_EQ(bytes(app::tintRamp(1.0)), glm::ivec4(255, 0, 0, app::tintStrength));
    const std::vector<uint32_t> tint = app::visibilityTint(census(), scene::PartSet(7));
    EXPECT_EQ(tint[3], app::tintRamp(1.0)) << "the census's largest part is red";
    EXPECT_DOUBLE_EQ(app::tintRampPosition(100000, 100000), 1.0);
    EXPECT_DOUBLE_EQ(app::tintRampPosition(0, 100000), 0.0);
    // One pixel of 100000 sits low on the log scale: the blue end's first segment.
    EXPECT_LT(app::tintRampPosition(1, 100000), 0.1);
    const glm::ivec4 least = bytes(tint[0]);
    EXPECT_EQ(least.r, 0);
    EXPECT_GT(least.b, 250);
}

TEST(VisibilityTint, MorePixelsNeverMoveAPartTowardsBlue) {
    const uint64_t largest = 100000;
    double lastT = -1.0;
    int lastRedOverBlue = -256;
    for (uint64_t pixels = 0; pixels <= largest; pixels = pixels * 3 / 2 + 1) {
        const double t = app::tintRampPosition(pixels, largest);
        EXPECT_GT(t, lastT) << pixels;
        const glm::ivec4 c = bytes(app::tintRamp(t));
        EXPECT_GE(c.r - c.b, lastRedOverBlue) << pixels;
        lastT = t;
        lastRedOverBlue = c.r - c.b;
    }
    // Along the ramp, hue moves one way: blue falls before red rises, green peaks between.
    const std::vector<uint32_t> tint = app::visibilityTint(census(), scene::PartSet(7));
    EXPECT_LT(bytes(tint[1]).r - bytes(tint[1]).b, bytes(tint[4]).r - bytes(tint[4]).b);
    EXPECT_LT(bytes(tint[4]).r - bytes(tint[4]).b, bytes(tint[3]).r - bytes(tint[3]).b);
}

} // namespace
