// test_progressive.cpp - what the viewer takes of a CAD file shown as it loads
// (app/viewer/state/progressive.h): only the newest partial scene waits in the slot, uploads are
// spaced by their cost, and the panel's words for how far the load is and what it lacks.
#include <gtest/gtest.h>

#include "app/viewer/state/progressive.h"
#include "scene/bounds.h"

namespace {

scene::CadPartial partialOf(uint32_t ready, uint32_t lost, uint32_t total) {
    scene::CadPartial partial;
    partial.solidsReady = ready;
    partial.solidsLost = lost;
    partial.solidsTotal = total;
    return partial;
}

} // namespace

TEST(Progressive, TheSlotKeepsOnlyTheNewestPartial) {
    app::PartialSlot slot;
    EXPECT_FALSE(slot.take().has_value());
    slot.put(partialOf(1, 0, 8));
    slot.put(partialOf(3, 0, 8)); // the first was not taken: dropped
    const auto taken = slot.take();
    ASSERT_TRUE(taken.has_value());
    EXPECT_EQ(taken->solidsReady, 3u);
    EXPECT_FALSE(slot.take().has_value());
}

TEST(Progressive, UploadsWaitForTheirShareOfTime) {
    using Clock = app::UploadPacer::Clock;
    using std::chrono::milliseconds;
    app::UploadPacer pacer;
    const Clock::time_point start{};
    EXPECT_TRUE(pacer.due(start));
    // A cheap upload waits the least gap; a dear one its cost over its share.
    pacer.uploaded(start, start + milliseconds(10));
    EXPECT_FALSE(pacer.due(start + milliseconds(500)));
    EXPECT_TRUE(pacer.due(start + milliseconds(10) +
                          milliseconds(int(app::UploadPacer::minGapSeconds * 1000))));
    pacer.uploaded(start, start + milliseconds(300));
    const auto gap = milliseconds(int(300 / app::UploadPacer::costShare));
    EXPECT_FALSE(pacer.due(start + milliseconds(300) + gap - milliseconds(1)));
    EXPECT_TRUE(pacer.due(start + milliseconds(300) + gap));
}

TEST(Progressive, LinesSayWhatIsShownAndMissing) {
    scene::CadPartial partial = partialOf(5, 1, 8);
    partial.bytesTotal = 3'000'000;
    partial.bytesDone = 1'800'000;
    EXPECT_EQ(app::shownLine(partial), "5 of 8 solids shown, 1 lost, 1.2 MB left");
    EXPECT_EQ(app::missingLine(partial), "3 of 8 solids missing");
    EXPECT_EQ(app::shownLine(partialOf(8, 0, 8)), "8 of 8 solids shown");
}

TEST(Progressive, TheExtentHoldsEveryBoxButEmptyOnes) {
    const scene::Bounds a{{0, 0, 0}, {1, 1, 1}}, b{{-2, 3, 0}, {-1, 4, 5}};
    const scene::Bounds all = app::extentOf({a, scene::emptyBounds(), b});
    EXPECT_EQ(all.min, glm::dvec3(-2, 0, 0));
    EXPECT_EQ(all.max, glm::dvec3(1, 4, 5));
}
