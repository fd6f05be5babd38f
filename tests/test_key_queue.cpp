// test_key_queue.cpp - key events held for Dear ImGui 1.86 (app/viewer/window/key_queue.h): a key
// pressed and released between two frames shows as down for one frame, then up; a chord
// (Ctrl+A) keeps its modifier down while its key goes down; a key struck twice shows twice.
#include <gtest/gtest.h>

#include "app/viewer/window/key_queue.h"

namespace {

constexpr int enter = 257, ctrl = 341, a = 65, backspace = 259;

app::KeyEvent press(int key) {
    return {key, 0, true, 0};
}
app::KeyEvent release(int key) {
    return {key, 0, false, 0};
}

} // namespace

TEST(KeyQueue, APressAndReleaseInOneFrameSpanTwoFrames) {
    app::KeyQueue queue;
    queue.push(press(enter));
    queue.push(release(enter));
    EXPECT_EQ(queue.takeFrame(), std::vector{press(enter)}); // the frame sees Enter down
    EXPECT_EQ(queue.takeFrame(), std::vector{release(enter)});
    EXPECT_TRUE(queue.takeFrame().empty());
    EXPECT_TRUE(queue.empty());
}

TEST(KeyQueue, AChordKeepsItsModifierDownWithItsKey) {
    app::KeyQueue queue;
    for (const app::KeyEvent& e : {press(ctrl), press(a), release(a), release(ctrl)}) queue.push(e);
    EXPECT_EQ(queue.takeFrame(), (std::vector{press(ctrl), press(a)}));
    EXPECT_EQ(queue.takeFrame(), (std::vector{release(a), release(ctrl)}));
}

TEST(KeyQueue, AKeyStruckTwiceIsDownInTwoFrames) {
    app::KeyQueue queue;
    for (int i = 0; i < 2; ++i) {
        queue.push(press(backspace));
        queue.push(release(backspace));
    }
    int downFrames = 0;
    for (int frame = 0; frame < 6; ++frame) {
        const auto events = queue.takeFrame();
        EXPECT_LE(events.size(), 1u); // never two changes of one key in a frame
        if (!events.empty() && events[0].down) ++downFrames;
    }
    EXPECT_EQ(downFrames, 2);
    EXPECT_TRUE(queue.empty());
}

TEST(KeyQueue, EventsOfOtherKeysWaitBehindAStalledOne) {
    // Order is kept: Enter's release and the A after it both wait for the next frame.
    app::KeyQueue queue;
    for (const app::KeyEvent& e : {press(enter), release(enter), press(a)}) queue.push(e);
    EXPECT_EQ(queue.takeFrame(), std::vector{press(enter)});
    EXPECT_EQ(queue.takeFrame(), (std::vector{release(enter), press(a)}));
}
