// measure_overlay.cpp - the measure line, its label and points, on ImGui's foreground list.
#include "app/viewer/panel/measure_overlay.h"

#include <string>

#include <imgui.h>

namespace app {

void drawMeasure(const std::vector<MeasurePoint>& points, const glm::dmat4& viewProj,
                 glm::vec2 size, const scene::LengthUnit& unit, const scene::Precision& precision,
                 uint32_t colour) {
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    std::vector<ImVec2> screen;
    for (const MeasurePoint& p : points) {
        const glm::dvec4 clip = viewProj * glm::dvec4(p.world, 1.0);
        if (clip.w <= 0.0) return; // behind the eye: nothing sensible to draw
        const glm::vec2 ndc = glm::vec2(glm::dvec2(clip) / clip.w);
        screen.push_back(ImVec2((ndc.x * 0.5f + 0.5f) * size.x, (ndc.y * 0.5f + 0.5f) * size.y));
    }
    const ImU32 shadow = IM_COL32(0, 0, 0, 200);
    if (screen.size() == 2) {
        draw->AddLine(screen[0], screen[1], shadow, 4.0f);
        draw->AddLine(screen[0], screen[1], colour, 2.0f);
        const std::string label =
            scene::formatLength(glm::length(points[1].world - points[0].world), unit, precision);
        const ImVec2 middle((screen[0].x + screen[1].x) * 0.5f + 8.0f,
                            (screen[0].y + screen[1].y) * 0.5f - 8.0f);
        const ImVec2 extent = ImGui::CalcTextSize(label.c_str());
        draw->AddRectFilled(ImVec2(middle.x - 3, middle.y - 2),
                            ImVec2(middle.x + extent.x + 3, middle.y + extent.y + 2), shadow, 3.0f);
        draw->AddText(middle, colour, label.c_str());
    }
    for (const ImVec2& p : screen) {
        draw->AddCircleFilled(p, 5.0f, shadow);
        draw->AddCircleFilled(p, 3.5f, colour);
    }
}

} // namespace app
