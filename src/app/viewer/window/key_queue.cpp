// key_queue.cpp - one frame's worth of key events for Dear ImGui.
#include "app/viewer/window/key_queue.h"

#include <algorithm>

namespace app {

std::vector<KeyEvent> KeyQueue::takeFrame() {
    std::vector<KeyEvent> frame;
    while (!events_.empty()) {
        const KeyEvent& next = events_.front();
        const bool changed = std::any_of(frame.begin(), frame.end(),
                                         [&](const KeyEvent& e) { return e.key == next.key; });
        if (changed) break; // its second change this frame would hide the first
        frame.push_back(next);
        events_.pop_front();
    }
    return frame;
}

} // namespace app
