// input.cpp - keys, mouse, dropped files and picking (scripted input: input_script.cpp).
#include "app/viewer/input.h"

#include <algorithm>
#include <utility>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include "app/viewer/commands.h"
#include "app/viewer/viewer.h"
#include "render/culling.h"

namespace app {
namespace {

// A left click is a press and release this close together; farther is a drag.
constexpr double clickSlop = 4.0;

} // namespace

Input::Input(Viewer& viewer, GLFWwindow* window, ScriptPlayer script)
    : viewer_(viewer), window_(window), script_(std::move(script)) {}

// Every key command is a row of the command table (commands.h). Keys typed into a panel
// field are ImGui's alone (WantCaptureKeyboard): typing "h" in a path hides nothing, and Esc
// there leaves the field.
void Input::onKey(int key, int scancode, int action, int mods) {
    if (action != GLFW_REPEAT) panelKeys_.push({key, scancode, action == GLFW_PRESS, mods});
    if (action != GLFW_PRESS || ImGui::GetIO().WantCaptureKeyboard) return;
    if (const auto command = commandOfKey(key, mods)) execute(*command, viewer_, *this);
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
        viewer_.camera().pan(glm::vec2(delta), float(height));
    else if (drag_->kind == DragKind::Orbit)
        viewer_.camera().orbit(glm::vec2(delta)); // a box leaves the view as it is
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
            // Ctrl+click, not a box of one pixel: thing B of the Inspect panel (things.h).
            pendingClick_ = viewer_.nextFrame();
            pendingLevel_ = viewer_.view().selectLevel;
            pendingAdd_ = true;
        } else if (done.kind == DragKind::Box) {
            // The parts come from the ID image of a frame after the release.
            box_ = Box{done.start, cursor_, done.mode, viewer_.nextFrame()};
        } else if (done.kind == DragKind::Orbit && done.moved < clickSlop) {
            // The pick of the next frame (at this cursor position) decides what it hits. A
            // second click soon at the same place selects the object (a CAD solid) at least.
            const double now = glfwGetTime();
            const bool twice = now - lastClickTime_ < doubleClickSeconds &&
                               glm::length(cursor_ - lastClickAt_) < clickSlop;
            lastClickTime_ = now;
            lastClickAt_ = cursor_;
            pendingClick_ = viewer_.nextFrame();
            pendingLevel_ =
                twice ? std::max(1u, viewer_.view().selectLevel) : viewer_.view().selectLevel;
            pendingAdd_ = false;
        }
    }
}

void Input::onScroll(double dx, double dy) {
    ImGui_ImplGlfw_ScrollCallback(window_, dx, dy);
    if (!ImGui::GetIO().WantCaptureMouse) viewer_.zoomAtCursor(float(dy));
}

void Input::onDrop(const std::string& path) {
    drops_.push_back(path); // opened between frames, not inside GLFW's event processing
}

void Input::fail(std::exception_ptr error) {
    if (!failure_) failure_ = error;
    viewer_.quit();
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

std::optional<glm::uvec2> Input::pickPixel(VkExtent2D extent, uint64_t frame) {
    const std::optional<glm::uvec2> pixel = cursorPixel(extent);
    if (!pixel)
        pickingSince_.reset();
    else if (!pickingSince_)
        pickingSince_ = frame;
    return pixel;
}

bool Input::readPick(const std::optional<render::PickReading>& pick) {
    // Picks arrive a frame or two late; only those since the cursor came over the scene
    // count, so an old pick never shows as the hover after leaving the panel.
    if (!pickingSince_) {
        selection_.hover(std::nullopt);
        hoverPick_.reset();
        pendingClick_.reset();
        return false;
    }
    if (pick && pick->frame >= *pickingSince_) {
        selection_.hover(pick->part);
        hoveredDepth_ = pick->depth;
        hoverPick_ = pick;
    }
    // A click selects what was under the cursor in the frame after the click.
    if (pendingClick_ && pick && pick->frame >= *pendingClick_ && viewer_.measuring()) {
        viewer_.measured(*pick); // measure mode: the click places a point, selects nothing
        pendingClick_.reset();
        return false;
    }
    if (pendingClick_ && pick && pick->frame >= *pendingClick_) {
        pendingClick_.reset();
        if (pendingAdd_ && !selection_.hovered()) return false; // Ctrl+click on empty space
        clicked();
        selectedDepth_ = hoveredDepth_;
        return true;
    }
    return false;
}

void Input::clicked() {
    const uint32_t partCount = selection_.selected().partCount();
    const auto hovered = selection_.hovered();
    std::optional<scene::Thing> thing;
    if (hovered) {
        // At the face level an edge under the cursor (edge_hover.h) is the thing, not its face.
        const std::optional<scene::EdgeRef> edge =
            pendingLevel_ == 0 ? selection_.hoveredEdge() : std::nullopt;
        thing = viewer_.thingOf(viewer_.partsAround(*hovered, pendingLevel_), *hovered, edge);
    }
    if (pendingAdd_)
        things_.add(std::move(*thing));
    else
        things_.click(std::move(thing));
    // A plain click at the face level selects the part alone (and what Selection::click
    // takes with it); at coarser levels, and with Ctrl, A's and B's parts. The clicked part
    // is the primary one (the panel details its face).
    if (!pendingAdd_ && pendingLevel_ == 0)
        selection_.click();
    else
        selection_.clickAround(things_.parts(partCount));
}

std::optional<std::pair<glm::vec2, glm::vec2>> Input::boxInWindow() const {
    if (!drag_ || drag_->kind != DragKind::Box) return std::nullopt;
    return std::pair{glm::vec2(drag_->start), glm::vec2(cursor_)};
}

std::optional<render::PartSetQuery> Input::boxQuery(VkExtent2D extent) const {
    if (!box_ || extent.width == 0 || extent.height == 0) return std::nullopt;
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    if (width <= 0 || height <= 0) return std::nullopt;
    // Window coordinates to scene image pixels, clamped to the image.
    auto pixel = [&](glm::dvec2 p) {
        const glm::dvec2 scaled =
            p * glm::dvec2(extent.width, extent.height) / glm::dvec2(width, height);
        return glm::uvec2(
            glm::clamp(scaled, glm::dvec2(0.0), glm::dvec2(extent.width - 1, extent.height - 1)));
    };
    return render::spanning(pixel(box_->a), pixel(box_->b));
}

bool Input::readPartSets(const std::optional<render::PartSetReading>& reading, VkExtent2D extent) {
    if (!reading || reading->frame < partSetsFrom_) return false;
    partSetsFrom_ = reading->frame + 1;
    const render::PartSetQuery whole{{0, 0}, {extent.width - 1, extent.height - 1}};
    const auto box = boxQuery(extent);
    bool changed = false;
    for (size_t i = 0; i < reading->queries.size(); ++i) {
        if (reading->queries[i] == whole) {
            visibleParts_ = reading->counts[i];
            visibleFrame_ = reading->frame;
        }
        if (box && box_ && reading->frame >= box_->since && reading->queries[i] == *box) {
            selection_.select(reading->sets[i], box_->mode);
            box_.reset();
            changed = true;
        }
    }
    return changed;
}

void Input::forgetParts(uint32_t partCount) {
    selection_.reset(partCount);
    things_.forget();
    pendingClick_.reset();
    pickingSince_.reset();
    hoverPick_.reset();
    box_.reset();
    partSetsFrom_ = viewer_.nextFrame(); // earlier frames counted the old scene's parts
    visibleParts_ = 0;
    visibleFrame_ = 0;
}

} // namespace app
