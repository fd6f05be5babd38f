// input.h - everything the user does to the viewer: keys, mouse, wheel, dropped files and
// the scripted input that plays them (--script). Real and scripted events end in the same
// handlers, and they turn into commands (commands.h) and requests (a drag's orbit, a click
// or a box for the picks to answer) to an InputTarget, which the viewer implements. Input
// keeps only what gestures need between events: the cursor, drags, the last click's time.
#pragma once

#include <deque>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "app/viewer/commands/command_target.h"
#include "app/viewer/commands/script.h"
#include "app/viewer/window/key_queue.h"
#include "render/pick.h"

struct GLFWwindow;

namespace app {

// What input asks for besides commands: the camera's drags and wheel, clicks and boxes for
// the picks to answer, and the script's waits and holds.
class InputTarget : public CommandTarget {
  public:
    virtual void orbit(glm::vec2 delta) = 0;
    virtual void pan(glm::vec2 delta, float height) = 0;
    virtual void zoomAtCursor(float steps) = 0;
    // A click released at the cursor (`twice`: a double-click; `add`: a Ctrl+click), and a
    // box dragged from `a` to `b` (window coordinates) to select with `mode`.
    virtual void clicked(bool add, bool twice) = 0;
    virtual void boxed(glm::dvec2 a, glm::dvec2 b, SelectMode mode) = 0;
    // The script's waits (`solids N`, `pipeline ready`, `inspect ready`, `census-done`) and
    // holds.
    virtual uint32_t solidsShown() const = 0;
    virtual bool pipelinePending() const = 0;
    virtual bool inspecting() const = 0;
    virtual bool censusBusy() const = 0; // a census running, or a `census here` not counted
    virtual void redraw() = 0;
    virtual void holdBlink(std::optional<bool> strong) = 0;
    virtual void holdPipelineBuilds(bool hold) = 0;
    virtual void holdInspect(bool hold) = 0;
};

class Input {
  public:
    Input(InputTarget& target, GLFWwindow* window, ScriptPlayer script);

    // GLFW's callbacks (window.cpp) and the script call these.
    void onKey(int key, int scancode, int action, int mods);
    void onCursor(double x, double y);
    void onButton(int button, int action, int mods);
    void onScroll(double dx, double dy);
    // The pointer left (or entered) the window, the window lost (or gained) the keyboard: the
    // hover ends until the pointer moves over the window again, so nothing blinks while the
    // person works elsewhere.
    void onCursorEnter(bool entered);
    void onFocus(bool focused);
    void onDrop(const std::string& path); // opened between frames (takeDrops)
    // Before the panel's frame starts: this frame's share of the key events for ImGui.
    void feedPanelKeys();
    void fail(std::exception_ptr error); // a handler threw inside a GLFW callback
    static constexpr double doubleClickSeconds = 0.4;

    // Between frames: plays the script lines due at `seconds`, a frame's worth of steps.
    void runScript(double seconds);
    // How long an idle (minimised) window may sleep before the script needs it; nullopt: until
    // an event comes.
    std::optional<double> wakeIn(double seconds) const;
    std::vector<std::string> takeDrops();
    // Script steps run so far: scripted input counts as input for the frames it needs.
    uint64_t stepsRun() const { return stepsRun_; }
    // Whether something waits for frames: script steps, key events not yet handed to the panel (a
    // typed path's Enter waits behind its repeated letters, a change per key a frame: the loop must
    // not rest before it is in).
    bool waiting() const { return (!steps_.empty() && !resting()) || !panelKeys_.empty(); }
    std::exception_ptr failure() const { return failure_; }

    // The cursor in window coordinates, nullopt outside the window.
    std::optional<glm::vec2> cursorInWindow() const;
    // The scene image pixel under the cursor now, nullopt over the panel or outside.
    std::optional<glm::uvec2> cursorPixel(VkExtent2D extent) const;
    // The box being dragged (Shift/Ctrl/Alt + left drag), in window coordinates.
    std::optional<std::pair<glm::vec2, glm::vec2>> boxInWindow() const;
    // Window coordinates as scene image pixels (of `extent`), clamped to the image.
    glm::uvec2 imagePixel(glm::dvec2 window, VkExtent2D extent) const;
    // Esc's first cancel: a box being dragged is dropped; false when none was.
    bool cancelBox() {
        if (!drag_ || drag_->kind != DragKind::Box) return false;
        drag_.reset();
        return true;
    }

  private:
    enum class DragKind { Orbit, Pan, Box };
    struct Drag {
        int button;
        DragKind kind;
        SelectMode mode; // Box: by the modifier held at the press
        glm::dvec2 start;
        double moved; // farthest distance from the start, in window pixels
    };
    // A script line as steps: a click is a move, then the press and release a frame later,
    // as a hand would do it.
    struct Step {
        std::function<void()> run;
        bool endsFrame; // the next step waits for a frame
    };
    void queue(const ScriptLine& line);
    void queuePointer(const ScriptLine& line); // move, click, dblclick, drag, box, scroll
    void queueWait(const ScriptLine& line); // loaded, solids, frames, redraw, blink, rest, pipeline
    void chord(int key, int mods);          // a script's key: modifiers down, the key, modifiers up
    void step(std::function<void()> run, bool endsFrame) {
        steps_.push_back({std::move(run), endsFrame});
    }
    // A step that comes back every frame while a dropped model is loading.
    void waitForLoads();
    // The same until the model loading shows `solids` solids (`solids N`).
    void waitForSolids(uint32_t solids);
    // The same while a pipeline is being built or awaited (`pipeline ready`).
    void waitForPipelines();
    void waitForInspect();
    void waitForCensus();

    InputTarget& target_;
    GLFWwindow* window_;
    glm::dvec2 cursor_{-1.0, -1.0};
    bool pointing_ = false; // the cursor is over the window and the person is with it
    std::optional<Drag> drag_;
    double lastClickTime_ = -1.0; // glfwGetTime of the last click, for double-clicks
    glm::dvec2 lastClickAt_{-1.0, -1.0};
    std::optional<uint64_t> pickingSince_; // first frame of the current run of picks
    std::vector<std::string> drops_;
    KeyQueue panelKeys_; // for ImGui, a change per key a frame (key_queue.h)
    ScriptPlayer script_;
    std::deque<Step> steps_;
    uint64_t stepsRun_ = 0;
    // A script's `rest`: no step runs before this time (script seconds, as runScript's).
    std::optional<double> restUntil_;
    double scriptNow_ = 0.0;
    bool resting() const { return restUntil_ && scriptNow_ < *restUntil_; }
    std::exception_ptr failure_;
};

} // namespace app
