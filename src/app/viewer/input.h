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
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "app/viewer/script.h"
#include "app/viewer/selection.h"
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
    void onDrop(const std::string& path); // opened between frames (takeDrops)
    void fail(std::exception_ptr error);  // a handler threw inside a GLFW callback

    // Between frames: plays the script commands due at `seconds`, a frame's worth of steps.
    void runScript(double seconds);
    // How long an idle (minimised) window may sleep before the script needs it; nullopt: until
    // an event comes.
    std::optional<double> wakeIn(double seconds) const;
    std::vector<std::string> takeDrops();
    std::exception_ptr failure() const { return failure_; }

    // The cursor in window coordinates, nullopt outside the window.
    std::optional<glm::vec2> cursorInWindow() const;
    // The pixel of the scene image (of `extent`) this frame picks: under the cursor, unless
    // the panel is. `frame` starts the run of picks that hover and clicks read.
    std::optional<glm::uvec2> pickPixel(VkExtent2D extent, uint64_t frame);
    // Hover and clicks from the newest completed pick. True when the selection changed.
    bool readPick(const std::optional<render::PickReading>& pick);
    // The scene changed: part IDs and picks in flight name parts of the old one.
    void forgetParts();

    const Selection& selection() const { return selection_; }
    float hoveredDepth() const { return hoveredDepth_; }
    float selectedDepth() const { return selectedDepth_; }
    // Esc: clears the selection; false when there was none.
    bool escape() { return selection_.escape(); }

  private:
    struct Drag {
        int button;
        bool pan;
        glm::dvec2 start;
        double moved; // farthest distance from the start, in window pixels
    };
    // A script command as steps: a click is a move, then the press and release a frame later,
    // as a hand would do it.
    struct Step {
        std::function<void()> run;
        bool endsFrame; // the next step waits for a frame
    };
    void queue(const ScriptCommand& command);
    void step(std::function<void()> run, bool endsFrame) {
        steps_.push_back({std::move(run), endsFrame});
    }

    Viewer& viewer_;
    GLFWwindow* window_;
    glm::dvec2 cursor_{-1.0, -1.0};
    std::optional<Drag> drag_;
    Selection selection_;
    float hoveredDepth_ = 1.0f, selectedDepth_ = 1.0f;
    std::optional<uint64_t> pendingClick_; // the frame whose pick the click selects from
    std::optional<uint64_t> pickingSince_; // first frame of the current run of picks
    std::vector<std::string> drops_;
    ScriptPlayer script_;
    std::deque<Step> steps_;
    std::exception_ptr failure_;
};

} // namespace app
