// panel.cpp - the panel: the open field, view toggles, renderer settings, scene, statistics,
// timing and help; its layout, the part a newcomer needs first at the top.
#include "app/viewer/panel.h"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <type_traits>
#include <utility>

#include <imgui.h>

#include "app/viewer/panel_section.h"
#include "app/viewer/panel_selection.h"
#include "app/viewer/panel_tree.h"
#include "render/culling.h"
#include "render/technique.h"
#include "scene/lod.h"

namespace app {
namespace {

const char* const controlsHelp = "left drag          orbit\n"
                                 "right/middle drag  pan\n"
                                 "wheel              zoom towards the target\n"
                                 "left click         select the part (background: clear)\n"
                                 "shift + left drag  select the parts in the box\n"
                                 "ctrl/alt + drag    add them / remove them\n"
                                 "H / I              hide / isolate the selection\n"
                                 "shift + H          show all parts\n"
                                 "E                  part edges on/off\n"
                                 "M                  measure: click points and faces\n"
                                 "Esc                clear selection; if none, quit\n"
                                 "F                  fit the selection (or the shown\n"
                                 "                   parts) beside the panel\n"
                                 "1 / 3 / 7          front / right / top view\n"
                                 "ctrl + 1 / 3 / 7   back / left / bottom view\n"
                                 "0                  isometric view\n"
                                 "2 / 4 / 5 / 6      FreeCAD's top / back / bottom / left\n"
                                 "O                  orthographic / perspective\n"
                                 "Home               reset the view\n"
                                 "R                  reload shaders, clear pipeline caches\n"
                                 "V                  vsync on/off\n"
                                 "F1                 hide/show this panel\n"
                                 "drop a file        open it (.gltf .glb .step .stp .iges\n"
                                 "                   .igs .brep); or type its path in\n"
                                 "                   the open field (ctrl + L)\n"
                                 "ctrl + O           Open...: the desktop's file chooser";

// When to choose which technique, from the H100 figures in docs/benchmarks.md.
const char* const techniqueHelp =
    "On an H100 at 1440p, against drawing with no part IDs:\n"
    "vertex-fs: 1.00-1.02x with and without MSAA, one draw per object, no mesh shaders. "
    "Start here.\n"
    "mesh-vertex-fs: 1.00-1.01x without MSAA (and the faster pipeline there), 1.04x with "
    "4x MSAA in the mdi modes (1.00x with push).\n"
    "tri-fs, search-fs, bsearch-fs, nsearch-fs: 1.03x with 4x MSAA, 1.24x without "
    "(gl_PrimitiveID).\n"
    "gs techniques and mesh-fs (per-primitive output): 1.3-1.6x, avoid.\n"
    "per-draw: one draw per part, 1.1-1.3x and CPU-bound with push constants.\n"
    "Numbers and method: docs/benchmarks.md.";

std::string bytes(uint64_t value) {
    char text[32];
    if (value >= 10ull << 20)
        std::snprintf(text, sizeof text, "%.1f MB", double(value) / (1 << 20));
    else if (value >= 10ull << 10)
        std::snprintf(text, sizeof text, "%.1f KB", double(value) / (1 << 10));
    else
        std::snprintf(text, sizeof text, "%llu B", static_cast<unsigned long long>(value));
    return text;
}

// A combo over a registry (techniques or modes), pointing `current` at the chosen entry.
template <typename Entry>
void registryCombo(const char* label, const Entry*& current, const std::vector<Entry>& entries) {
    if (!ImGui::BeginCombo(label, current->name)) return;
    for (const Entry& entry : entries) {
        if (ImGui::Selectable(entry.name, &entry == current)) current = &entry;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", entry.description);
    }
    ImGui::EndCombo();
}

// A slider applied on release, not on every step of a drag: each value is its own pipeline
// or draw list. Only one slider is dragged at a time, so one value in flight is enough.
template <typename T>
void sliderOnRelease(const char* label, T& value, T min, T max) {
    static ImGuiID editing = 0;
    static T editingValue{};
    const ImGuiID id = ImGui::GetID(label);
    T shown = editing == id ? editingValue : value;
    if constexpr (std::is_same_v<T, float>)
        ImGui::SliderFloat(label, &shown, min, max, "%.2f");
    else
        ImGui::SliderScalar(label, ImGuiDataType_U32, &shown, &min, &max);
    if (ImGui::IsItemActive()) {
        editing = id;
        editingValue = shown;
    } else if (editing == id) {
        editing = 0;
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) value = shown;
}

void sliderOnRelease(const char* label, uint32_t& value, render::Range range) {
    sliderOnRelease(label, value, range.min, range.max);
}

void narySearch(render::NarySearch& n) {
    sliderOnRelease("N-ary fan-out", n.n, render::nsearchFanOutRange);
    ImGui::Checkbox("N-ary initial guess", &n.guess);
    sliderOnRelease("N-ary linear below", n.linearBelow, render::nsearchLinearRange);
    sliderOnRelease("N-ary max steps", n.maxSteps, render::nsearchStepsRange);
}

// The renderer combo: what the device cannot run is listed, greyed, with the reason.
void techniqueCombo(const render::Technique*& current, const PanelInfo& info) {
    if (!ImGui::BeginCombo("renderer", current->name)) return;
    const auto& all = render::techniques();
    for (size_t i = 0; i < all.size(); ++i) {
        const bool usable = i >= info.unavailable.size() || info.unavailable[i].empty();
        ImGui::BeginDisabled(!usable);
        if (ImGui::Selectable(all[i].name, &all[i] == current)) current = &all[i];
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("%s%s%s", all[i].description, usable ? "" : "\nunavailable: ",
                              usable ? "" : info.unavailable[i].c_str());
    }
    ImGui::EndCombo();
}

std::string counted(uint64_t drawn, uint64_t total) {
    char text[64];
    std::snprintf(text, sizeof text, "%llu of %llu (%.0f%%)",
                  static_cast<unsigned long long>(drawn), static_cast<unsigned long long>(total),
                  total ? 100.0 * double(drawn) / double(total) : 0.0);
    return text;
}

// The culling mode, freezing its lists, what this technique and mode get of it, and what the
// newest frame drew.
void culling(render::CullSettings& c, const PanelInfo& info) {
    if (ImGui::BeginCombo("culling", render::cullModeName(c.mode))) {
        for (const render::CullModeEntry& entry : render::cullModes()) {
            if (ImGui::Selectable(entry.name, entry.mode == c.mode)) c.mode = entry.mode;
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", entry.description);
        }
        ImGui::EndCombo();
    }
    ImGui::BeginDisabled(c.mode == render::CullMode::Off);
    ImGui::Checkbox("freeze culling", &c.freeze);
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("keep drawing what the last culled frame chose while the camera "
                          "moves: fly around to see what was left out");
    ImGui::TextDisabled("%s", info.cullingApplied.c_str());
    if (info.listsReused) {
        ImGui::TextDisabled("still view: the last culled frame's lists drawn again");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("the view has not changed since two frames were culled: what "
                              "they drew is drawn again without culling, so the cull and "
                              "pyramid times fall to nothing until the camera moves");
    }
    ImGui::Text("draws drawn    %s", counted(info.drawn.draws, info.totals.draws).c_str());
    if (info.totals.meshlets)
        ImGui::Text("meshlets       %s",
                    counted(info.drawn.meshlets, info.totals.meshlets).c_str());
    ImGui::Text("triangles      %s", counted(info.drawn.triangles, info.totals.triangles).c_str());
}

// Levels of detail: how many the scene has (a reload), the error the cull pass chooses them
// by, the tint, and the triangles the newest frame drew at each.
void levelsOfDetail(Options& settings, const PanelInfo& info) {
    sliderOnRelease("LOD levels built", settings.scene.lodLevels, 1u, scene::maxLevels);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("levels of detail built when the scene loads, full detail included "
                          "(changing it reloads the scene)");
    const bool usable = settings.scene.lodLevels > 1 && info.lodChosen;
    ImGui::BeginDisabled(!usable);
    ImGui::SliderFloat("LOD error [px]", &settings.render.lod.errorPixels, 0.0f, 8.0f, "%.2f");
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", !usable && settings.scene.lodLevels < 2
                                    ? "build levels of detail first (LOD levels built)"
                                : !usable ? "levels are chosen by the cull pass: culling "
                                            "frustum or occlusion in an mdi mode"
                                          : "each object drawn at its coarsest level whose "
                                            "error stays under this many pixels; 0: full "
                                            "detail");
    ImGui::Checkbox("tint by level", &settings.render.shading.tintLevels);
    // The colours of shading.glsl's levelTint, as displayed.
    static const ImVec4 tints[] = {{0.87f, 0.87f, 0.87f, 1},
                                   {0.35f, 0.76f, 0.98f, 1},
                                   {0.98f, 0.88f, 0.35f, 1},
                                   {0.95f, 0.48f, 0.58f, 1}};
    if (settings.render.lod.errorPixels <= 0.0f || !usable) return;
    for (uint32_t l = 0; l < info.drawn.levelTriangles.size(); ++l) {
        ImGui::TextColored(tints[l], "level %u", l);
        ImGui::SameLine();
        ImGui::Text("%llu triangles",
                    static_cast<unsigned long long>(info.drawn.levelTriangles[l]));
    }
}

void rendering(Options& settings, const PanelInfo& info, PanelActions& actions) {
    render::RenderSettings& s = settings.render;
    render::PipelineKey& key = s.pipeline;
    techniqueCombo(key.technique, info);
    registryCombo("per-draw mode", key.mode, render::drawModes());
    if (key.technique->readsSearchBatch())
        sliderOnRelease("search batch", key.searchBatch, render::searchBatchRange);
    if (key.technique->narySearch) narySearch(key.nsearch);
    sliderOnRelease("visible objects", s.draws.visible, 0.0f, 1.0f);
    ImGui::SliderFloat("part weight", &s.shading.partWeight, 0.0f, 1.0f, "%.2f");
    ImGui::Checkbox("colorize draws", &s.shading.colorizeDraws);
    ImGui::Checkbox("ignore materials", &s.shading.ignoreMaterials);
    ImGui::Checkbox("sort draws once", &s.draws.sortDraws);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("sort the draw list by geometry, then material, when it is built "
                          "(--no-sort-draws: scene order)");
    char label[8];
    std::snprintf(label, sizeof label, "%ux", key.msaa);
    if (ImGui::BeginCombo("MSAA", label)) {
        for (uint32_t n = 1; n <= 8; n *= 2) {
            if (!(info.sampleCounts & n)) continue; // only what the device renders
            std::snprintf(label, sizeof label, "%ux", n);
            if (ImGui::Selectable(label, n == key.msaa)) key.msaa = n;
        }
        ImGui::EndCombo();
    }
    // Edge settings stay in place, greyed while edges are off: E moves nothing below.
    render::EdgeSettings& edges = s.edges;
    ImGui::BeginDisabled(!edges.on);
    const render::Range widths = render::edgeWidthRange;
    ImGui::SliderScalar("edge width", ImGuiDataType_U32, &edges.width, &widths.min, &widths.max);
    ImGui::ColorEdit3("edge colour", &edges.color.x, ImGuiColorEditFlags_NoInputs);
    ImGui::SameLine();
    ImGui::ColorEdit3("selected", &edges.selectColor.x, ImGuiColorEditFlags_NoInputs);
    ImGui::SameLine();
    ImGui::ColorEdit3("hovered", &edges.hoverColor.x, ImGuiColorEditFlags_NoInputs);
    ImGui::EndDisabled();
    culling(s.culling, info);
    levelsOfDetail(settings, info);
    ImGui::Checkbox("animate (exploded view)", &settings.animation.animate);
    // What the last switch cost: a cached pipeline makes it a lookup.
    const render::SwitchReport& last = info.lastSwitch;
    ImGui::Text("last switch %.2f ms, pipeline %s%s", last.ms,
                last.pipelineCached ? "cached" : "built", last.drawsKept ? ", draws kept" : "");
    ImGui::Text("pipelines cached %zu (R clears)", info.cachedPipelines);
    actions.resetSettings = ImGui::Button("Reset to defaults");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the settings kept between runs (renderer, mode, MSAA, edges, "
                          "culling, levels of detail, projection) back to the defaults");
}

void sceneSection(SceneSettings& s, const PanelInfo& info) {
    int copies = int(s.copies);
    if (ImGui::InputInt("model copies", &copies, 1, 4, ImGuiInputTextFlags_EnterReturnsTrue))
        s.copies = uint32_t(std::clamp(copies, 1, 256));
    ImGui::Text("copies along");
    for (uint32_t bit = 0; bit < 3; ++bit) {
        ImGui::SameLine();
        bool on = s.copyAxes & (1u << bit);
        const char* names[] = {"x", "y", "z"};
        // At least one axis stays on: unticking the last one is ignored.
        if (ImGui::Checkbox(names[bit], &on) && (on || (s.copyAxes & ~(1u << bit))))
            s.copyAxes = on ? (s.copyAxes | (1u << bit)) : (s.copyAxes & ~(1u << bit));
    }
    if (info.gltf) {
        int parts = int(s.parts);
        ImGui::Text("parts");
        ImGui::SameLine();
        ImGui::RadioButton("primitives", &parts, int(scene::PartMode::Primitives));
        ImGui::SameLine();
        ImGui::RadioButton("components", &parts, int(scene::PartMode::Components));
        s.parts = scene::PartMode(parts);
    }
    if (!info.scene) return;
    const scene::Scene& scene = *info.scene;
    ImGui::Text("draw calls     %zu", info.stats.draws);
    ImGui::Text("triangles      %llu", static_cast<unsigned long long>(info.stats.triangles));
    ImGui::Text("parts          %u", scene.uniquePartCount());
    ImGui::Text("objects        %zu", scene.objects.size());
    ImGui::Text("triangle IDs   %s", bytes(info.idBytes.trianglePartIds).c_str());
    ImGui::Text("part counts    %s", bytes(info.idBytes.partTriangleCounts).c_str());
    ImGui::Text("part offsets   %s", bytes(info.idBytes.partTriangleOffsets).c_str());
    // What the current renderer and mode uploaded.
    ImGui::Text("renderer IDs   %s", bytes(info.stats.idBufferBytes).c_str());
    ImGui::Text("per-draw data  %s + %s indirect", bytes(info.stats.perDrawBytes).c_str(),
                bytes(info.stats.indirectBytes).c_str());
    if (info.stats.geometryBytes)
        ImGui::Text("own geometry   %s", bytes(info.stats.geometryBytes).c_str());
    if (info.stats.geometryBytes) // every derived geometry is cut from part vertices
        ImGui::Text("added vertices %llu (%s)",
                    static_cast<unsigned long long>(info.stats.addedVertices),
                    bytes(info.stats.addedVertexBytes).c_str());
    if (info.stats.meshlets)
        ImGui::Text("meshlets       %llu", static_cast<unsigned long long>(info.stats.meshlets));
}

void timing(const PanelInfo& info) {
    ImGui::Text("Render GPU [ms]  %.3f", info.gpuMs);
    ImGui::Text("ID passes  [ms]  %.3f", info.idPassMs);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("edges and outlines, the visible part count and box selection: "
                          "compute passes over the ID image after the scene pass");
    ImGui::Text("cull, pyramid [ms] %.3f, %.3f", info.cullMs, info.pyramidMs);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("GPU time of the cull passes (and the visible-part pass culling "
                          "reads) and of the depth pyramid; included in Render GPU");
    ImGui::Text("CPU record [ms]  %.3f", info.cpuRecordMs);
    if (!info.gpuHistory.empty())
        ImGui::PlotLines("##gpu", info.gpuHistory.data(), int(info.gpuHistory.size()), 0,
                         "scene pass GPU ms", 0.0f, FLT_MAX, ImVec2(310, 60));
}

// The recent files' list: a file no longer there is greyed out (it may come back: a
// network drive, a USB stick), and the last entry empties the list.
void recentFiles(ViewSettings& view, PanelActions& actions) {
    ImGui::BeginDisabled(view.recentFiles.empty());
    if (ImGui::BeginCombo("##recent", nullptr, ImGuiComboFlags_NoPreview)) {
        for (const std::string& path : view.recentFiles) {
            std::error_code error;
            const bool there = std::filesystem::exists(path, error); // only while open
            if (ImGui::Selectable(path.c_str(), false,
                                  there ? ImGuiSelectableFlags_None
                                        : ImGuiSelectableFlags_Disabled))
                actions.open = path;
        }
        ImGui::Separator();
        if (ImGui::Selectable("clear list")) view.recentFiles.clear();
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s",
                          view.recentFiles.empty() ? "recent files: none yet" : "recent files");
}

// The model path field, the width of the panel so its hint shows whole, with the recent
// files beside it. Clicking it, or Ctrl+O, selects what it holds: typing replaces it.
void openField(ViewSettings& view, PanelActions& actions) {
    const float spacing = ImGui::GetStyle().ItemInnerSpacing.x;
    const char* chooseLabel = "Open...";
    const float chooseWidth =
        ImGui::CalcTextSize(chooseLabel).x + 2.0f * ImGui::GetStyle().FramePadding.x;
    const float recentWidth = ImGui::GetFrameHeight();
    if (std::exchange(view.focusOpen, false)) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - recentWidth - chooseWidth -
                            2.0f * spacing);
    if (ImGui::InputTextWithHint("##open", "open .gltf .glb .step .iges .brep",
                                 view.openPath.data(), view.openPath.size(),
                                 ImGuiInputTextFlags_EnterReturnsTrue |
                                     ImGuiInputTextFlags_AutoSelectAll) &&
        view.openPath[0])
        actions.open = std::string(view.openPath.data());
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("type or paste a model's path, Enter opens it; or drop the file on "
                          "the window");
    ImGui::SameLine(0.0f, spacing);
    if (ImGui::Button(chooseLabel)) actions.chooseFile = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("choose a model file (Ctrl+O)");
    ImGui::SameLine(0.0f, spacing);
    recentFiles(view, actions);
}

// What a newcomer reaches for first, always in view: edges, projection, vsync, the views.
void viewRow(Options& settings, ViewSettings& view, PanelActions& actions) {
    ImGui::Checkbox("edges (E)", &settings.render.edges.on);
    ImGui::SameLine();
    ImGui::Checkbox("ortho (O)", &settings.camera.ortho);
    ImGui::SameLine();
    ImGui::Checkbox("vsync (V)", &view.vsync);
    // The standard views, as their keys turn to them (1, 3, 7, Ctrl, 0), wrapped to the
    // panel's width.
    const ImGuiStyle& style = ImGui::GetStyle();
    for (const scene::StandardView& standard : scene::standardViews()) {
        const float width = ImGui::CalcTextSize(standard.name).x + 2.0f * style.FramePadding.x;
        if (&standard != scene::standardViews().data()) {
            ImGui::SameLine();
            if (ImGui::GetContentRegionAvail().x < width) ImGui::NewLine();
        }
        if (ImGui::SmallButton(standard.name)) actions.view = &standard;
    }
}

void status(const PanelInfo& info, PanelActions& actions) {
    ImGui::TextDisabled("%s, %.0f fps", info.device.c_str(), info.fps);
    if (!info.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", info.error.c_str());
        ImGui::PopStyleColor();
    }
    if (const auto& loading = info.loading) {
        // CAD loads report their stage and how far it is; glTF loads report nothing, and the
        // bar sweeps once a second while they run.
        const double t = loading->seconds;
        char label[96];
        std::snprintf(label, sizeof label, "%s %.0f%%, %.1f s",
                      loading->stage.empty() ? "loading" : loading->stage.c_str(),
                      100.0 * loading->fraction, t);
        ImGui::TextWrapped("%s", loading->path.c_str());
        const double shown = loading->stage.empty() ? t - std::floor(t) : loading->fraction;
        ImGui::ProgressBar(float(shown), ImVec2(-1, 0), label);
        // CAD loads stop at their next face or progress step; glTF loads run to their end.
        if (ImGui::Button("Cancel")) actions.cancelLoad = true;
    }
}

} // namespace

PanelActions drawPanel(Options& settings, ViewSettings& view, const PanelInfo& info) {
    PanelActions actions;
    view.panelLeft = view.panelRight = 0.0f; // until it is drawn, uncollapsed
    ImGui::SetNextWindowPos(ImVec2(panelMargin, panelMargin), ImGuiCond_FirstUseEver);
    // As tall as its contents, but never taller than the window (it scrolls then).
    const float maxHeight = std::max(ImGui::GetIO().DisplaySize.y - 16.0f, 100.0f);
    ImGui::SetNextWindowSizeConstraints(ImVec2(340, 0), ImVec2(340, maxHeight));
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (!ImGui::Begin("idview (F1 hides)", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::End();
        return actions;
    }
    ImGui::PushItemWidth(-120.0f); // room for the labels right of the widgets
    // Where the panel lies, for F to fit the scene beside it.
    view.panelLeft = ImGui::GetWindowPos().x;
    view.panelRight = view.panelLeft + ImGui::GetWindowSize().x;
    status(info, actions);
    openField(view, actions);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", info.source.c_str());
    ImGui::PopStyleColor();
    viewRow(settings, view, actions);
    if (info.measuring &&
        ImGui::CollapsingHeader("Measure (M to leave)", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (info.measureLines.empty())
            ImGui::TextWrapped("Click a part for its face; two clicks for their distance.");
        for (const std::string& line : info.measureLines) ImGui::TextWrapped("%s", line.c_str());
    }
    // The parts first, open; the rarely used sections closed, so the details stay in view.
    if (ImGui::CollapsingHeader("Selection", ImGuiTreeNodeFlags_DefaultOpen))
        selectionSection(view, info, actions);
    if (ImGui::CollapsingHeader("Assembly tree", ImGuiTreeNodeFlags_DefaultOpen))
        assemblyTree(view, info, actions);
    if (ImGui::CollapsingHeader("Rendering")) rendering(settings, info, actions);
    if (ImGui::CollapsingHeader("Scene")) sceneSection(settings.scene, info);
    if (ImGui::CollapsingHeader("Section"))
        sectionPlanes(settings.render.section, info.bounds, info.selectedPlane);
    if (ImGui::CollapsingHeader("Timing")) timing(info);
    if (ImGui::CollapsingHeader("Controls")) ImGui::TextUnformatted(controlsHelp);
    if (ImGui::CollapsingHeader("Which technique?")) ImGui::TextWrapped("%s", techniqueHelp);
    ImGui::PopItemWidth();
    ImGui::End();
    return actions;
}

} // namespace app
