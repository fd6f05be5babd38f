// inspect.cpp - distances and properties (inspect.h): from the B-rep where the scene has one
// (cad/brep_inspect.h), from triangles otherwise (mesh_inspect.h); and their JSON lines.
#include "scene/inspect.h"

#include "scene/bounds.h"
#include "scene/cad/brep_inspect.h"
#include "scene/mesh_inspect.h"
#include "util/json_number.h"

namespace scene {

std::optional<DistanceReport> measureDistance(const Scene& scene, const Thing& a, const Thing& b) {
    if (scene.brep) return brepDistance(scene, a, b);
    return meshDistance(scene, a, b);
}

std::optional<SolidProperties> objectProperties(const Scene& scene, uint32_t object) {
    if (object >= scene.objects.size()) return std::nullopt;
    if (auto exact = brepProperties(scene, object)) return exact;
    return meshProperties(scene, object);
}

SolidProperties sumProperties(const std::vector<SolidProperties>& each) {
    SolidProperties sum;
    sum.object = uint32_t(each.size());
    sum.bbox = emptyBounds();
    sum.closed = !each.empty();
    glm::dvec3 volumeMoment(0.0), areaMoment(0.0);
    for (const SolidProperties& p : each) {
        sum.volume += p.volume;
        sum.area += p.area;
        volumeMoment += p.volume * p.center;
        areaMoment += p.area * p.center;
        sum.bbox = unite(sum.bbox, p.bbox);
        sum.closed = sum.closed && p.closed;
        sum.unit = p.unit;
    }
    // Solids weigh by their volume; where one is open its volume means nothing, so areas do.
    if (sum.closed && sum.volume > 0.0)
        sum.center = volumeMoment / sum.volume;
    else if (sum.area > 0.0)
        sum.center = areaMoment / sum.area;
    return sum;
}

namespace {

std::string number(double v) {
    return util::jsonNumber(v);
}

// The members after "object": what a solid and a sum print alike.
std::string propertiesBody(const SolidProperties& p) {
    const std::string closed = p.closed ? "true" : "false";
    return ",\"volume\":" + number(p.volume) + ",\"area\":" + number(p.area) +
           ",\"center\":" + util::jsonVector(p.center) +
           ",\"bbox\":{\"min\":" + util::jsonVector(p.bbox.min) +
           ",\"max\":" + util::jsonVector(p.bbox.max) +
           ",\"size\":" + util::jsonVector(p.bbox.max - p.bbox.min) + "},\"closed\":" + closed +
           "," + unitJsonMember(p.unit) + "}";
}

} // namespace

std::string distanceJson(const DistanceReport& r) {
    std::string json = "{\"distance\":" + number(r.distance) + ",\"p0\":" + util::jsonVector(r.p0) +
                       ",\"p1\":" + util::jsonVector(r.p1) + ",\"source\":\"" +
                       (r.fromBrep ? "brep" : "mesh") + "\"";
    auto optional = [&](const char* name, const std::optional<double>& value) {
        if (value) json += std::string(",\"") + name + "\":" + number(*value);
    };
    optional("center_distance", r.centreDistance);
    optional("axis_angle", r.axisAngleDegrees);
    optional("axis_distance", r.axisDistance);
    optional("point_to_plane", r.pointToPlane);
    return json + "," + unitJsonMember(r.unit) + "}";
}

std::string propertiesJson(const SolidProperties& p) {
    return "{\"object\":" + std::to_string(p.object) + propertiesBody(p);
}

std::string totalPropertiesJson(const SolidProperties& sum) {
    return "{\"object\":\"all\",\"objects\":" + std::to_string(sum.object) + propertiesBody(sum);
}

} // namespace scene
