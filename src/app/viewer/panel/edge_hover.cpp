// edge_hover.cpp - the hovered and selected B-rep edges (edge_hover.h).
#include "app/viewer/panel/edge_hover.h"

#include <vector>

#include <imgui.h>

namespace app {
namespace {

// "edge":{"part":P,"edge":E}, or null.
void edgeMember(util::JsonWriter& json, const std::optional<scene::EdgeRef>& ref) {
    if (!ref) {
        json.member("edge", std::nullopt);
        return;
    }
    json.beginObject("edge").member("part", ref->part).member("edge", ref->edge).endObject();
}

std::optional<scene::EdgeReport> reportOf(const scene::Scene& scene,
                                          const std::optional<scene::EdgeRef>& ref) {
    return ref ? scene::edgeReport(scene, *ref) : std::nullopt;
}

void polyline(const scene::EdgeReport& edge, const glm::dmat4& viewProj, glm::vec2 size,
              ImU32 colour, float width) {
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const ImU32 shadow = IM_COL32(0, 0, 0, 200);
    std::vector<ImVec2> screen;
    // A run of points in front of the eye at a time: a point behind it has no place on screen.
    auto flush = [&] {
        if (screen.size() >= 2) {
            draw->AddPolyline(screen.data(), int(screen.size()), shadow, 0, width + 2.0f);
            draw->AddPolyline(screen.data(), int(screen.size()), colour, 0, width);
        }
        screen.clear();
    };
    for (const glm::dvec3& p : edge.points) {
        const glm::dvec4 clip = viewProj * glm::dvec4(p, 1.0);
        if (clip.w <= 0.0) {
            flush();
            continue;
        }
        const glm::vec2 ndc = glm::vec2(glm::dvec2(clip) / clip.w);
        screen.push_back(ImVec2((ndc.x * 0.5f + 0.5f) * size.x, (ndc.y * 0.5f + 0.5f) * size.y));
    }
    flush();
}

} // namespace

void EdgeHover::update(const scene::Scene& scene, Document& document,
                       std::optional<glm::dvec2> cursor, const glm::dmat4& viewProj,
                       glm::dvec2 size) {
    const auto part = document.selection().hovered();
    if (!part || !cursor || !scene.brep) {
        document.hoverEdge(std::nullopt);
        return;
    }
    document.hoverEdge(
        scene::nearestEdge(scene, *part, viewProj, size, *cursor, scene::edgePickPixels));
}

void EdgeHover::tell(const scene::Scene& scene, const Selection& selection, const Events& events) {
    if (selection.hoveredEdge() != saidHovered_) {
        saidHovered_ = selection.hoveredEdge();
        hovered_ = reportOf(scene, saidHovered_);
        events.say("edge_hovered", [&](util::JsonWriter& j) { edgeMember(j, saidHovered_); });
    }
    if (selection.selectedEdge() != saidSelected_) {
        saidSelected_ = selection.selectedEdge();
        selected_ = reportOf(scene, saidSelected_);
        events.say("edge_selected", [&](util::JsonWriter& j) {
            edgeMember(j, saidSelected_);
            j.member("curve",
                     selected_ ? std::optional(scene::describeEdge(*selected_)) : std::nullopt);
        });
    }
}

void EdgeHover::draw(const glm::dmat4& viewProj, glm::vec2 size) const {
    // The selection under the hover: a hovered edge that is also selected shows as hovered.
    if (selected_) polyline(*selected_, viewProj, size, IM_COL32(255, 120, 30, 255), 3.0f);
    if (hovered_) polyline(*hovered_, viewProj, size, IM_COL32(80, 220, 255, 255), 2.5f);
}

std::string EdgeHover::line(const std::optional<scene::EdgeReport>& report) {
    if (!report) return "";
    return "edge " + std::to_string(report->ref.edge) + ": " + scene::describeEdge(*report);
}

} // namespace app
