// inspect.cpp - distances and properties (inspect.h): from the B-rep where the scene has one
// (cad/brep_inspect.h), from triangles otherwise (mesh_inspect.h); and their JSON lines.
#include "scene/inspect.h"

#include <algorithm>

#include "scene/bounds.h"
#include "scene/cad/brep_inspect.h"
#include "scene/mesh_inspect.h"
#include "util/json_writer.h"

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

Precision scenePrecision(const Scene& scene) {
    const Bounds b = scene.bounds();
    const glm::dvec3 reach = glm::max(glm::abs(b.min), glm::abs(b.max));
    return modelPrecision(std::max({reach.x, reach.y, reach.z}), brepTolerance(scene));
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

// The members after "object", what a solid and a sum print alike; closes the line.
std::string finishProperties(util::JsonWriter& json, const SolidProperties& p) {
    json.member("volume", p.volume).member("area", p.area).member("center", p.center);
    if (isEmpty(p.bbox)) // an object without triangles (not meshed)
        json.key("bbox").null();
    else
        json.beginObject("bbox")
            .member("min", p.bbox.min)
            .member("max", p.bbox.max)
            .member("size", p.bbox.max - p.bbox.min)
            .endObject();
    json.member("closed", p.closed);
    unitMember(json, p.unit);
    return json.endObject().text();
}

} // namespace

std::string distanceJson(const DistanceReport& r) {
    util::JsonWriter json;
    json.beginObject()
        .member("distance", r.distance)
        .member("p0", r.p0)
        .member("p1", r.p1)
        .member("source", r.fromBrep ? "brep" : "mesh");
    auto optional = [&](const char* name, const std::optional<double>& value) {
        if (value) json.member(name, *value);
    };
    optional("center_distance", r.centreDistance);
    optional("axis_angle", r.axisAngleDegrees);
    optional("axis_distance", r.axisDistance);
    optional("point_to_plane", r.pointToPlane);
    unitMember(json, r.unit);
    return json.endObject().text();
}

std::string propertiesJson(const SolidProperties& p) {
    util::JsonWriter json;
    json.beginObject().member("object", p.object);
    return finishProperties(json, p);
}

std::string totalPropertiesJson(const SolidProperties& sum) {
    util::JsonWriter json;
    json.beginObject().member("object", "all").member("objects", sum.object);
    return finishProperties(json, sum);
}

} // namespace scene
