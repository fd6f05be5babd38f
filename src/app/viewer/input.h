// input.h - everything the user does to the viewer: keys, mouse, wheel, dropped files and
// the scripted input that plays them (--script). Real and scripted events end in the same
// handlers. Input keeps the cursor, drags, clicks and the picking state (hover and
// selection follow the GPU's pick of each frame); what they change belongs to the Viewer.
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

#include "app/viewer/key_queue.h"
#include "app/viewer/script.h"
#include "app/viewer/selection.h"
#include "app/viewer/things.h"
#include "render/pick.h"

struct GLFWwindow;

namespace app {

class Viewer;

class Input {
  public:
    Input(Viewer& viewer, GLFWwindow* window, ScriptPlayer script);

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
    // Whether something waits for frames: script steps, a click for its pick, a box for its
    // parts, key events not yet handed to the panel (a typed path's Enter waits behind its
    // repeated letters, a change per key a frame: the loop must not rest before it is in).
    bool waiting() const {
        return (!steps_.empty() && !resting()) || pendingClick_ || box_ || !panelKeys_.empty();
    }
    std::exception_ptr failure() const { return failure_; }

    // The cursor in window coordinates, nullopt outside the window.
    std::optional<glm::vec2> cursorInWindow() const;
    // The pixel of the scene image (of `extent`) this frame picks: under the cursor, unless
    // the panel is. `frame` starts the run of picks that hover and clicks read.
    std::optional<glm::uvec2> pickPixel(VkExtent2D extent, uint64_t frame);
    // The scene image pixel under the cursor now, nullopt over the panel or outside.
    std::optional<glm::uvec2> cursorPixel(VkExtent2D extent) const;
    // The newest pick that gave the hover (its frame, pixel, part and depth): the wheel zooms
    // toward its point while the cursor is still on its pixel.
    const std::optional<render::PickReading>& hoverPick() const { return hoverPick_; }
    // Hover and clicks from the newest completed pick. True when the selection changed.
    bool readPick(const std::optional<render::PickReading>& pick);
    // The box being dragged (Shift/Ctrl/Alt + left drag), in window coordinates.
    std::optional<std::pair<glm::vec2, glm::vec2>> boxInWindow() const;
    // The released box, as scene image pixels, until its parts have arrived: each frame asks
    // for it (after the whole image, see Viewer::frameParams).
    std::optional<render::PartSetQuery> boxQuery(VkExtent2D extent) const;
    // The visible parts (the query of the whole image, `extent`) and a released box's parts
    // from the newest completed part sets. True when the selection changed.
    bool readPartSets(const std::optional<render::PartSetReading>& reading, VkExtent2D extent);
    uint32_t visibleParts() const { return visibleParts_; }
    uint64_t partSetsFrame() const { return visibleFrame_; } // the frame visibleParts is of
    // The scene changed: part IDs and picks in flight name parts of the old one.
    void forgetParts(uint32_t partCount);

    const Selection& selection() const { return selection_; }
    Selection& selection() { return selection_; }
    // Things A and B of the Inspect panel: a click makes A, a Ctrl+click B (things.h).
    const Things& things() const { return things_; }
    Things& things() { return things_; }
    float hoveredDepth() const { return hoveredDepth_; }
    float selectedDepth() const { return selectedDepth_; }
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
    struct Box {
        glm::dvec2 a, b; // corners, window coordinates
        SelectMode mode;
        uint64_t since; // the first frame that asks for it
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

    Viewer& viewer_;
    GLFWwindow* window_;
    glm::dvec2 cursor_{-1.0, -1.0};
    bool pointing_ = false; // the cursor is over the window and the person is with it
    std::optional<Drag> drag_;
    std::optional<Box> box_;
    uint64_t partSetsFrom_ = 0; // the first frame whose part sets are still to be read
    uint64_t visibleFrame_ = 0; // the frame visibleParts_ was counted in
    uint32_t visibleParts_ = 0;
    Selection selection_;
    Things things_;
    // The click's pick has come: its thing becomes A or B, and A's and B's parts the selection.
    void clicked();
    float hoveredDepth_ = 0.0f, selectedDepth_ = 0.0f; // reversed: 0 is the far plane
    std::optional<render::PickReading> hoverPick_;
    std::optional<uint64_t> pendingClick_; // the frame whose pick the click selects from
    uint32_t pendingLevel_ = 0;            // what it selects (ViewSettings::selectLevel)
    bool pendingAdd_ = false;              // a Ctrl+click: thing B (things.h)
    double lastClickTime_ = -1.0;          // glfwGetTime of the last click, for double-clicks
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
