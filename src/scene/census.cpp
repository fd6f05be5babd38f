// census.cpp - the census's views and the sums over what it found (see census.h).
#include "scene/census.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace scene {

std::vector<glm::dvec3> censusDirections(uint32_t count) {
    // Equal steps in z give equal areas of the sphere; the golden angle between successive
    // longitudes keeps neighbours from lining up.
    const double goldenAngle = std::numbers::pi * (3.0 - std::sqrt(5.0));
    std::vector<glm::dvec3> directions;
    directions.reserve(count);
    for (uint32_t i = 0; i < count; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / count;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = goldenAngle * i;
        directions.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
    }
    return directions;
}

Camera censusCamera(const Bounds& bounds, glm::dvec3 direction) {
    const double radius = std::max(bounds.radius(), 1e-3);
    Camera camera;
    camera.ortho = true;
    camera.target = bounds.center();
    // orthoHeight() is the perspective height at the target's distance: pick the distance
    // that makes it the sphere's diameter with the margin.
    const double height = 2.0 * radius * 1.02;
    const double distance = 0.5 * height / std::tan(0.5 * double(camera.fovY));
    direction = glm::normalize(direction);
    camera.eye = camera.target + direction * distance;
    // Any up not along the view; world z unless the view looks along it.
    camera.up = std::abs(direction.z) > 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
    fitPlanes(camera, bounds);
    return camera;
}

PartSet seenParts(const Census& census) {
    PartSet seen(uint32_t(census.parts.size()));
    for (uint32_t id = 0; id < census.parts.size(); ++id)
        if (census.seen(id)) seen.insert(id);
    return seen;
}

std::vector<uint8_t> seenObjects(const Scene& scene, const Census& census) {
    std::vector<uint8_t> seen(scene.objects.size(), 0);
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const Object& object = scene.objects[o];
        const uint32_t parts = scene.geometries[object.geometry].partCount;
        for (uint32_t p = 0; p < parts && !seen[o]; ++p)
            seen[o] = census.seen(object.uniquePartOffset + p);
    }
    return seen;
}

namespace {

enum class PartState { Seen, NeverSeen, Hidden, Empty };

PartState stateOf(const Scene& scene, const Census& census, const PartSet& hidden,
                  const Object& object, uint32_t local) {
    const uint32_t id = object.uniquePartOffset + local;
    if (census.seen(id)) return PartState::Seen;
    if (scene.part(object, local).empty()) return PartState::Empty;
    if (hidden.contains(id)) return PartState::Hidden;
    return PartState::NeverSeen;
}

} // namespace

CensusSummary summarize(const Scene& scene, const Census& census, const PartSet& hidden) {
    CensusSummary sum;
    sum.parts = scene.uniquePartCount();
    sum.objects = uint32_t(scene.objects.size());
    for (const Object& object : scene.objects) {
        const uint32_t parts = scene.geometries[object.geometry].partCount;
        uint64_t unseenTriangles = 0;
        bool anySeen = false, anyUnseen = false;
        for (uint32_t p = 0; p < parts; ++p) {
            const uint64_t triangles = scene.part(object, p).triangleCount;
            sum.triangles += triangles;
            switch (stateOf(scene, census, hidden, object, p)) {
            case PartState::Seen:
                ++sum.partsSeen, anySeen = true;
                break;
            case PartState::Empty:
                ++sum.partsEmpty;
                break;
            case PartState::Hidden:
                ++sum.partsHidden;
                break;
            case PartState::NeverSeen:
                ++sum.partsNeverSeen, anyUnseen = true;
                unseenTriangles += triangles;
                break;
            }
        }
        sum.trianglesNeverSeen += unseenTriangles;
        if (anySeen) ++sum.objectsSeen;
        if (!anySeen && anyUnseen) {
            ++sum.objectsNeverSeen;
            sum.objectTrianglesNeverSeen += unseenTriangles;
        }
    }
    return sum;
}

PartSet neverSeenParts(const Scene& scene, const Census& census, const PartSet& hidden) {
    PartSet never(scene.uniquePartCount());
    for (const Object& object : scene.objects)
        for (uint32_t p = 0; p < scene.geometries[object.geometry].partCount; ++p)
            if (stateOf(scene, census, hidden, object, p) == PartState::NeverSeen)
                never.insert(object.uniquePartOffset + p);
    return never;
}

} // namespace scene
