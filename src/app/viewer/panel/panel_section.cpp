// panel_section.cpp - the section planes in the panel. Offsets apply while dragging: a plane
// is a per-frame constant (FrameData::sectionPlanes), only switching sections on or off
// changes the pipeline.
#include "app/viewer/panel/panel_section.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <string>

#include <imgui.h>

#include "app/viewer/panel/panel_widgets.h"

namespace app {

glm::dvec2 offsetRange(const scene::Bounds& bounds, glm::dvec3 normal) {
    glm::dvec2 range(std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest());
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p((corner & 1) ? bounds.max.x : bounds.min.x,
                           (corner & 2) ? bounds.max.y : bounds.min.y,
                           (corner & 4) ? bounds.max.z : bounds.min.z);
        range.x = std::min(range.x, glm::dot(normal, p));
        range.y = std::max(range.y, glm::dot(normal, p));
    }
    return range;
}

namespace {

// Which axis a plane lies on, or -1 for a face's plane.
int axisOf(const scene::SectionPlane& plane) {
    for (int axis = 0; axis < 3; ++axis)
        if (plane.normal == glm::dvec3(axis == 0, axis == 1, axis == 2)) return axis;
    return -1;
}

void onePlane(int index, scene::SectionPlane& plane, const scene::Bounds& bounds,
              const std::optional<scene::SurfaceInfo>& selectedPlane,
              const scene::LengthUnit& unit) {
    ImGui::PushID(index);
    char label[32];
    std::snprintf(label, sizeof label, "plane %d", index + 1);
    if (ImGui::Checkbox(label, &plane.on) && plane.on && axisOf(plane) >= 0) {
        // Turned on: start through the middle of the scene, where a cut shows most.
        const glm::dvec2 range = offsetRange(bounds, plane.normal);
        plane.offset = 0.5 * (range.x + range.y);
    }
    if (!plane.on) {
        ImGui::PopID();
        return;
    }
    const int axis = axisOf(plane);
    for (int a = 0; a < 3; ++a) {
        const char* names[] = {"X", "Y", "Z"};
        sameLineIfFits(checkboxWidth(names[a]));
        if (ImGui::RadioButton(names[a], axis == a) && axis != a) {
            const double middle = 0.5 * (bounds.min[a] + bounds.max[a]);
            plane = scene::axisPlane(a, middle, plane.flip);
        }
    }
    sameLineIfFits(checkboxWidth("face"));
    ImGui::BeginDisabled(!selectedPlane);
    if (ImGui::RadioButton("face", axis < 0) && selectedPlane) {
        plane = scene::planeAtFace(*selectedPlane, plane.flip);
    }
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip(selectedPlane ? "on the plane of the selected face"
                                        : "select a planar face of a CAD model first");
    ImGui::EndDisabled();
    sameLineIfFits(checkboxWidth("flip"));
    ImGui::Checkbox("flip", &plane.flip);
    const glm::dvec2 range = offsetRange(bounds, plane.normal);
    // A little past the bounds, so a plane can leave the scene whole on either side.
    const double margin = 0.02 * (range.y - range.x) + 1e-6;
    const double low = range.x - margin, high = range.y + margin;
    // The slider shows the offset with its unit (none where the model has none).
    std::string format = "%.3f" + (unit.symbol.empty() ? std::string() : " " + unit.symbol);
    const std::string offsetLabel = fitLabel("offset");
    // Double: a plane through a building at its map position keeps its millimetres.
    ImGui::SliderScalar(offsetLabel.c_str(), ImGuiDataType_Double, &plane.offset, &low, &high,
                        format.c_str());
    if (axis < 0) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        textWrappedAtSpaces("normal " + scene::directionText(plane.normal));
        ImGui::PopStyleColor();
    }
    ImGui::PopID();
}

} // namespace

void sectionPlanes(scene::Section& section, const scene::Bounds& bounds,
                   const std::optional<scene::SurfaceInfo>& selectedPlane,
                   const scene::LengthUnit& unit, PanelLayout& layout) {
    const char* names[] = {"section plane 1", "section plane 2", "section plane 3"};
    for (size_t i = 0; i < section.planes.size(); ++i) {
        layout.mark(i < 3 ? names[i] : "section plane");
        onePlane(int(i), section.planes[i], bounds, selectedPlane, unit);
    }
    layout.mark("section note");
    textDisabledWrapped("Each plane cuts its side away; hatched caps close the cut solids.");
}

} // namespace app
