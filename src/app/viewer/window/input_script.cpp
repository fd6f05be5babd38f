// input_script.cpp - scripted input (--script): each line becomes steps, run a frame's worth
// at a time. Input lines play into the handlers real input reaches, as a hand would give
// them; command lines run the command a key or the panel would (commands.h).
#include <algorithm>
#include <utility>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>

#include "app/viewer/commands/commands.h"
#include "app/viewer/window/input.h"

namespace app {
namespace {

// The keys a chord's modifier bits stand for.
constexpr std::pair<int, int> modifierKeys[] = {{GLFW_MOD_SHIFT, GLFW_KEY_LEFT_SHIFT},
                                                {GLFW_MOD_CONTROL, GLFW_KEY_LEFT_CONTROL},
                                                {GLFW_MOD_ALT, GLFW_KEY_LEFT_ALT}};

} // namespace

void Input::chord(int key, int mods) {
    for (const auto& [bit, modifier] : modifierKeys)
        if (mods & bit) onKey(modifier, glfwGetKeyScancode(modifier), GLFW_PRESS, mods);
    const int code = glfwGetKeyScancode(key);
    onKey(key, code, GLFW_PRESS, mods);
    onKey(key, code, GLFW_RELEASE, mods);
    for (const auto& [bit, modifier] : modifierKeys)
        if (mods & bit) onKey(modifier, glfwGetKeyScancode(modifier), GLFW_RELEASE, 0);
}

void Input::runScript(double seconds) {
    for (const ScriptLine& line : script_.due(seconds)) queue(line);
    scriptNow_ = seconds;
    while (!steps_.empty() && !resting()) {
        const Step next = std::move(steps_.front());
        steps_.pop_front();
        next.run();
        ++stepsRun_;
        if (next.endsFrame) break;
    }
}

std::optional<double> Input::wakeIn(double seconds) const {
    if (resting()) return std::max(*restUntil_ - seconds, 0.0);
    if (!steps_.empty()) return 0.05;
    if (auto next = script_.nextTime()) return std::clamp(*next - seconds, 0.01, 1.0);
    return std::nullopt;
}

void Input::waitForLoads() {
    if (target_.loading()) steps_.push_front({[this] { waitForLoads(); }, true});
}

void Input::waitForSolids(uint32_t solids) {
    if (target_.loading() && target_.solidsShown() < solids)
        steps_.push_front({[this, solids] { waitForSolids(solids); }, true});
}

void Input::waitForPipelines() {
    if (target_.pipelinePending()) steps_.push_front({[this] { waitForPipelines(); }, true});
}

void Input::waitForInspect() {
    if (target_.inspecting()) steps_.push_front({[this] { waitForInspect(); }, true});
}

void Input::waitForCensus() {
    if (target_.censusBusy()) steps_.push_front({[this] { waitForCensus(); }, true});
}

void Input::queue(const ScriptLine& line) {
    switch (line.op) {
    case ScriptOp::Command:
        step(
            [this, command = *line.command, where = line.where] {
                try {
                    execute(command, target_);
                } catch (const CommandError& e) {
                    throw ScriptError(where + ": " + e.what());
                }
            },
            true);
        break;
    case ScriptOp::Key:
        // Pressed and released at once, modifiers held around it: what a quick hand gives a
        // slow frame. A frame between key presses (V twice must show off).
        step([this, key = line.key, mods = line.mods] { chord(key, mods); }, true);
        break;
    case ScriptOp::Type:
        step(
            [this, text = line.text] {
                for (const char ch : text)
                    if (static_cast<unsigned char>(ch) < 0x80)
                        ImGui_ImplGlfw_CharCallback(window_, static_cast<unsigned char>(ch));
            },
            true);
        break;
    case ScriptOp::Resize:
        step([this, v = line.values] { glfwSetWindowSize(window_, int(v[0]), int(v[1])); }, true);
        break;
    case ScriptOp::Drop:
        step([this, path = line.text] { onDrop(path); }, true);
        break;
    case ScriptOp::Leave:
        step([this] { onCursorEnter(false); }, true);
        break;
    case ScriptOp::Unfocus:
        step([this] { onFocus(false); }, true);
        break;
    case ScriptOp::Move:
    case ScriptOp::Click:
    case ScriptOp::DoubleClick:
    case ScriptOp::Drag:
    case ScriptOp::Box:
    case ScriptOp::Scroll:
        queuePointer(line);
        break;
    case ScriptOp::Loaded:
    case ScriptOp::Solids:
    case ScriptOp::Frames:
    case ScriptOp::Redraw:
    case ScriptOp::Blink:
    case ScriptOp::Rest:
    case ScriptOp::Pipeline:
    case ScriptOp::Inspect:
    case ScriptOp::CensusDone:
        queueWait(line);
        break;
    }
}

// The pointer as a hand moves it: to the place first, with a frame after it so the panel
// knows whether it is under the cursor, then the buttons.
void Input::queuePointer(const ScriptLine& line) {
    const auto v = line.values;
    auto press = [this](int action, int mods = 0) {
        return [this, action, mods] { onButton(GLFW_MOUSE_BUTTON_LEFT, action, mods); };
    };
    // Ctrl is held as a hand holds it: down before the press, up after the release.
    auto ctrl = [this](int mods, int action) {
        if (mods)
            onKey(GLFW_KEY_LEFT_CONTROL, glfwGetKeyScancode(GLFW_KEY_LEFT_CONTROL), action,
                  action == GLFW_PRESS ? mods : 0);
    };
    if (line.op == ScriptOp::Scroll) {
        step([this, v] { onScroll(0.0, v[0]); }, false);
        return;
    }
    step([this, v] { onCursor(v[0], v[1]); }, true);
    switch (line.op) {
    case ScriptOp::Click:
        step(
            [mods = line.mods, press, ctrl] {
                ctrl(mods, GLFW_PRESS);
                press(GLFW_PRESS, mods)();
            },
            false);
        step(
            [mods = line.mods, press, ctrl] {
                press(GLFW_RELEASE, mods)();
                ctrl(mods, GLFW_RELEASE);
            },
            true);
        break;
    case ScriptOp::DoubleClick: // both clicks in one step: well within doubleClickSeconds
        step(
            [press] {
                for (int i = 0; i < 2; ++i) {
                    press(GLFW_PRESS)();
                    press(GLFW_RELEASE)();
                }
            },
            true);
        break;
    case ScriptOp::Drag:
    case ScriptOp::Box: // the same hand movement, with the modifier held at the press
        step(press(GLFW_PRESS, line.op == ScriptOp::Box ? line.mods : 0), true);
        for (int i = 1; i <= 8; ++i) { // a hand's drag arrives as several moves
            const double t = i / 8.0;
            step([this, v, t] { onCursor(v[0] + (v[2] - v[0]) * t, v[1] + (v[3] - v[1]) * t); },
                 true);
        }
        step(press(GLFW_RELEASE), true);
        break;
    default:
        break; // a move is the place alone
    }
}

// The test's own waits and holds.
void Input::queueWait(const ScriptLine& line) {
    switch (line.op) {
    case ScriptOp::Loaded:
        step([this] { waitForLoads(); }, true);
        break;
    case ScriptOp::Solids:
        step([this, solids = uint32_t(line.values[0])] { waitForSolids(solids); }, true);
        break;
    case ScriptOp::Frames: // empty steps, one frame each: what follows waits for them
        for (int i = 0; i < int(line.values[0]); ++i) step([] {}, true);
        break;
    case ScriptOp::Redraw: // with what follows at the same time, in the same frame
        step([this] { target_.redraw(); }, false);
        break;
    case ScriptOp::Blink:
        step(
            [this, weight = line.text] {
                target_.holdBlink(weight == "clock" ? std::nullopt
                                                    : std::optional(weight == "strong"));
            },
            true);
        break;
    case ScriptOp::Rest: // the steps after it wait, and the loop with them
        step([this, s = line.values[0]] { restUntil_ = scriptNow_ + s; }, false);
        break;
    case ScriptOp::CensusDone:
        step([this] { waitForCensus(); }, true);
        break;
    case ScriptOp::Pipeline: // the pipeline builds' worker, or Inspect's: held or awaited
    case ScriptOp::Inspect: {
        const bool builds = line.op == ScriptOp::Pipeline;
        if (line.text == "ready")
            step([this, builds] { builds ? waitForPipelines() : waitForInspect(); }, true);
        else
            step(
                [this, builds, hold = line.text == "hold"] {
                    builds ? target_.holdPipelineBuilds(hold) : target_.holdInspect(hold);
                },
                true);
        break;
    }
    default:
        break;
    }
}

} // namespace app
