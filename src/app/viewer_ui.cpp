// viewer_ui.cpp - the panel: renderer settings, scene, statistics, timing, picking, help.
#include "app/viewer_ui.h"

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <type_traits>

#include <imgui.h>

#include "render/technique.h"

namespace app {
namespace {

const char* const controlsHelp = "left drag          orbit\n"
                                 "right/middle drag  pan (also shift + left drag)\n"
                                 "wheel              zoom towards the target\n"
                                 "left click         select the part (background: clear)\n"
                                 "Esc                clear selection; if none, quit\n"
                                 "F                  fit the view to the scene\n"
                                 "Home               reset the view\n"
                                 "R                  reload shaders from shaders/\n"
                                 "V                  vsync on/off\n"
                                 "F1                 hide/show this panel\n"
                                 "drop .gltf/.glb    open the model";

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

// A combo over a registry (techniques or modes); returns the chosen index.
template <typename Entries>
int registryCombo(const char* label, int current, const Entries& entries) {
    int chosen = current;
    if (ImGui::BeginCombo(label, entries[size_t(current)].name)) {
        for (size_t i = 0; i < entries.size(); ++i) {
            if (ImGui::Selectable(entries[i].name, int(i) == current)) chosen = int(i);
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", entries[i].description);
        }
        ImGui::EndCombo();
    }
    return chosen;
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

void narySearch(render::NarySearch& n) {
    sliderOnRelease("N-ary fan-out", n.n, 3u, 16u);
    ImGui::Checkbox("N-ary initial guess", &n.guess);
    sliderOnRelease("N-ary linear below", n.linearBelow, 0u, 64u);
    sliderOnRelease("N-ary max steps", n.maxSteps, 1u, 64u);
}

void rendering(ViewerSettings& s, const PanelInfo& info) {
    s.technique = registryCombo("renderer", s.technique, render::techniques());
    s.mode = registryCombo("per-draw mode", s.mode, render::drawModes());
    sliderOnRelease("search batch", s.searchBatch, 1u, 32u);
    if (render::techniques()[size_t(s.technique)].narySearch) narySearch(s.nsearch);
    sliderOnRelease("visible objects", s.visible, 0.0f, 1.0f);
    ImGui::SliderFloat("part weight", &s.partWeight, 0.0f, 1.0f, "%.2f");
    ImGui::Checkbox("colorize draws", &s.colorizeDraws);
    ImGui::Checkbox("ignore materials", &s.ignoreMaterials);
    char label[8];
    std::snprintf(label, sizeof label, "%ux", s.msaa);
    if (ImGui::BeginCombo("MSAA", label)) {
        for (uint32_t n = 1; n <= 8; n *= 2) {
            if (!(info.sampleCounts & n)) continue; // only what the device renders
            std::snprintf(label, sizeof label, "%ux", n);
            if (ImGui::Selectable(label, n == s.msaa)) s.msaa = n;
        }
        ImGui::EndCombo();
    }
    ImGui::Checkbox("animate (exploded view)", &s.animate);
    ImGui::Checkbox("vsync (V)", &s.vsync);
}

void sceneSection(ViewerSettings& s, const PanelInfo& info) {
    ImGui::TextWrapped("%s", info.source.c_str());
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
        int parts = s.componentParts ? 1 : 0;
        ImGui::Text("parts");
        ImGui::SameLine();
        ImGui::RadioButton("primitives", &parts, 0);
        ImGui::SameLine();
        ImGui::RadioButton("components", &parts, 1);
        s.componentParts = parts == 1;
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
}

void timing(const PanelInfo& info) {
    ImGui::Text("%.0f fps", info.fps);
    ImGui::Text("Render GPU [ms]  %.3f", info.gpuMs);
    ImGui::Text("CPU record [ms]  %.3f", info.cpuRecordMs);
    if (!info.gpuHistory.empty())
        ImGui::PlotLines("##gpu", info.gpuHistory.data(), int(info.gpuHistory.size()), 0,
                         "scene pass GPU ms", 0.0f, FLT_MAX, ImVec2(310, 60));
}

void partLine(const char* what, const PartLine& line) {
    if (!line.part) {
        ImGui::Text("%s: none", what);
        return;
    }
    const scene::PartInfo& p = *line.part;
    ImGui::Text("%s: part %u", what, p.uniquePartId);
    ImGui::Text("  object %u, local part %u, geometry %u", p.object, p.localPart, p.geometry);
    ImGui::Text("  %u triangles, depth %.6f", p.triangleCount, double(line.depth));
}

} // namespace

ViewerSettings drawPanel(const ViewerSettings& current, const PanelInfo& info) {
    ViewerSettings s = current;
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    // As tall as its contents, but never taller than the window (it scrolls then).
    const float maxHeight = std::max(ImGui::GetIO().DisplaySize.y - 16.0f, 100.0f);
    ImGui::SetNextWindowSizeConstraints(ImVec2(340, 0), ImVec2(340, maxHeight));
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (!ImGui::Begin("idview (F1 hides)", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::End();
        return s;
    }
    ImGui::PushItemWidth(-120.0f); // room for the labels right of the widgets
    ImGui::TextDisabled("%s", info.device.c_str());
    if (!info.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", info.error.c_str());
        ImGui::PopStyleColor();
    }
    if (ImGui::CollapsingHeader("Rendering", ImGuiTreeNodeFlags_DefaultOpen)) rendering(s, info);
    if (ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) sceneSection(s, info);
    if (ImGui::CollapsingHeader("Timing", ImGuiTreeNodeFlags_DefaultOpen)) timing(info);
    if (ImGui::CollapsingHeader("Picking", ImGuiTreeNodeFlags_DefaultOpen)) {
        partLine("hovered", info.hovered);
        partLine("selected", info.selected);
    }
    if (ImGui::CollapsingHeader("Controls")) ImGui::TextUnformatted(controlsHelp);
    ImGui::PopItemWidth();
    ImGui::End();
    return s;
}

} // namespace app
