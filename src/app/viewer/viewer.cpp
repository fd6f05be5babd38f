// viewer.cpp - the viewer's parts put together, the loop around the frames, and what input
// asks of the viewer as a whole.
#include "app/viewer/viewer.h"

#include <cctype>
#include <cstdio>

#include <imgui.h>

#include "app/camera_frame.h"
#include "app/cli.h"
#include "app/exit_code.h"
#include "app/measure_json.h"
#include "app/pipeline_cache_file.h"
#include "app/saved_settings.h"
#include "app/viewer/commands/commands.h"
#include "app/viewer/state/kept_view.h"
#include "scene/bounds.h"
#include "scene/part_data.h"
#include "vk/check.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace app {
namespace {

vk::DeviceInfo presentableDevice(const vk::Instance& instance, const std::string& request,
                                 VkSurfaceKHR surface) {
    const vk::DeviceInfo info = vk::chooseDevice(instance.devices(), request);
    vk::checkPresentSupport(info, surface);
    return info;
}

// The panel's layout and the recent files as the last run left them (kept_view.h).
ViewSettings keptView(const ViewerStart& start) {
    ViewSettings view;
    const std::string path = start.savedSettings ? savedSettingsPath() : "";
    if (!path.empty()) readKeptView(readSavedSettings(path), path, view, Events::problem);
    return view;
}

ViewerStart viewerStart(const Options& options) {
    return {.window = windowPlace(options),
            .device = options.device,
            .shaderDir = options.shaderDir,
            .validation = options.validation,
            .syncValidation = options.syncValidation,
            .script = options.script,
            .printEvents = options.printEvents,
            .savedSettings = options.savedSettings};
}

} // namespace

Viewer::Viewer(const ViewerStart& start, const LiveSettings& settings, Window& window,
               vk::Instance& instance, ScriptPlayer script)
    : startup_(start), settings_(settings), view_(keptView(start)), window_(window),
      events_(start.printEvents), surface_(instance, window.createSurface(instance)),
      device_(instance, presentableDevice(instance, start.device, surface_.handle()),
              {VK_KHR_SWAPCHAIN_EXTENSION_NAME}),
      compiler_(vk::ShaderCompiler::locate(start.shaderDir)),
      presenter_(window, instance, device_, surface_.handle()),
      scene_(device_, compiler_, events_, settings, presenter_.extent()),
      census_(device_, compiler_, pipelineCacheFolder(settings.scene),
              scene_.renderer().driverCache()),
      slots_(device_), input_(*this, window.handle(), std::move(script)) {
    const auto size = window.size(), position = window.position();
    events_.say("window", [&](util::JsonWriter& j) {
        j.member("width", size[0]).member("height", size[1]);
        j.member("x", position[0]).member("y", position[1]);
        j.member("recent_files", view_.recentFiles.size());
    });
    // Nothing is open until the model given at start shows (follow, from the frames' poll).
    // The command line's planes, explode and X-ray are the document's from here on; the
    // frames hand them to the renderer (applySettings, showParts).
    document_.newScene(scene_.scene().uniquePartCount(), settings_.render.section);
    document_.setExplode(settings_.animation.explode);
    document_.setXray(settings_.xray);
    settings_.render.section = {};
    settings_.animation.explode = 0.0f;
    settings_.xray = false;
    window.listen(input_);
    // A pipeline built on a worker wakes the resting loop, which then switches to it.
    scene_.renderer().onPipelineBuilt(&Window::wake);
}

Viewer::~Viewer() {
    window_.stopListening(); // the window outlives the viewer: no callback may reach it
}

double Viewer::elapsed() const {
    return start_ ? std::chrono::duration<double>(Clock::now() - *start_).count() : 0.0;
}

float Viewer::aspect() const {
    const VkExtent2D e = presenter_.extent();
    return e.height ? float(e.width) / float(e.height)
                    : float(startup_.window.width) / float(startup_.window.height);
}

void Viewer::reloadShaders() {
    scene_.reloadShaders();
}

void Viewer::selectionChanged() const {
    const Selection& selection = document_.selection();
    const auto part = selection.primary();
    const PartDetails& details = partDetails_.get(scene_.scene(), part);
    const auto& info = details.part;
    if (!info || selection.selected().size() > 1) { // a solid or assembly: its count
        const uint32_t count = selection.selected().size();
        events_.say("selected", [&](util::JsonWriter& j) {
            j.member("parts", count).member("part", std::nullopt);
        });
        return;
    }
    // Named as the assembly names it (its path ends with the object's name), then for a CAD
    // part its face: "board/R1", face 3, "cylinder r 0.5 mm, area 3.14159 mm²".
    const bool face = details.face && info->face;
    events_.say("selected", [&](util::JsonWriter& j) {
        j.member("parts", 1).member("part", info->uniquePartId).member("object", info->object);
        j.member("local_part", info->localPart).member("path", info->path);
        j.member("face", face ? info->face : std::nullopt);
        j.member("surface",
                 face ? std::optional(scene::describeSurface(*details.face)) : std::nullopt);
    });
}

void Viewer::keepViewProj(uint64_t frame, const glm::dmat4& viewProj) {
    drawnViewProj_.emplace_back(frame, viewProj);
    if (drawnViewProj_.size() > 8) drawnViewProj_.pop_front(); // picks come back sooner
}

std::optional<glm::dvec3> Viewer::pointUnderCursor() const {
    const auto& pick = picking_.hoverPick();
    if (!pick || !pick->part || !scene_.targets()) return std::nullopt; // background
    const VkExtent2D extent = scene_.targets()->extent();
    if (input_.cursorPixel(extent) != pick->pixel) return std::nullopt; // stale: moved since
    for (const auto& [frame, viewProj] : drawnViewProj_)
        if (frame == pick->frame)
            return scene::unprojectPixel(viewProj, glm::dvec2(extent.width, extent.height),
                                         glm::dvec2(pick->pixel) +
                                             glm::dvec2(scene_.targets()->pass().sampleZero()),
                                         pick->depth);
    return std::nullopt;
}

// The part under the cursor comes from a frame's ID image a frame or two after the cursor
// got there: wheel steps that come sooner wait for it (a few frames at most, then they zoom
// toward the target), so a quick move-and-scroll still zooms at the cursor.
void Viewer::zoomAtCursor(float steps) {
    if (!pendingZoom_ && !hoverIsCurrent()) pendingZoomFrame_ = frameNumber_;
    pendingZoom_ += steps;
    zoomWhenReady();
}

bool Viewer::hoverIsCurrent() const {
    const auto& pick = picking_.hoverPick();
    return pick && scene_.targets() &&
           input_.cursorPixel(scene_.targets()->extent()) == pick->pixel;
}

void Viewer::zoomWhenReady() {
    constexpr uint64_t patience = 4; // frames: the hover arrives two frames after the move
    if (!pendingZoom_ || (!hoverIsCurrent() && frameNumber_ < pendingZoomFrame_ + patience)) return;
    zoomNow(std::exchange(pendingZoom_, 0.0f));
}

void Viewer::zoomNow(float steps) {
    const auto point = pointUnderCursor();
    if (!point) {
        camera_.zoom(steps);
        events_.say("zoom", [](util::JsonWriter& j) { j.member("part", std::nullopt); });
        return;
    }
    camera_.zoomToward(*point, steps);
    // Where the point shows now, for the event line: on the cursor's pixel.
    const VkExtent2D extent = scene_.targets()->extent();
    const glm::dmat4 viewProj =
        camera_.shiftMatrix() *
        cameraFrame(camera_.camera(reach(), settings_.camera.ortho), extent).worldViewProj;
    const glm::dvec4 clip = viewProj * glm::dvec4(*point, 1.0);
    const glm::vec2 at = glm::vec2((glm::dvec2(clip) / clip.w * 0.5 + 0.5) *
                                   glm::dvec2(extent.width, extent.height)) -
                         scene_.targets()->pass().sampleZero();
    const glm::uvec2 pixel = picking_.hoverPick()->pixel;
    events_.say("zoom", [&](util::JsonWriter& j) {
        j.member("part", *picking_.hoverPick()->part);
        j.beginArray("pixel").value(pixel.x).value(pixel.y).endArray();
        j.beginArray("now_at").value(util::Fixed{at.x, 2}).value(util::Fixed{at.y, 2}).endArray();
    });
}

void Viewer::fitView() {
    // The selection; else the parts not hidden (isolated ones); else the whole scene; framed
    // in the area the panel leaves free.
    const Selection& selection = document_.selection();
    const scene::Scene& scene = scene_.scene();
    const FreeSpan span = panelSpan();
    scene::Bounds bounds = scene::partsWorldBounds(scene, selection.selected());
    const char* what = "selection";
    if (scene::isEmpty(bounds) && !selection.hidden().empty()) {
        scene::PartSet shown = selection.hidden();
        shown.invert();
        bounds = scene::partsWorldBounds(scene, shown);
        what = "shown parts";
    }
    if (scene::isEmpty(bounds)) {
        camera_.fit(aspect(), span);
        what = "scene";
    } else {
        camera_.fit(bounds, aspect(), span);
    }
    events_.say("fit", [&](util::JsonWriter& j) { j.member("what", what); });
}

FreeSpan Viewer::panelSpan() const {
    if (!view_.panelVisible) return {};
    int width = 0, height = 0;
    glfwGetWindowSize(window_.handle(), &width, &height);
    // Before the first frame (the model given at start) the panel is not placed yet: where
    // it opens, at its width. Later both sides are 0 while it is collapsed.
    if (frameNumber_ == 0)
        return freeSpan(float(width), panelMargin, panelMargin + view_.panelWidth);
    return freeSpan(float(width), view_.panelLeft, view_.panelRight);
}

void Viewer::sayFitted() const {
    // The window x range the scene's bounds cover, for scripts to check against the panel.
    const VkExtent2D extent = presenter_.extent();
    const glm::dmat4 viewProj =
        camera_.shiftMatrix() *
        cameraFrame(camera_.camera(1.0f, settings_.camera.ortho), extent).worldViewProj;
    const scene::Bounds& b = camera_.bounds();
    float left = float(extent.width), right = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec4 clip = viewProj * glm::dvec4((corner & 1) ? b.max.x : b.min.x,
                                                      (corner & 2) ? b.max.y : b.min.y,
                                                      (corner & 4) ? b.max.z : b.min.z, 1.0);
        const float x = float((clip.x / clip.w * 0.5 + 0.5) * double(extent.width));
        left = std::min(left, x);
        right = std::max(right, x);
    }
    const FreeSpan span = panelSpan();
    events_.say("opened_fitted", [&](util::JsonWriter& j) {
        j.member("left", util::Fixed{left, 0}).member("right", util::Fixed{right, 0});
        j.member("free_left", util::Fixed{span.left * float(extent.width), 0});
        j.member("free_right", util::Fixed{span.right * float(extent.width), 0});
        j.member("width", extent.width);
    });
}

void Viewer::turnTo(const scene::StandardView& view) {
    camera_.turnTo(view);
    events_.say("view", [&](util::JsonWriter& j) { j.member("name", view.name); });
}

void Viewer::setOrtho(bool ortho) {
    settings_.camera.ortho = ortho;
    events_.say("projection", [&](util::JsonWriter& j) { j.member("ortho", ortho); });
}

void Viewer::setXray(bool on) {
    document_.setXray(on); // shown by the next frame's showParts
    events_.say("xray", [&](util::JsonWriter& j) { j.member("on", on); });
}

void Viewer::partsChanged() const {
    events_.say("hidden", [&](util::JsonWriter& j) {
        j.member("parts", document_.selection().hidden().size());
    });
}

void Viewer::selectObjects(const std::string& name, SelectMode mode) {
    const scene::Scene& scene = scene_.scene();
    scene::PartSet parts(scene.uniquePartCount());
    for (const scene::Object& object : scene.objects)
        if (object.name == name) {
            const uint32_t count = scene.geometries[object.geometry].partCount;
            for (uint32_t p = 0; p < count; ++p) parts.insert(object.uniquePartOffset + p);
        }
    document_.select(parts, mode);
    selectionChanged();
}

// The pick of the next frame (at this cursor position) decides what a click hits; a
// double-click selects the object (a CAD solid) at least.
void Viewer::clicked(bool add, bool twice) {
    const uint32_t level = twice ? std::max(1u, view_.selectLevel) : view_.selectLevel;
    picking_.click(frameNumber_, level, add);
}

// The parts come from the ID image of a frame after the release.
void Viewer::boxed(glm::dvec2 a, glm::dvec2 b, SelectMode mode) {
    if (!scene_.targets()) return;
    const VkExtent2D extent = scene_.targets()->extent();
    picking_.box(render::spanning(input_.imagePixel(a, extent), input_.imagePixel(b, extent)), mode,
                 frameNumber_);
}

void Viewer::clickAnswered(const Picking::Click& click) {
    if (document_.measure().on()) return measured(click.pick); // a point, nothing selected
    ClickedThing clickedThing{std::nullopt, {}, click.add, click.level == 0};
    if (const auto part = click.pick.part) {
        // At the face level an edge under the cursor (edge_hover.h) is the thing, not its face.
        const auto edge = click.level == 0 ? document_.selection().hoveredEdge() : std::nullopt;
        clickedThing.around = partsAround(*part, click.level);
        clickedThing.thing = makeThing(scene_.scene(), tree_, clickedThing.around, *part, edge);
    }
    document_.click(std::move(clickedThing));
    selectedDepth_ = click.pick.depth;
    selectionChanged();
}

scene::PartSet Viewer::partsAround(uint32_t part, uint32_t level) const {
    const scene::Scene& scene = scene_.scene();
    return scene::partSetOf(scene::partsAround(scene, part, level), scene.uniquePartCount());
}

bool Viewer::actOnNode(const NodeTarget& node) {
    const auto row = rowOfNode(tree_, node);
    if (!row) return false;
    const scene::PartSet parts =
        scene::partSetOf(tree_[*row].parts, scene_.scene().uniquePartCount());
    const scene::PartSet before = document_.selection().selected();
    const bool select = node.action == NodeAction::Select || node.action == NodeAction::Add;
    if (select)
        document_.select(parts,
                         node.action == NodeAction::Add ? SelectMode::Add : SelectMode::Replace);
    if (node.action == NodeAction::Hide) document_.hide(parts);
    if (node.action == NodeAction::Show) document_.show(parts);
    if (select || document_.selection().selected() != before) selectionChanged();
    if (!select) partsChanged();
    return true;
}

void Viewer::run() {
    while (!window_.closing() && !input_.failure() && !scene_.firstFailure()) {
        window_.pollEvents();
        openDrops();
        if (!presenter_.ready(view_.vsync)) { // minimised: render nothing, sleep until woken
            window_.waitEvents(scriptStart_ ? input_.wakeIn(scriptSeconds()) : std::nullopt);
            continue;
        }
        if (!start_) start_ = Clock::now();
        if (!scriptStart_ && !scene_.waitingForFirst()) scriptStart_ = Clock::now();
        if (scriptStart_) input_.runScript(scriptSeconds());
        if (window_.closing() || input_.failure()) break;
        const FrameWants wants = frameWants();
        if (pacer_.due(wants)) {
            drawFrame(wants);
            rested_ = false;
            continue;
        }
        rest();
        window_.waitEvents(pacer_.rest(wants));
    }
    // A load still running stops now: its workers are killed, and the thread waited for at
    // the end is one that has seen the cancel, not one that goes on to the model's end.
    if (const auto loading = scene_.loading(); loading && !loading->stopping) {
        events_.say("loading", [](util::JsonWriter& j) {
            j.member("state", "cancelled").member("after", "window closed");
        });
        scene_.cancelOpen();
    }
    slots_.finish();
    if (input_.failure()) std::rethrow_exception(input_.failure());
    // The model given at start failed: the run ends with its message (exit 1), as it did when
    // that model was loaded before the window showed.
    if (const auto& failed = scene_.firstFailure()) throw scene::ModelError(*failed);
    savePipelineCache(scene_.renderer());
}

double Viewer::scriptSeconds() const {
    return scriptStart_ ? std::chrono::duration<double>(Clock::now() - *scriptStart_).count() : 0.0;
}

FrameWants Viewer::frameWants() const {
    FrameWants wants;
    wants.now = elapsed();
    wants.events = window_.events() + input_.stepsRun(); // scripted input counts as input
    wants.continuous = !view_.vsync;
    // A selection the Inspect section has not asked about yet, or its answer landed: a frame
    // for it. While the worker works the answer out, the loop may rest: the answer wakes it.
    wants.busy = input_.waiting() || picking_.waiting() || !screenshotPath_.empty() ||
                 pendingZoom_ != 0.0f || censusDrawing() || censusExport_.landed() ||
                 inspect_.due(document_.selection().selected(), document_.things());
    wants.loading = loading() || pipelinePending(); // progress lines in the panel
    wants.hovering = document_.selection().hovered().has_value();
    if (scriptStart_) wants.scriptWake = input_.wakeIn(scriptSeconds());
    if (!shell_.notice.empty()) wants.changeAt = shell_.noticeUntil; // the notice goes then
    return wants;
}

SceneKey Viewer::sceneKey(const render::FrameParams& params) const {
    const render::Renderer& renderer = scene_.renderer();
    SceneKey key;
    key.origin = params.origin;
    key.viewProj = params.viewProj;
    key.eye =
        params.orthoToViewer ? glm::vec4(*params.orthoToViewer, 0.0f) : glm::vec4(params.eye, 1.0f);
    key.explode = params.explode;
    key.targets = scene_.targets().get();
    key.renderer = renderer.changes();
    key.pipeline = renderer.pipeline();
    key.settings = renderer.settings();
    key.settings.edges = {}; // composed over the scene pass's images
    return key;
}

// The tests read this line to count the scene passes while nothing moves.
void Viewer::rest() {
    if (rested_) return;
    rested_ = true;
    events_.say("rest", [&](util::JsonWriter& j) {
        j.member("scene_passes", pacer_.scenePasses())
            .member("compositions", pacer_.compositions());
        j.member("hover_tiles", tileCompositions_).member("panel_kept", presenter_.keptPanels());
    });
}

// The one place the viewer reads the command line: what it starts with, and its live settings.
int runViewer(const Options& options) {
    const ViewerStart start = viewerStart(options);
    // A bad script fails before any window opens.
    ScriptPlayer script(start.script.empty() ? std::vector<ScriptLine>{}
                                             : loadScript(start.script));
    Window window(start.window.width, start.window.height, start.window.position);
    vk::Instance instance({start.validation, window.vulkanExtensions(), start.syncValidation});
    {
        Viewer viewer(start, options.live, window, instance, std::move(script));
        viewer.run();
        if (start.savedSettings) {
            // The window as it closes opens next time: its size and place are --size and
            // --window-pos lines, the panel and the recent files the viewer's own.
            const auto size = window.size();
            const WindowPlace closed{uint32_t(std::max(size[0], 1)), uint32_t(std::max(size[1], 1)),
                                     window.position()};
            writeSavedSettings(savedSettingsPath(), viewer.settings(), closed, Events::problem,
                               keptViewText(viewer.view()));
        }
    }
    return exitCode(instance.validationMessages());
}

void Viewer::resetSettings() {
    resetSavedSettings(settings_);
    if (startup_.savedSettings)
        writeSavedSettings(
            savedSettingsPath(), settings_, startup_.window,
            [this](const std::string& message) { scene_.fail(message); }, keptViewText(view_));
    events_.say("settings", [](util::JsonWriter& j) { j.member("reset", true); });
}

void Viewer::toggleMeasure() {
    document_.toggleMeasure();
    events_.say("measure", [&](util::JsonWriter& j) { j.member("on", document_.measure().on()); });
}

// The point is where the pick's depth puts the surface, in the view of the newest frame: a
// click does not move the camera, so that is the view the pick was taken in.
void Viewer::measured(const render::PickReading& pick) {
    if (!pick.part) return; // background: nothing to measure
    const VkExtent2D extent = scene_.targets()->extent();
    const glm::dvec3 world = scene::unprojectPixel(
        viewProj_, glm::dvec2(extent.width, extent.height),
        glm::dvec2(pick.pixel) + glm::dvec2(scene_.targets()->pass().sampleZero()), pick.depth);
    document_.addMeasurePoint({world, *pick.part});
    const auto& points = document_.measure().points();
    std::array<std::optional<glm::dvec3>, 2> at;
    std::array<std::optional<uint32_t>, 2> parts;
    for (size_t i = 0; i < points.size(); ++i) {
        at[i] = points[i].world;
        parts[i] = points[i].part;
    }
    events_.say("measure", [&](util::JsonWriter& j) {
        measureMembers(j.member("on", true).beginObject("measured"), at, parts,
                       scene_.scene().unit);
        j.endObject();
    });
}

} // namespace app
