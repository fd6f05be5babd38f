// face_info.cpp - a part's surface and box in world coordinates (face_info.h).
#include "scene/face_info.h"

#include <cmath>

#include "scene/bounds.h"
#include "util/json_writer.h"

namespace scene {

const char* surfaceName(SurfaceKind kind) {
    static constexpr const char* names[] = {
        "mesh",    "plane",  "cylinder",   "cone",      "sphere", "torus",
        "bspline", "bezier", "revolution", "extrusion", "offset", "other",
    };
    return names[size_t(kind)];
}

std::optional<FaceReport> faceReport(const Scene& scene, uint32_t uniquePartId) {
    const auto ref = scene.locate(uniquePartId);
    if (!ref) return std::nullopt;
    const Object& object = scene.objects[ref->object];
    const Geometry& g = scene.geometries[object.geometry];
    FaceReport report;
    report.part = uniquePartId;
    report.object = ref->object;
    report.unit = scene.unit;
    report.precision = scene.precision;
    if (ref->localPart < g.partFaces.size()) report.face = g.partFaces[ref->localPart];
    const glm::dmat4 world(object.world);
    const glm::dmat3 linear(world);
    const double scale = std::cbrt(std::abs(glm::determinant(linear)));
    auto place = [&](glm::dvec3 p) { return glm::dvec3(world * glm::dvec4(p, 1.0)); };

    const Part& part = scene.part(object, ref->localPart);
    report.bbox = emptyBounds();
    double triangleArea = 0.0;
    for (uint32_t t = part.firstTriangle; t < part.firstTriangle + part.triangleCount; ++t) {
        glm::dvec3 c[3];
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = scene.indices[g.firstIndex + 3 * t + uint32_t(k)];
            c[k] = place(glm::dvec3(scene.vertices[g.firstVertex + v].position));
            report.bbox.min = glm::min(report.bbox.min, c[k]);
            report.bbox.max = glm::max(report.bbox.max, c[k]);
        }
        triangleArea += 0.5 * glm::length(glm::cross(c[1] - c[0], c[2] - c[0]));
    }
    if (ref->localPart >= g.partSurfaces.size()) {
        report.surface.area = triangleArea;
        return report;
    }
    SurfaceInfo s = g.partSurfaces[ref->localPart];
    s.area *= scale * scale;
    s.radius *= scale;
    if (s.kind == SurfaceKind::Plane) {
        const glm::dvec3 normal = glm::normalize(glm::transpose(glm::inverse(linear)) * s.normal);
        s.d = glm::dot(normal, place(s.normal * s.d));
        s.normal = normal;
    }
    if (s.kind == SurfaceKind::Cylinder || s.kind == SurfaceKind::Sphere)
        s.axisOrigin = place(s.axisOrigin);
    if (s.kind == SurfaceKind::Cylinder) s.axisDirection = glm::normalize(linear * s.axisDirection);
    report.surface = s;
    return report;
}

std::string faceReportJson(const FaceReport& r) {
    const SurfaceInfo& s = r.surface;
    // Every digit: a face kilometres from the origin keeps its millimetres.
    util::JsonWriter json;
    json.beginObject()
        .member("part", r.part)
        .member("object", r.object)
        .member("face", r.face)
        .member("surface", surfaceName(s.kind))
        .member("area", s.area);
    if (s.kind == SurfaceKind::Plane) json.member("normal", s.normal).member("d", s.d);
    if (s.kind == SurfaceKind::Cylinder)
        json.member("radius", s.radius)
            .member("diameter", 2.0 * s.radius)
            .beginObject("axis")
            .member("origin", s.axisOrigin)
            .member("direction", s.axisDirection)
            .endObject();
    if (s.kind == SurfaceKind::Sphere)
        json.member("radius", s.radius).member("center", s.axisOrigin);
    if (isEmpty(r.bbox)) // an empty part (no triangles)
        json.key("bbox").null();
    else
        json.beginObject("bbox").member("min", r.bbox.min).member("max", r.bbox.max).endObject();
    unitMember(json, r.unit);
    return json.endObject().text();
}

std::string describeSurface(const FaceReport& r) {
    const SurfaceInfo& s = r.surface;
    const Precision& p = r.precision;
    std::string line = surfaceName(s.kind);
    // A hole or a boss is sized by its diameter; the radius follows for fillets.
    if (s.kind == SurfaceKind::Cylinder)
        line += " Ø " + formatLength(2.0 * s.radius, r.unit, p) + " (r " + lengthText(s.radius, p) +
                "), axis " + directionText(s.axisDirection);
    if (s.kind == SurfaceKind::Sphere) line += " r " + formatLength(s.radius, r.unit, p);
    if (s.kind == SurfaceKind::Plane) line += " n " + directionText(s.normal);
    // Without a B-rep face the area is its triangles' (mesh parts).
    return line + (s.kind == SurfaceKind::Mesh ? ", triangle area " : ", area ") +
           formatArea(s.area, r.unit, p);
}

std::optional<PlanePair> comparePlanes(const FaceReport& a, const FaceReport& b) {
    if (a.surface.kind != SurfaceKind::Plane || b.surface.kind != SurfaceKind::Plane)
        return std::nullopt;
    const glm::dvec3 na = glm::normalize(a.surface.normal), nb = glm::normalize(b.surface.normal);
    PlanePair pair;
    // atan2 of |cross| and dot: exact near 0 and 180 degrees, where acos loses digits.
    pair.angleDegrees = glm::degrees(std::atan2(glm::length(glm::cross(na, nb)), glm::dot(na, nb)));
    // Parallel within a millionth of a radian: the distance from a's plane to b's.
    if (glm::length(glm::cross(na, nb)) < 1e-6)
        pair.distance = std::abs(glm::dot(nb, na * a.surface.d) - b.surface.d);
    return pair;
}

} // namespace scene
