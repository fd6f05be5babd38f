// measure.cpp - the measure mode's text and overlay.
#include "app/viewer/measure.h"

#include <imgui.h>

#include "scene/face_info.h"

namespace app {

namespace {

// "part 3 (bracket), face 2: cylinder r 5 mm, area 628.319 mm²": what the panel says of a
// face, named as the assembly names its object.
std::string faceLine(const scene::Scene& scene, const scene::FaceReport& face) {
    std::string line = "part " + std::to_string(face.part);
    const std::string& name = scene.objects[face.object].name;
    if (!name.empty()) line += " (" + name + ")";
    if (face.face) line += ", face " + std::to_string(*face.face);
    return line + ": " + scene::describeSurface(face);
}

} // namespace

std::vector<std::string> measureLines(const scene::Scene& scene,
                                      const std::vector<MeasurePoint>& points) {
    // The unit once, above bare lengths and points (units.h); the face lines name theirs.
    std::vector<std::string> lines;
    if (points.empty()) return lines;
    const scene::Precision& p = scene.precision;
    lines.push_back(scene::unitHeading(scene.unit));
    std::vector<scene::FaceReport> faces;
    for (const MeasurePoint& point : points) {
        const auto face = scene::faceReport(scene, point.part);
        if (!face) continue;
        faces.push_back(*face);
        lines.push_back(faceLine(scene, *face));
        lines.push_back("  at " + scene::pointText(glm::dvec3(point.world), p));
    }
    if (points.size() == 2) {
        const glm::dvec3 d = glm::dvec3(points[1].world) - glm::dvec3(points[0].world);
        lines.push_back("distance " + scene::lengthText(glm::length(d), p));
        lines.push_back("dX dY dZ " + scene::pointText(d, p));
    }
    if (faces.size() == 2)
        if (const auto planes = scene::comparePlanes(faces[0], faces[1])) {
            lines.push_back("faces' normals at " + scene::angleText(planes->angleDegrees) +
                            " degrees");
            if (planes->distance)
                lines.push_back("planes " + scene::lengthText(*planes->distance, p) + " apart");
        }
    return lines;
}

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
