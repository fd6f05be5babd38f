// panel_rendering.cpp - the panel's Rendering and Scene sections: the renderer, its mode and
// settings, culling, levels of detail, and what the scene and the renderer hold.
#include "app/viewer/panel/panel_rendering.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>

#include <imgui.h>

#include "app/viewer/panel/panel_commands.h"
#include "app/viewer/panel/panel_widgets.h"
#include "render/culling.h"
#include "render/technique.h"
#include "scene/lod.h"

namespace app {
namespace {

// A linear colour as the panel shows it: sRGB-encoded, as the swapchain shows the picture.
ImVec4 displayed(glm::vec3 linear) {
    auto encode = [](float c) {
        return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    };
    return {encode(linear.r), encode(linear.g), encode(linear.b), 1.0f};
}

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
    if (!ImGui::BeginCombo(fitLabel(label).c_str(), current->name)) return;
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
    const std::string fitted = fitLabel(label);
    if constexpr (std::is_same_v<T, float>)
        ImGui::SliderFloat(fitted.c_str(), &shown, min, max, "%.2f");
    else
        ImGui::SliderScalar(fitted.c_str(), ImGuiDataType_U32, &shown, &min, &max);
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
    if (!ImGui::BeginCombo(fitLabel("renderer").c_str(), current->name)) return;
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
void culling(const render::CullSettings& c, const PanelInfo& info, PanelActions& actions) {
    if (ImGui::BeginCombo(fitLabel("culling").c_str(), render::cullModeName(c.mode))) {
        for (const render::CullModeEntry& entry : render::cullModes()) {
            if (ImGui::Selectable(entry.name, entry.mode == c.mode) && entry.mode != c.mode)
                actions.ask({CommandId::Culling, entry.mode});
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", entry.description);
        }
        ImGui::EndCombo();
    }
    ImGui::BeginDisabled(!info.can(CommandId::Freeze));
    switchCheckbox("freeze culling", CommandId::Freeze, c.freeze, actions);
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("keep drawing what the last culled frame chose while the camera "
                          "moves: fly around to see what was left out");
    textDisabledWrapped(info.cullingApplied.c_str());
    ImGui::TextWrapped("draws drawn    %s", counted(info.drawn.draws, info.totals.draws).c_str());
    if (info.totals.meshlets)
        ImGui::TextWrapped("meshlets       %s",
                           counted(info.drawn.meshlets, info.totals.meshlets).c_str());
    ImGui::TextWrapped("triangles      %s",
                       counted(info.drawn.triangles, info.totals.triangles).c_str());
    if (info.drawn.computeTriangles)
        ImGui::TextWrapped("  in compute   %s",
                           counted(info.drawn.computeTriangles, info.drawn.triangles).c_str());
}

// How frames start and resolve (render/settings.h ClearPath): auto shows the path it chose
// and, on hover, the empty-frame times it chose by.
void clearPathCombo(render::ClearPath clear, const PanelInfo& info, PanelActions& actions) {
    std::string current = render::clearPathName(clear);
    if (clear == render::ClearPath::Auto)
        current += std::string(" (") + render::clearPathName(info.clearPath) + ")";
    if (ImGui::BeginCombo(fitLabel("clear").c_str(), current.c_str())) {
        for (render::ClearPath p :
             {render::ClearPath::Auto, render::ClearPath::Pass, render::ClearPath::Compute})
            if (ImGui::Selectable(render::clearPathName(p), p == clear) && p != clear)
                actions.ask({CommandId::Clear, p});
        ImGui::EndCombo();
    }
    if (!ImGui::IsItemHovered()) return;
    std::string tip = "pass: the scene pass clears colour, IDs and depth and resolves MSAA\n"
                      "compute: it clears depth alone; a compute pass writes the background "
                      "and resolves\nauto: the faster of the two on this device (--clear)";
    if (info.clearTiming) {
        char line[128];
        std::snprintf(line, sizeof line,
                      "\n\nan empty %ux%u frame at %ux: pass %.3f ms, compute %.3f ms (%s)",
                      render::clearTimingWidth, render::clearTimingHeight,
                      info.clearTiming->samples, info.clearTiming->passMs,
                      info.clearTiming->computeMs,
                      info.clearTiming->remembered ? "timed before, kept" : "timed now");
        tip += line;
    }
    ImGui::SetTooltip("%s", tip.c_str());
}

// Levels of detail: how many the scene has (a reload), the error the cull pass chooses them
// by, the tint, and the triangles the newest frame drew at each.
void levelsOfDetail(LiveSettings& settings, const PanelInfo& info) {
    sliderOnRelease("LOD levels built", settings.scene.lodLevels, 1u, scene::maxLevels);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("levels of detail built when the scene loads, full detail included "
                          "(changing it reloads the scene)");
    const bool usable = settings.scene.lodLevels > 1 && info.lodChosen;
    ImGui::BeginDisabled(!usable);
    ImGui::SliderFloat(fitLabel("LOD error [px]").c_str(), &settings.render.lod.errorPixels, 0.0f,
                       8.0f, "%.2f");
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", !usable && settings.scene.lodLevels < 2
                                    ? "build levels of detail first (LOD levels built)"
                                : !usable ? "levels are chosen by the cull pass, which "
                                            "lists the draws in the mdi modes: push mode "
                                            "draws full detail"
                                          : "each object drawn at its coarsest level whose "
                                            "error stays under this many pixels; 0: full "
                                            "detail");
    ImGui::Checkbox("tint by level", &settings.render.shading.tintLevels);
    if (settings.render.lod.errorPixels <= 0.0f || !usable) return;
    for (uint32_t l = 0; l < info.drawn.levelTriangles.size(); ++l) {
        ImGui::TextColored(displayed(gpu::LEVEL_TINTS[l]), "level %u", l);
        ImGui::SameLine();
        ImGui::TextWrapped("%llu triangles",
                           static_cast<unsigned long long>(info.drawn.levelTriangles[l]));
    }
}

// The compute rasterizer's share: which meshlets its task shader sends to the compute pass.
void computeRaster(render::RasterSettings& r) {
    ImGui::Checkbox("all in compute", &r.all);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("every meshlet the compute rasterizer can draw: all but those that "
                          "reach in front of the near plane, cross a section plane or span "
                          "over %u pixels (--raster-all)",
                          gpu::RASTER_MAX_SPAN - 2);
    ImGui::BeginDisabled(r.all);
    ImGui::SliderFloat(fitLabel("compute below [samples/tri]").c_str(), &r.trianglePixels, 0.0f,
                       128.0f, "%.1f");
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("meshlets whose projected rectangle holds at most this many samples "
                          "per triangle (pixels at 1x) are rasterized in compute, the rest by "
                          "the hardware; 0: none (--raster-pixels)");
}

// What draws: the renderer, its mode and the settings it reads, and how frames are sampled,
// cleared and resolved. The renderer, mode, MSAA and clear path are commands (a script line
// asks for them too); the rest the panel edits in place.
void pipeline(render::RenderSettings& s, const PanelInfo& info, PanelActions& actions) {
    render::PipelineKey& key = s.pipeline;
    const render::Technique* technique = key.technique;
    techniqueCombo(technique, info);
    if (technique != key.technique) actions.ask({CommandId::Renderer, technique});
    const render::DrawMode* mode = key.mode;
    registryCombo("per-draw mode", mode, render::drawModes());
    if (mode != key.mode) actions.ask({CommandId::Mode, mode});
    if (key.technique->readsSearchBatch())
        sliderOnRelease("search batch", key.searchBatch, render::searchBatchRange);
    if (key.technique->narySearch) narySearch(key.nsearch);
    if (key.technique->computeRaster) computeRaster(s.raster);
    sliderOnRelease("visible objects", s.draws.visible, 0.0f, 1.0f);
    ImGui::SliderFloat(fitLabel("part weight").c_str(), &s.shading.partWeight, 0.0f, 1.0f, "%.2f");
    ImGui::Checkbox("colorize draws", &s.shading.colorizeDraws);
    ImGui::Checkbox("ignore materials", &s.shading.ignoreMaterials);
    switchCheckbox("sort draws once", CommandId::Sort, s.draws.sortDraws, actions);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("sort the draw list by geometry, then material, when it is built "
                          "(--no-sort-draws: scene order)");
    char label[8];
    std::snprintf(label, sizeof label, "%ux", key.msaa);
    if (ImGui::BeginCombo(fitLabel("MSAA").c_str(), label)) {
        for (uint32_t n = 1; n <= 8; n *= 2) {
            if (!(info.sampleCounts & n)) continue; // only what the device renders
            std::snprintf(label, sizeof label, "%ux", n);
            if (ImGui::Selectable(label, n == key.msaa) && n != key.msaa)
                actions.ask({CommandId::Msaa, n});
        }
        ImGui::EndCombo();
    }
    clearPathCombo(s.clear, info, actions);
}

// Edge settings stay in place, greyed while edges are off: E moves nothing below.
void edgeSettings(render::EdgeSettings& edges) {
    ImGui::BeginDisabled(!edges.on);
    const render::Range widths = render::edgeWidthRange;
    ImGui::SliderScalar(fitLabel("edge width").c_str(), ImGuiDataType_U32, &edges.width,
                        &widths.min, &widths.max);
    ImGui::ColorEdit3("edge colour", &edges.color.x, ImGuiColorEditFlags_NoInputs);
    sameLineIfFits(checkboxWidth("selected"));
    ImGui::ColorEdit3("selected", &edges.selectColor.x, ImGuiColorEditFlags_NoInputs);
    sameLineIfFits(checkboxWidth("hovered"));
    ImGui::ColorEdit3("hovered", &edges.hoverColor.x, ImGuiColorEditFlags_NoInputs);
    ImGui::EndDisabled();
}

} // namespace

void rendering(LiveSettings& settings, const PanelInfo& info, PanelActions& actions) {
    pipeline(settings.render, info, actions);
    edgeSettings(settings.render.edges);
    culling(settings.render.culling, info, actions);
    levelsOfDetail(settings, info);
    // What the last switch cost: a cached pipeline makes it a lookup.
    const render::SwitchReport& last = info.lastSwitch;
    textWrappedAtSpacesf("last switch %.2f ms, pipeline %s%s", last.ms,
                         last.pipelineCached ? "cached" : "built",
                         last.drawsKept ? ", draws kept" : "");
    ImGui::TextWrapped("pipelines cached %zu (R clears)", info.cachedPipelines);
    commandButton("Reset to defaults", CommandId::Defaults, info, actions);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the settings kept between runs (renderer, mode, MSAA, edges, "
                          "culling, levels of detail, projection) back to the defaults");
}

void sceneSection(SceneSettings& s, const PanelInfo& info, PanelActions& actions) {
    int copies = int(s.copies);
    if (ImGui::InputInt(fitLabel("model copies").c_str(), &copies, 1, 4,
                        ImGuiInputTextFlags_EnterReturnsTrue) &&
        uint32_t(std::clamp(copies, 1, 256)) != s.copies)
        actions.ask({CommandId::Copies, uint32_t(std::clamp(copies, 1, 256))});
    ImGui::TextUnformatted("copies along");
    for (uint32_t bit = 0; bit < 3; ++bit) {
        bool on = s.copyAxes & (1u << bit);
        const char* names[] = {"x", "y", "z"};
        sameLineIfFits(checkboxWidth(names[bit]));
        // At least one axis stays on: unticking the last one is ignored.
        if (ImGui::Checkbox(names[bit], &on) && (on || (s.copyAxes & ~(1u << bit))))
            s.copyAxes = on ? (s.copyAxes | (1u << bit)) : (s.copyAxes & ~(1u << bit));
    }
    if (info.gltf) {
        int parts = int(s.parts);
        ImGui::TextUnformatted("parts");
        sameLineIfFits(checkboxWidth("primitives"));
        ImGui::RadioButton("primitives", &parts, int(scene::PartMode::Primitives));
        sameLineIfFits(checkboxWidth("components"));
        ImGui::RadioButton("components", &parts, int(scene::PartMode::Components));
        s.parts = scene::PartMode(parts);
    }
    if (!info.scene) return;
    const scene::Scene& scene = *info.scene;
    ImGui::TextWrapped("draw calls     %zu", info.stats.draws);
    ImGui::TextWrapped("triangles      %llu",
                       static_cast<unsigned long long>(info.stats.triangles));
    ImGui::TextWrapped("parts          %u", scene.uniquePartCount());
    ImGui::TextWrapped("objects        %zu", scene.objects.size());
    textWrappedAtSpacesf("triangle IDs   %s", bytes(info.idBytes.trianglePartIds).c_str());
    textWrappedAtSpacesf("part counts    %s", bytes(info.idBytes.partTriangleCounts).c_str());
    textWrappedAtSpacesf("part offsets   %s", bytes(info.idBytes.partTriangleOffsets).c_str());
    // What the current renderer and mode uploaded.
    textWrappedAtSpacesf("renderer IDs   %s", bytes(info.stats.idBufferBytes).c_str());
    ImGui::TextWrapped("per-draw data  %s + %s indirect", bytes(info.stats.perDrawBytes).c_str(),
                       bytes(info.stats.indirectBytes).c_str());
    if (info.stats.geometryBytes)
        textWrappedAtSpacesf("own geometry   %s", bytes(info.stats.geometryBytes).c_str());
    if (info.stats.geometryBytes) // every derived geometry is cut from part vertices
        ImGui::TextWrapped("added vertices %llu (%s)",
                           static_cast<unsigned long long>(info.stats.addedVertices),
                           bytes(info.stats.addedVertexBytes).c_str());
    if (info.stats.meshlets)
        ImGui::TextWrapped("meshlets       %llu",
                           static_cast<unsigned long long>(info.stats.meshlets));
}

} // namespace app
