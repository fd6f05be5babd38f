// key_queue.h - key presses and releases held for Dear ImGui 1.86, whose GLFW backend keeps
// only whether a key is down when a frame starts: a key pressed and released between two
// frames (a quick Enter at a low frame rate, a script's key) never showed as pressed. Events
// wait here and reach ImGui at most one change per key a frame, in their order, as 1.87's
// input queue trickles them. Plain C++ (no GLFW, no ImGui), so it is unit-tested.
#pragma once

#include <deque>
#include <vector>

namespace app {

struct KeyEvent {
    int key = 0, scancode = 0;
    bool down = false; // press or release (repeats are not queued: ImGui 1.86 ignores them)
    int mods = 0;
    bool operator==(const KeyEvent&) const = default;
};

class KeyQueue {
  public:
    void push(const KeyEvent& event) { events_.push_back(event); }
    // The events for the frame about to start: from the front, up to (not including) the
    // first that would change a key already changed by an earlier one of this frame, so
    // ImGui sees every press as down for a whole frame. The rest wait for the next frames.
    std::vector<KeyEvent> takeFrame();
    bool empty() const { return events_.empty(); }

  private:
    std::deque<KeyEvent> events_;
};

} // namespace app
