// viewer_input.cpp - keys, mouse, dropped files and scripted input: every source of input
// ends in the same handlers.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <utility>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include "app/viewer_app.h"

namespace app {
namespace {

// A left click is a press and release this close together; farther is a drag.
constexpr double clickSlop = 4.0;

bool isGltf(std::string path) {
    std::transform(path.begin(), path.end(), path.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return path.ends_with(".gltf") || path.ends_with(".glb");
}

template <typename Entries>
int indexOf(const Entries& entries, const std::string& name) {
    for (size_t i = 0; i < entries.size(); ++i)
        if (name == entries[i].name) return int(i);
    return 0; // names were checked when the script was parsed
}

} // namespace

void Viewer::onKey(int key, int scancode, int action, int mods) {
    ImGui_ImplGlfw_KeyCallback(window_, key, scancode, action, mods);
    if (action != GLFW_PRESS || ImGui::GetIO().WantCaptureKeyboard) return;
    switch (key) {
    case GLFW_KEY_V: {
        ViewerSettings wanted = settings_;
        wanted.vsync = !wanted.vsync;
        applySettings(wanted);
        break;
    }
    case GLFW_KEY_F:
        camera_.fit(aspect());
        break;
    case GLFW_KEY_R:
        reloadShaders();
        break;
    case GLFW_KEY_HOME:
        camera_.resetView();
        break;
    case GLFW_KEY_F1:
        panelVisible_ = !panelVisible_;
        break;
    case GLFW_KEY_ESCAPE:
        if (selection_.escape())
            reportSelection();
        else
            glfwSetWindowShouldClose(window_, GLFW_TRUE); // nothing selected: Esc closes
        break;
    default:
        break;
    }
}

void Viewer::onCursor(double x, double y) {
    const glm::dvec2 position(x, y);
    const glm::dvec2 delta = position - cursor_;
    cursor_ = position;
    if (!drag_) return;
    drag_->moved = std::max(drag_->moved, glm::length(position - drag_->start));
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    if (drag_->pan)
        camera_.pan(glm::vec2(delta), float(height));
    else
        camera_.orbit(glm::vec2(delta));
}

void Viewer::onButton(int button, int action, int mods) {
    ImGui_ImplGlfw_MouseButtonCallback(window_, button, action, mods);
    if (action == GLFW_PRESS) {
        if (drag_ || ImGui::GetIO().WantCaptureMouse) return; // the panel's, or a second button
        const bool pan = button != GLFW_MOUSE_BUTTON_LEFT || (mods & GLFW_MOD_SHIFT);
        drag_ = Drag{button, pan, cursor_, 0.0};
    } else if (action == GLFW_RELEASE && drag_ && drag_->button == button) {
        const bool click = !drag_->pan && drag_->moved < clickSlop;
        drag_.reset();
        // The pick of the next frame (at this cursor position) decides what the click hits.
        if (click) pendingClick_ = frameNumber_;
    }
}

void Viewer::onScroll(double dx, double dy) {
    ImGui_ImplGlfw_ScrollCallback(window_, dx, dy);
    if (!ImGui::GetIO().WantCaptureMouse) camera_.zoom(float(dy));
}

void Viewer::onDrop(const std::string& path) {
    drops_.push_back(path); // opened between frames, not inside GLFW's event processing
}

void Viewer::openDroppedFiles() {
    for (const std::string& path : std::exchange(drops_, {})) {
        if (!isGltf(path)) {
            error_ = "'" + path + "' is not a glTF model (.gltf or .glb)";
            continue;
        }
        Options source = options_;
        source.model = path;
        source.scene.clear();
        source.parts = settings_.componentParts ? "components" : "primitives";
        openScene(source);
    }
}

void Viewer::runScript(double seconds) {
    for (const ScriptCommand& command : script_.due(seconds)) queueCommand(command);
    while (!steps_.empty()) {
        const Step step = std::move(steps_.front());
        steps_.pop_front();
        step.run();
        if (step.endsFrame) break;
    }
}

void Viewer::queueCommand(const ScriptCommand& c) {
    const auto& v = c.values;
    auto step = [this](std::function<void()> run, bool endsFrame) {
        steps_.push_back({std::move(run), endsFrame});
    };
    auto settings = [this](auto change) {
        return [this, change] {
            ViewerSettings wanted = settings_;
            change(wanted);
            applySettings(wanted); // as the panel's widgets do
        };
    };
    auto press = [this](int action) {
        return [this, action] { onButton(GLFW_MOUSE_BUTTON_LEFT, action, 0); };
    };
    switch (c.op) {
    case ScriptOp::Key:
        step(
            [this, key = c.key] {
                const int code = glfwGetKeyScancode(key);
                onKey(key, code, GLFW_PRESS, 0);
                onKey(key, code, GLFW_RELEASE, 0);
            },
            true); // a frame between key presses, as a hand gives (V twice must show off)
        break;
    case ScriptOp::Move:
        step([this, v] { onCursor(v[0], v[1]); }, true);
        break;
    case ScriptOp::Click:
        // Move first and let a frame pass, so the panel knows whether it is under the cursor.
        step([this, v] { onCursor(v[0], v[1]); }, true);
        step(press(GLFW_PRESS), false);
        step(press(GLFW_RELEASE), true);
        break;
    case ScriptOp::Drag:
        step([this, v] { onCursor(v[0], v[1]); }, true);
        step(press(GLFW_PRESS), true);
        for (int i = 1; i <= 8; ++i) { // a hand's drag arrives as several moves
            const double t = i / 8.0;
            step([this, v, t] { onCursor(v[0] + (v[2] - v[0]) * t, v[1] + (v[3] - v[1]) * t); },
                 true);
        }
        step(press(GLFW_RELEASE), true);
        break;
    case ScriptOp::Scroll:
        step([this, v] { onScroll(0.0, v[0]); }, false);
        break;
    case ScriptOp::Resize:
        step([this, v] { glfwSetWindowSize(window_, int(v[0]), int(v[1])); }, true);
        break;
    case ScriptOp::Renderer:
        step(settings([i = indexOf(render::techniques(), c.text)](ViewerSettings& s) {
                 s.technique = i;
             }),
             true);
        break;
    case ScriptOp::Mode:
        step(
            settings([i = indexOf(render::drawModes(), c.text)](ViewerSettings& s) { s.mode = i; }),
            true);
        break;
    case ScriptOp::Copies:
        step(settings([n = uint32_t(v[0])](ViewerSettings& s) { s.copies = n; }), true);
        break;
    case ScriptOp::Msaa:
        step(settings([n = uint32_t(v[0])](ViewerSettings& s) { s.msaa = n; }), true);
        break;
    case ScriptOp::Screenshot:
        step([this, path = c.text] { screenshotPath_ = path; }, true);
        break;
    case ScriptOp::Drop:
        step([this, path = c.text] { onDrop(path); }, true);
        break;
    case ScriptOp::Frames: // empty steps, one frame each: what follows waits for them
        for (int i = 0; i < int(v[0]); ++i) step([] {}, true);
        break;
    case ScriptOp::Quit:
        step([this] { glfwSetWindowShouldClose(window_, GLFW_TRUE); }, true);
        break;
    }
}

} // namespace app
