// input.cpp - keys, mouse, dropped files, picking and scripted input.
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

Input::Input(Viewer& viewer, GLFWwindow* window, ScriptPlayer script)
    : viewer_(viewer), window_(window), script_(std::move(script)) {}

// Every key command is a row of the command table (commands.h). Keys typed into a panel
// field are ImGui's alone (WantCaptureKeyboard): typing "h" in a path hides nothing, and Esc
// there leaves the field.
void Input::onKey(int key, int scancode, int action, int mods) {
    if (action != GLFW_REPEAT) panelKeys_.push({key, scancode, action == GLFW_PRESS, mods});
    if (action != GLFW_PRESS || ImGui::GetIO().WantCaptureKeyboard) return;
    if (const Command* command = commandOfKey(key, mods)) command->run(viewer_, *this);
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
    if (!drag_) return;
    drag_->moved = std::max(drag_->moved, glm::length(position - drag_->start));
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    if (drag_->kind == DragKind::Pan)
        viewer_.camera().pan(glm::vec2(delta), float(height));
    else if (drag_->kind == DragKind::Orbit)
        viewer_.camera().orbit(glm::vec2(delta)); // a box leaves the view as it is
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

void Input::runScript(double seconds) {
    for (const ScriptCommand& command : script_.due(seconds)) queue(command);
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
    if (viewer_.loading()) steps_.push_front({[this] { waitForLoads(); }, true});
}

void Input::waitForPipelines() {
    if (viewer_.pipelinePending()) steps_.push_front({[this] { waitForPipelines(); }, true});
}

void Input::queue(const ScriptCommand& c) {
    const auto& v = c.values;
    // Settings change in place, as the panel's widgets change them; the frame applies them.
    auto settings = [this](auto change) { return [this, change] { change(viewer_.settings()); }; };
    auto press = [this](int action, int mods = 0) {
        return [this, action, mods] { onButton(GLFW_MOUSE_BUTTON_LEFT, action, mods); };
    };
    switch (c.op) {
    case ScriptOp::Key:
        // Pressed and released at once, modifiers held around it: what a quick hand gives a
        // slow frame. A frame between key presses (V twice must show off).
        step([this, key = c.key, mods = c.mods] { chord(key, mods); }, true);
        break;
    case ScriptOp::Type:
        step(
            [this, text = c.text] {
                for (const char ch : text)
                    if (static_cast<unsigned char>(ch) < 0x80)
                        ImGui_ImplGlfw_CharCallback(window_, static_cast<unsigned char>(ch));
            },
            true);
        break;
    case ScriptOp::Move:
        step([this, v] { onCursor(v[0], v[1]); }, true);
        break;
    case ScriptOp::Click:
        // Move first and let a frame pass, so the panel knows whether it is under the cursor.
        // Ctrl is held as a hand holds it: down before the press, up after the release.
        step([this, v] { onCursor(v[0], v[1]); }, true);
        step(
            [this, mods = c.mods, press] {
                if (mods)
                    onKey(GLFW_KEY_LEFT_CONTROL, glfwGetKeyScancode(GLFW_KEY_LEFT_CONTROL),
                          GLFW_PRESS, mods);
                press(GLFW_PRESS, mods)();
            },
            false);
        step(
            [this, mods = c.mods, press] {
                press(GLFW_RELEASE, mods)();
                if (mods)
                    onKey(GLFW_KEY_LEFT_CONTROL, glfwGetKeyScancode(GLFW_KEY_LEFT_CONTROL),
                          GLFW_RELEASE, 0);
            },
            true);
        break;
    case ScriptOp::DoubleClick: // both clicks in one step: well within doubleClickSeconds
        step([this, v] { onCursor(v[0], v[1]); }, true);
        step(
            [this, press] {
                for (int i = 0; i < 2; ++i) {
                    press(GLFW_PRESS)();
                    press(GLFW_RELEASE)();
                }
            },
            true);
        break;
    case ScriptOp::Level:
        step([this, level = c.text == "face"    ? 0u
                            : c.text == "solid" ? 1u
                                                : 2u] { viewer_.view().selectLevel = level; },
             true);
        break;
    case ScriptOp::Drag:
    case ScriptOp::Box: // the same hand movement, with the modifier held at the press
        step([this, v] { onCursor(v[0], v[1]); }, true);
        step(press(GLFW_PRESS, c.op == ScriptOp::Box ? c.mods : 0), true);
        for (int i = 1; i <= 8; ++i) { // a hand's drag arrives as several moves
            const double t = i / 8.0;
            step([this, v, t] { onCursor(v[0] + (v[2] - v[0]) * t, v[1] + (v[3] - v[1]) * t); },
                 true);
        }
        step(press(GLFW_RELEASE), true);
        break;
    case ScriptOp::Object:
        step([this, name = c.text] { viewer_.selectObjects(name, SelectMode::Replace); }, true);
        break;
    case ScriptOp::Node:
        step(
            [this, c] {
                const int action = int(c.values[0]); // select, add, hide, show (script.h)
                const auto what = action >= 2 ? (action == 2 ? Viewer::NodeAction::Hide
                                                             : Viewer::NodeAction::Show)
                                              : Viewer::NodeAction::Select;
                if (!viewer_.actOnNode(c.text, what,
                                       action == 1 ? SelectMode::Add : SelectMode::Replace))
                    throw ScriptError(c.where + ": no node of the assembly tree has the path '" +
                                      c.text + "'");
            },
            true);
        break;
    case ScriptOp::Scroll:
        step([this, v] { onScroll(0.0, v[0]); }, false);
        break;
    case ScriptOp::Resize:
        step([this, v] { glfwSetWindowSize(window_, int(v[0]), int(v[1])); }, true);
        break;
    case ScriptOp::Renderer: // names were checked when the script was parsed
        step(settings([t = render::findTechnique(c.text)](Options& s) {
                 s.render.pipeline.technique = t;
             }),
             true);
        break;
    case ScriptOp::Mode:
        step(settings(
                 [m = render::findDrawMode(c.text)](Options& s) { s.render.pipeline.mode = m; }),
             true);
        break;
    case ScriptOp::Culling:
        step(settings([m = render::findCullMode(c.text)->mode](Options& s) {
                 s.render.culling.mode = m;
             }),
             true);
        break;
    case ScriptOp::Freeze:
        step(settings([on = c.text == "on"](Options& s) { s.render.culling.freeze = on; }), true);
        break;
    case ScriptOp::Sort:
        step(settings([on = c.text == "on"](Options& s) { s.render.draws.sortDraws = on; }), true);
        break;
    case ScriptOp::Defaults:
        step([this] { viewer_.resetSettings(); }, true);
        break;
    case ScriptOp::Section: // checked when the script was parsed
        step(settings([text = c.text](Options& s) {
                 scene::Section& section = s.render.section;
                 if (text == "off") {
                     section = {};
                 } else if (const auto plane = scene::parseSectionPlane(text);
                            !section.add(plane)) {
                     section.planes.back() = plane;
                 }
             }),
             true);
        break;
    case ScriptOp::View: // names were checked when the script was parsed
        step([this, view = scene::findStandardView(c.text)] { viewer_.turnTo(*view); }, true);
        break;
    case ScriptOp::Ortho:
        step([this, on = c.text == "on"] { viewer_.setOrtho(on); }, true);
        break;
    case ScriptOp::Explode: // as the panel's slider sets it
        step(settings([f = float(v[0])](Options& s) { s.animation.explode = f; }), true);
        break;
    case ScriptOp::Xray:
        step([this, on = c.text == "on"] { viewer_.setXray(on); }, true);
        break;
    case ScriptOp::Copies:
        step(settings([n = uint32_t(v[0])](Options& s) { s.scene.copies = n; }), true);
        break;
    case ScriptOp::Msaa:
        step(settings([n = uint32_t(v[0])](Options& s) { s.render.pipeline.msaa = n; }), true);
        break;
    case ScriptOp::Clear: // checked when the script was parsed
        step(settings([p = *render::findClearPath(c.text)](Options& s) { s.render.clear = p; }),
             true);
        break;
    case ScriptOp::Screenshot:
        step([this, path = c.text] { viewer_.screenshot(path); }, true);
        break;
    case ScriptOp::Drop:
        step([this, path = c.text] { onDrop(path); }, true);
        break;
    case ScriptOp::Loaded:
        step([this] { waitForLoads(); }, true);
        break;
    case ScriptOp::Cancel:
        step([this] { viewer_.cancelLoads(); }, true);
        break;
    case ScriptOp::ClearRecent: // as the panel's entry does
        step([this] { viewer_.view().recentFiles.clear(); }, true);
        break;
    case ScriptOp::Frames: // empty steps, one frame each: what follows waits for them
        for (int i = 0; i < int(v[0]); ++i) step([] {}, true);
        break;
    case ScriptOp::Redraw: // with what follows at the same time, in the same frame
        step([this] { viewer_.redraw(); }, false);
        break;
    case ScriptOp::Blink:
        step(
            [this, weight = c.text] {
                viewer_.holdBlink(weight == "clock" ? std::nullopt
                                                    : std::optional(weight == "strong"));
            },
            true);
        break;
    case ScriptOp::Rest: // the steps after it wait, and the loop with them
        step([this, s = v[0]] { restUntil_ = scriptNow_ + s; }, false);
        break;
    case ScriptOp::Pipeline:
        if (c.text == "ready")
            step([this] { waitForPipelines(); }, true);
        else
            step([this, hold = c.text == "hold"] { viewer_.holdPipelineBuilds(hold); }, true);
        break;
    case ScriptOp::Quit:
        step([this] { viewer_.quit(); }, true);
        break;
    }
}

} // namespace app
