// input.cpp - keys, mouse and dropped files (scripted input: input_script.cpp).
#include "app/viewer/window/input.h"

#include <algorithm>
#include <utility>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include "app/viewer/commands/commands.h"

namespace app {
namespace {

// A left click is a press and release this close together; farther is a drag.
constexpr double clickSlop = 4.0;

} // namespace

Input::Input(InputTarget& target, GLFWwindow* window, ScriptPlayer script)
    : target_(target), window_(window), script_(std::move(script)) {}

// Every key command is a row of the command table (commands.h). Keys typed into a panel
// field are ImGui's alone (WantCaptureKeyboard): typing "h" in a path hides nothing, and Esc
// there leaves the field.
void Input::onKey(int key, int scancode, int action, int mods) {
    if (action != GLFW_REPEAT) panelKeys_.push({key, scancode, action == GLFW_PRESS, mods});
    if (action != GLFW_PRESS || ImGui::GetIO().WantCaptureKeyboard) return;
    if (const auto command = commandOfKey(key, mods)) execute(*command, target_);
}

void Input::feedPanelKeys() {
    for (const KeyEvent& e : panelKeys_.takeFrame())
        ImGui_ImplGlfw_KeyCallback(window_, e.key, e.scancode, e.down ? GLFW_PRESS : GLFW_RELEASE,
                                   e.mods);
}

void Input::onCursor(double x, double y) {
    const glm::dvec2 position(x, y);
    const glm::dvec2 delta = position - cursor_;
    cursor_ = position;
    pointing_ = true; // X delivers motion only over the window (or to the drag holding it)
    if (!drag_) return;
    drag_->moved = std::max(drag_->moved, glm::length(position - drag_->start));
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    if (drag_->kind == DragKind::Pan)
        target_.pan(glm::vec2(delta), float(height));
    else if (drag_->kind == DragKind::Orbit)
        target_.orbit(glm::vec2(delta)); // a box leaves the view as it is
}

void Input::onCursorEnter(bool entered) {
    // A drag goes on outside the window (the window system holds the pointer for it).
    if (!entered && !drag_) pointing_ = false;
}

void Input::onFocus(bool focused) {
    if (!focused && !drag_) pointing_ = false;
}

void Input::onButton(int button, int action, int mods) {
    ImGui_ImplGlfw_MouseButtonCallback(window_, button, action, mods);
    if (action == GLFW_PRESS) {
        if (drag_ || ImGui::GetIO().WantCaptureMouse) return; // the panel's, or a second button
        const bool left = button == GLFW_MOUSE_BUTTON_LEFT;
        const int boxKeys = GLFW_MOD_SHIFT | GLFW_MOD_CONTROL | GLFW_MOD_ALT;
        const DragKind kind = !left              ? DragKind::Pan
                              : (mods & boxKeys) ? DragKind::Box
                                                 : DragKind::Orbit;
        const SelectMode mode = (mods & GLFW_MOD_ALT)       ? SelectMode::Remove
                                : (mods & GLFW_MOD_CONTROL) ? SelectMode::Add
                                                            : SelectMode::Replace;
        drag_ = Drag{button, kind, mode, cursor_, 0.0};
    } else if (action == GLFW_RELEASE && drag_ && drag_->button == button) {
        const Drag done = *drag_;
        drag_.reset();
        if (done.kind == DragKind::Box && done.mode == SelectMode::Add && done.moved < clickSlop) {
            target_.clicked(true, false); // Ctrl+click, not a box of one pixel: thing B
        } else if (done.kind == DragKind::Box) {
            target_.boxed(done.start, cursor_, done.mode);
        } else if (done.kind == DragKind::Orbit && done.moved < clickSlop) {
            // A second click soon at the same place selects the object (a CAD solid) at least.
            const double now = glfwGetTime();
            const bool twice = now - lastClickTime_ < doubleClickSeconds &&
                               glm::length(cursor_ - lastClickAt_) < clickSlop;
            lastClickTime_ = now;
            lastClickAt_ = cursor_;
            target_.clicked(false, twice);
        }
    }
}

void Input::onScroll(double dx, double dy) {
    ImGui_ImplGlfw_ScrollCallback(window_, dx, dy);
    if (!ImGui::GetIO().WantCaptureMouse) target_.zoomAtCursor(float(dy));
}

void Input::onDrop(const std::string& path) {
    drops_.push_back(path); // opened between frames, not inside GLFW's event processing
}

void Input::fail(std::exception_ptr error) {
    if (!failure_) failure_ = error;
    target_.quit();
}

std::vector<std::string> Input::takeDrops() {
    return std::exchange(drops_, {});
}

std::optional<glm::vec2> Input::cursorInWindow() const {
    if (!pointing_) return std::nullopt;
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    if (cursor_.x < 0 || cursor_.y < 0 || cursor_.x >= width || cursor_.y >= height)
        return std::nullopt;
    return glm::vec2(cursor_);
}

std::optional<glm::uvec2> Input::cursorPixel(VkExtent2D extent) const {
    const auto cursor = cursorInWindow();
    if (!cursor || ImGui::GetIO().WantCaptureMouse) return std::nullopt; // over the panel
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    // Window coordinates to scene image pixels (they differ on high-DPI screens).
    const glm::uvec2 p(cursor->x * float(extent.width) / float(width),
                       cursor->y * float(extent.height) / float(height));
    if (p.x < extent.width && p.y < extent.height) return p;
    return std::nullopt;
}

std::optional<std::pair<glm::vec2, glm::vec2>> Input::boxInWindow() const {
    if (!drag_ || drag_->kind != DragKind::Box) return std::nullopt;
    return std::pair{glm::vec2(drag_->start), glm::vec2(cursor_)};
}

glm::uvec2 Input::imagePixel(glm::dvec2 window, VkExtent2D extent) const {
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    const glm::dvec2 scaled = window * glm::dvec2(extent.width, extent.height) /
                              glm::dvec2(std::max(width, 1), std::max(height, 1));
    return glm::uvec2(
        glm::clamp(scaled, glm::dvec2(0.0), glm::dvec2(extent.width - 1, extent.height - 1)));
}

} // namespace app
