// measure.cpp - the measure mode's text and overlay.
#include "app/viewer/measure.h"

#include <cstdio>

#include <imgui.h>

#include "scene/face_info.h"

namespace app {

namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
    char text[160];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

// "cylinder r 5, area 628.319": what the panel says of a face.
std::string faceLine(const scene::FaceReport& face) {
    const scene::SurfaceInfo& s = face.surface;
    std::string line = "part " + std::to_string(face.part);
    if (face.face) line += ", face " + std::to_string(*face.face);
    line += std::string(": ") + scene::surfaceName(s.kind);
    if (s.kind == scene::SurfaceKind::Cylinder || s.kind == scene::SurfaceKind::Sphere)
        line += format(" r %.6g", s.radius);
    if (s.kind == scene::SurfaceKind::Plane)
        line += format(" n (%.4g, %.4g, %.4g)", s.normal.x, s.normal.y, s.normal.z);
    return line + format(", area %.6g", s.area);
}

} // namespace

std::vector<std::string> measureLines(const scene::Scene& scene,
                                      const std::vector<MeasurePoint>& points) {
    std::vector<std::string> lines;
    std::vector<scene::FaceReport> faces;
    for (const MeasurePoint& p : points) {
        const auto face = scene::faceReport(scene, p.part);
        if (!face) continue;
        faces.push_back(*face);
        lines.push_back(faceLine(*face));
        lines.push_back(format("  at (%.6g, %.6g, %.6g)", p.world.x, p.world.y, p.world.z));
    }
    if (points.size() == 2) {
        const glm::vec3 d = points[1].world - points[0].world;
        lines.push_back(format("distance %.6g", glm::length(d)));
        lines.push_back(format("dX %.6g  dY %.6g  dZ %.6g", d.x, d.y, d.z));
    }
    if (faces.size() == 2)
        if (const auto planes = scene::comparePlanes(faces[0], faces[1])) {
            lines.push_back(format("faces' normals at %.4g degrees", planes->angleDegrees));
            if (planes->distance) lines.push_back(format("planes %.6g apart", *planes->distance));
        }
    return lines;
}

void drawMeasure(const std::vector<MeasurePoint>& points, const glm::mat4& viewProj,
                 glm::vec2 size) {
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    std::vector<ImVec2> screen;
    for (const MeasurePoint& p : points) {
        const glm::vec4 clip = viewProj * glm::vec4(p.world, 1.0f);
        if (clip.w <= 0.0f) return; // behind the eye: nothing sensible to draw
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        screen.push_back(ImVec2((ndc.x * 0.5f + 0.5f) * size.x, (ndc.y * 0.5f + 0.5f) * size.y));
    }
    const ImU32 colour = IM_COL32(255, 235, 59, 255), shadow = IM_COL32(0, 0, 0, 200);
    if (screen.size() == 2) {
        draw->AddLine(screen[0], screen[1], shadow, 4.0f);
        draw->AddLine(screen[0], screen[1], colour, 2.0f);
        const std::string label = format("%.6g", glm::length(points[1].world - points[0].world));
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
