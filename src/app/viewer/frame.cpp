// frame.cpp - one frame of the viewer, step by step: the panel, the settings it changed,
// the slot, the pick, the swapchain image, the scene pass, the window image, present, and
// the screenshot and title that follow.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <numeric>

#include <imgui.h>

#include "app/camera_frame.h"
#include "app/image_io.h"
#include "app/viewer/commands/commands.h"
#include "app/viewer/panel/inspect_panel.h"
#include "app/viewer/state/kept_view.h" // maxRecentFiles
#include "app/viewer/viewer.h"
#include "render/blink.h"
#include "render/xray.h"
#include "scene/explode.h"
#include "scene/face_info.h"
#include "scene/formats.h"

namespace app {
namespace {

// The mean of the last `last` values (a vector of GPU times or the deque of CPU times).
template <typename Values>
double mean(const Values& values, size_t last) {
    const size_t n = std::min(values.size(), last);
    return n ? std::accumulate(values.end() - long(n), values.end(), 0.0) / double(n) : 0.0;
}

} // namespace

void Viewer::drawFrame(const FrameWants& wants) {
    const double seconds = wants.now;
    stepCensus(); // its next views, on slots of its own; what finished shows in this panel
    drawPanel();
    applySettings();
    render::FrameSlot& slot = slots_.begin(frameNumber_);
    // The hovered part comes from the ID image of each frame, scene pass or not.
    if (const auto click = picking_.readPick(slots_.latestHover(), document_))
        clickAnswered(*click);
    zoomWhenReady();
    if (const auto hovered = document_.selection().hovered(); hovered != saidHovered_) {
        saidHovered_ = hovered;
        events_.say("hovered", [&](util::JsonWriter& j) { j.member("part", hovered); });
    }
    // The cursor at its pixel's centre, as --edge-info takes it.
    const VkExtent2D extent = scene_.targets()->extent();
    const auto cursor = input_.cursorPixel(extent);
    edgeHover_.update(scene_.scene(), document_,
                      cursor ? std::optional(glm::dvec2(*cursor) + 0.5) : std::nullopt, viewProj_,
                      glm::dvec2(extent.width, extent.height));
    edgeHover_.tell(scene_.scene(), document_.selection(), events_);
    if (picking_.readPartSets(slots_.latestPartSets(), scene_.targets()->extent(), document_))
        selectionChanged();
    if (picking_.visibleParts() != saidVisible_) {
        saidVisible_ = picking_.visibleParts();
        events_.say("visible", [&](util::JsonWriter& j) { j.member("parts", saidVisible_); });
    }
    const auto image = presenter_.acquire(frameNumber_);
    if (!image) return; // out of date: the next frame makes a new swapchain first
    render::FrameParams params = frameParams(seconds);
    const SceneKey key = sceneKey(params);
    const bool scenePass =
        pacer_.needsScene(key, wants.continuous) || std::exchange(redrawNext_, false);
    recordScene(slot, params, scenePass);
    countHere(slot, scenePass);
    pacer_.drew(wants, scenePass, key);
    const std::string screenshot = std::exchange(screenshotPath_, {});
    presenter_.record(slot.cmd, *image, scene_.targets()->color(), changedTiles(),
                      !screenshot.empty());
    presenter_.present(slots_, slot, *image);
    if (!screenshot.empty()) saveScreenshot(screenshot);
    ++frameNumber_;
    updateTitle(seconds, false);
}

// The panel first: what it changes applies before this frame records anything.
void Viewer::drawPanel() {
    input_.feedPanelKeys(); // before ImGui's frame starts: its share of the key events
    presenter_.beginPanel(input_.cursorInWindow());
    // The tree row the selection makes up, found again only when the selection changes.
    if (document_.selection().selected() != namedSelection_) {
        namedSelection_ = document_.selection().selected();
        selectedRow_ = scene::rowOfParts(tree_, namedSelection_);
    }
    // Sizes, properties and distances: worked out when the selection or A and B changed.
    inspect_.update(scene_.scene(), tree_, document_.selection().selected(), document_.things(),
                    events_);
    act(view_.panelVisible ? app::drawPanel(settings_, view_, panelInfo()) : PanelActions{});
    // The box being dragged, over everything.
    if (const auto box = input_.boxInWindow())
        ImGui::GetForegroundDrawList()->AddRect(ImVec2(box->first.x, box->first.y),
                                                ImVec2(box->second.x, box->second.y),
                                                IM_COL32(255, 184, 26, 255), 0.0f, 0, 1.5f);
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    drawMeasure(document_.measure().points(), viewProj_, glm::vec2(display.x, display.y),
                scene_.scene().unit, scene_.scene().precision);
    edgeHover_.draw(viewProj_, glm::vec2(display.x, display.y));
    drawInspect(inspect_.report(), viewProj_, glm::vec2(display.x, display.y), scene_.scene().unit,
                scene_.scene().precision);
    if (const scene::CadPartial* partial = scene_.partial())
        drawWaitingBoxes(scene_.scene(), *partial, document_.selection().hidden(), viewProj_,
                         glm::vec2(display.x, display.y));
    drawOverlays();
    ImGui::Render();
}

// The panel's buttons and widgets ask for commands as keys and script lines do (commands.h).
// A widget let go settles its held change into one undo step; the steps the document
// recorded since the last frame, by keys, scripts or the panel, are told.
void Viewer::act(const PanelActions& actions) {
    for (const Command& command : actions.commands) execute(command, *this);
    if (actions.section) document_.setSection(*actions.section, actions.held);
    if (!actions.held) document_.settle();
    for (const ShownState& step : document_.takeSteps())
        events_.say("undo_step", [&](util::JsonWriter& j) { shownMembers(j, step); });
}

void Viewer::applySettings() {
    follow(scene_.poll(settings_.scene));
    if (!scene_.loading()) before_.reset(); // only Cancel during a load brings it back
    render::RenderSettings render = settings_.render;
    render.section = document_.section(); // the planes are the document's
    follow(scene_.apply(settings_.scene, render));
    explode();
    scene_.resize(presenter_.extent());
}

// The explode slider moved (or a script's `explode`): the CPU's scene follows what the GPU
// draws, so picks, measurements, face reports and F see the objects where they show, and the
// camera's planes take in the exploded scene; measure points placed before no longer lie on
// their parts. The animation (--animate) is drawn by the GPU alone, the CPU's scene at rest.
void Viewer::explode() {
    const float at = settings_.animation.animate ? 0.0f : document_.explode();
    if (!scene_.explode(at)) return;
    camera_.setBounds(scene_.scene().bounds());
    document_.forgetMeasurePoints();
    partDetails_ = PartDetailsCache{}; // the same arrays hold other placements now
    events_.say("explode", [&](util::JsonWriter& j) {
        j.member("at", util::Significant{double(at), 3});
    });
}

void Viewer::openDrops() {
    if (const auto result = chooser_.poll()) chosen(*result); // Open...'s file opens as a drop
    for (const std::string& path : input_.takeDrops()) {
        if (scene::formatOfName(path))
            scene_.startOpen(path, settings_.scene); // follow() once it has loaded
        else
            scene_.fail("'" + path + "' is no model file idview reads; it reads " +
                        scene::formatList());
    }
}

// A model file that opened joins the recent files, and the open field empties for the next.
void Viewer::remember(const std::string& source) {
    if (!scene::formatOfName(source)) return; // a generated scene
    auto& recent = view_.recentFiles;
    std::erase(recent, source);
    recent.insert(recent.begin(), source);
    if (recent.size() > maxRecentFiles) recent.pop_back();
    view_.openPath.fill('\0');
}

render::FrameParams Viewer::frameParams(double seconds) {
    const VkExtent2D extent = scene_.targets()->extent();
    const bool animate = settings_.animation.animate;
    render::FrameParams params =
        cameraFrame(camera_.camera(reach(), settings_.camera.ortho), extent);
    // F's fit beside the panel: a shift in clip space, the same for both matrices.
    params.viewProj = glm::mat4(camera_.shiftMatrix()) * params.viewProj;
    params.worldViewProj = camera_.shiftMatrix() * params.worldViewProj;
    // A time in the step of the blink it is held at (the first half of a period is strong).
    const double period = 1.0 / render::blinkHz;
    params.time = blinkHeld_ ? float(*blinkHeld_ ? 0.25 * period : 0.75 * period) : float(seconds);
    viewProj_ = params.worldViewProj;
    keepViewProj(frameNumber_, params.worldViewProj);
    params.pickPixel = picking_.pickPixel(input_.cursorPixel(extent), frameNumber_);
    params.hoveredTiles = slots_.latestHoveredTiles();
    // A released box asks for its parts (recordScene adds the visible parts' count).
    if (const auto box = picking_.boxQuery()) params.partSets.push_back(*box);
    showParts();
    showTint();
    params.explode = animate ? scene::explodeLoop(float(seconds)) : document_.explode();
    return params;
}

// Hands the selection and the hidden parts to the renderer once per change of the document,
// with X-ray's parts (render/xray.h): under X-ray a new selection hides and shows other parts.
// Hiding the first part needs the hiding pipeline variant: until its worker has built it, the
// parts stay drawn (asked again each frame); if it fails, nothing is hidden and X-ray goes off.
void Viewer::showParts() {
    if (drawnVersion_ == document_.version() && !scene_.pipelinePending()) return;
    render::Renderer& renderer = scene_.renderer();
    const Selection& selection = document_.selection();
    if (!drawnVersion_ || drawnSelection_ != document_.selectionVersion()) {
        renderer.setSelection(selection.selected());
        drawnSelection_ = document_.selectionVersion();
    }
    try {
        const render::XrayParts parts =
            render::xrayParts(document_.xray(), selection.selected(), selection.hidden());
        if (!scene_.showHidden(parts.hidden)) return;
        renderer.setTranslucent(scene_.scene(), parts.translucent);
    } catch (const std::exception& e) {
        scene_.fail(std::string("hiding parts: ") + e.what());
        document_.showAll();
        document_.setXray(false);
        renderer.setHidden(selection.hidden());
        renderer.setTranslucent(scene_.scene(), scene::PartSet(scene_.scene().uniquePartCount()));
    }
    drawnVersion_ = document_.version();
}

// The scene pass, or the picture composed again over the images the last one left. Only a
// scene pass can change which parts show, so only it counts them for the panel.
void Viewer::recordScene(render::FrameSlot& slot, render::FrameParams params, bool scenePass) {
    if (!scenePass) {
        scene_.renderer().recordComposition(slot, scene_.targets(), params);
        if (scene_.renderer().lastComposedTiles()) ++tileCompositions_;
        return;
    }
    const VkExtent2D extent = scene_.targets()->extent();
    params.partSets.insert(params.partSets.begin(),
                           render::PartSetQuery{{0, 0}, {extent.width - 1, extent.height - 1}});
    const auto start = Clock::now();
    scene_.renderer().record(slot, scene_.targets(), params);
    cpuRecordMs_.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    if (cpuRecordMs_.size() > 30) cpuRecordMs_.pop_front();
}

// The pixels of the scene image this frame's composition made again, when it made only the
// hovered part's tiles.
std::optional<VkRect2D> Viewer::changedTiles() const {
    const auto& tiles = scene_.renderer().lastComposedTiles();
    if (!tiles) return std::nullopt;
    const VkExtent2D extent = scene_.targets()->extent();
    const glm::uvec2 first = tiles->first * gpu::ID_PASS_TILE;
    const glm::uvec2 end = glm::min((tiles->first + tiles->count) * gpu::ID_PASS_TILE,
                                    glm::uvec2(extent.width, extent.height));
    if (glm::any(glm::lessThanEqual(end, first))) return VkRect2D{{0, 0}, {0, 0}};
    return VkRect2D{{int32_t(first.x), int32_t(first.y)}, {end.x - first.x, end.y - first.y}};
}

// The copy is done once the frame's fence has signalled: a screenshot waits for it.
void Viewer::saveScreenshot(const std::string& path) {
    slots_.finish();
    const VkExtent2D size = presenter_.capturedExtent();
    writePng(path, size.width, size.height, presenter_.capturedRgba());
    events_.say("screenshot", [&](util::JsonWriter& j) {
        j.member("path", path).member("width", size.width).member("height", size.height);
    });
}

PanelInfo Viewer::panelInfo() const {
    PanelInfo info;
    info.device = device_.info().name;
    info.cpuDevice = device_.info().type == VK_PHYSICAL_DEVICE_TYPE_CPU;
    info.events = &events_;
    for (const render::Technique& t : render::techniques())
        info.unavailable.push_back(render::unavailableReason(t, device_.info()));
    info.source = scene_.loaded().source;
    const scene::ModelFormat* format = scene::formatOfName(info.source);
    info.gltf = format && format->reader == scene::Reader::Gltf;
    info.error = scene_.error();
    if (const auto loading = scene_.loading())
        info.loading = PanelInfo::Loading{loading->path,     loading->seconds, loading->stage,
                                          loading->fraction, loading->shown,   loading->modelBefore,
                                          loading->stopping};
    info.incomplete = scene_.incomplete();
    if (const scene::CadPartial* partial = scene_.partial()) info.objectStates = &partial->state;
    if (const auto building = scene_.building())
        info.building = PanelInfo::Building{building->pipeline, building->seconds, building->then};
    info.scene = &scene_.scene();
    info.tree = &tree_;
    info.hidden = &document_.selection().hidden();
    info.stats = scene_.renderer().stats();
    info.lastSwitch = scene_.renderer().lastSwitch();
    info.cachedPipelines = scene_.renderer().cachedPipelines();
    info.idBytes = scene_.idBytes();
    info.sampleCounts = scene_.sampleCounts();
    info.clearPath = scene_.renderer().clearPath();
    info.clearTiming = scene_.renderer().clearTiming(scene_.renderer().settings().pipeline.msaa);
    info.fps = fps_;
    info.continuous = !presenter_.vsync();
    const auto& gpu = slots_.gpuMilliseconds();
    info.gpuMs = mean(gpu, 30);
    info.cpuRecordMs = mean(cpuRecordMs_, 30);
    for (size_t i = gpu.size() - std::min<size_t>(gpu.size(), 200); i < gpu.size(); ++i)
        info.gpuHistory.push_back(float(gpu[i]));
    auto describe = [&](std::optional<uint32_t> part, float depth) {
        const PartDetails& details = partDetails_.get(scene_.scene(), part);
        return PartLine{details.part, depth, details.face, {}};
    };
    info.hovered = describe(document_.selection().hovered(), picking_.hoveredDepth());
    const Selection& selection = document_.selection();
    info.selected = describe(selection.primary(), selectedDepth_);
    info.hovered.edge = edgeHover_.hoveredLine();
    info.selected.edge = edgeHover_.selectedLine();
    info.bounds = camera_.bounds();
    info.measuring = document_.measure().on();
    info.measureLines = measureLines(scene_.scene(), document_.measure().points());
    info.inspect = &inspect_.report();
    if (const auto& face = info.selected.face;
        face && face->surface.kind == scene::SurfaceKind::Plane)
        info.selectedPlane = face->surface;
    info.selectedCount = selection.selected().size();
    info.selectedParts = &selection.selected();
    info.selectedRow = selectedRow_;
    info.hiddenCount = selection.hidden().size();
    info.xray = document_.xray();
    info.section = document_.section();
    info.explode = document_.explode();
    for (size_t id = 0; id < commandCount; ++id) info.enabled[id] = enabled(CommandId(id), *this);
    info.visibleParts = picking_.visibleParts();
    info.idPassMs = mean(slots_.idPassMilliseconds(), 30);
    const render::Renderer& renderer = scene_.renderer();
    const render::PipelineKey& key = renderer.settings().pipeline;
    info.cullingApplied =
        render::describeCulling(*key.technique, *key.mode, renderer.settings().culling.mode);
    info.lodChosen = render::levelsChosenIn(*key.mode);
    info.totals = renderer.cullTotals();
    if (!slots_.cullStats().empty())
        info.drawn = render::countsOf(slots_.cullStats().back(), key.technique->usesMeshShader());
    const auto& times = slots_.frameTimes();
    const size_t last = std::min<size_t>(times.size(), 30);
    for (size_t i = times.size() - last; i < times.size(); ++i) {
        info.cullMs += times[i].cullMs / double(last);
        info.pyramidMs += times[i].pyramidMs / double(last);
    }
    if (census_.running()) info.censusProgress = {census_.viewsDrawn(), census_.views()};
    if (census_.found()) {
        info.census = &*census_.found();
        info.exportDefault = defaultExportPath(scene_.loaded());
        info.exportStep = info.census->scene->brep != nullptr;
    }
    info.censusTint = census_.tint();
    info.here = &census_.here();
    info.exporting = censusExport_.writing();
    info.exportLine = &censusExport_.line();
    return info;
}

// A few times a second for fps and GPU time; at once when what it names changes. With vsync
// on the viewer draws on change, so a frame rate would only count changes: the title gives
// the scene pass's time alone.
void Viewer::updateTitle(double seconds, bool now) {
    const render::PipelineKey& key = scene_.renderer().settings().pipeline;
    const bool continuous = !presenter_.vsync();
    // A model stopped while it loaded says so, and what it lacks.
    const std::string& incomplete = scene_.incomplete();
    const std::string what = std::string(key.technique->name) + " + " + key.mode->name +
                             " - vsync " + presenter_.vsyncState() +
                             (continuous ? ", continuous" : ", draws on change") +
                             (incomplete.empty() ? "" : " - incomplete: " + incomplete);
    // The model's file name first, as desktop applications name their document.
    const std::string& source = scene_.loaded().source;
    const std::string name =
        source.empty() ? "" : std::filesystem::path(source).filename().string();
    const std::string head = (name.empty() ? "" : name + " - ") + "idview - " + what;
    now = now || title_.find(head + " - ") != 0;
    if (!now && seconds - titleTime_ < 0.25) return;
    if (seconds > titleTime_) fps_ = double(frameNumber_ - titleFrame_) / (seconds - titleTime_);
    titleTime_ = seconds;
    titleFrame_ = frameNumber_;
    char text[1024];
    // A CPU device's timestamps time the CPU rendering (lavapipe).
    const bool cpu = device_.info().type == VK_PHYSICAL_DEVICE_TYPE_CPU;
    const char* timed = cpu ? "render (CPU device)" : "GPU";
    const double ms = mean(slots_.gpuMilliseconds(), 30);
    if (continuous)
        std::snprintf(text, sizeof text, "%s - %.0f fps - %s %.2f ms", head.c_str(), fps_, timed,
                      ms);
    else
        std::snprintf(text, sizeof text, "%s - %s %.2f ms", head.c_str(), timed, ms);
    if (title_ == text) return;
    title_ = text;
    window_.setTitle(title_);
    events_.say("title", [&](util::JsonWriter& j) { j.member("text", title_); });
}

} // namespace app
