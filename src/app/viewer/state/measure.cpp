// measure.cpp - the measure mode's text for the panel.
#include "app/viewer/state/measure.h"

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

} // namespace app
