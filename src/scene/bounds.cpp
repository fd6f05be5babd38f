// bounds.cpp - part and meshlet boxes.
#include "scene/bounds.h"

#include <algorithm>
#include <limits>

namespace scene {

Bounds emptyBounds() {
    return {glm::dvec3(std::numeric_limits<double>::max()),
            glm::dvec3(std::numeric_limits<double>::lowest())};
}

Bounds unite(const Bounds& a, const Bounds& b) {
    return {glm::min(a.min, b.min), glm::max(a.max, b.max)};
}

bool isEmpty(const Bounds& b) {
    return b.min.x > b.max.x || b.min.y > b.max.y || b.min.z > b.max.z;
}

std::vector<Bounds> partBounds(const Scene& scene) {
    std::vector<Bounds> boxes(scene.parts.size(), emptyBounds());
    for (const Geometry& g : scene.geometries)
        for (uint32_t p = 0; p < g.partCount; ++p) {
            const Part& part = scene.parts[g.firstPart + p];
            Bounds& box = boxes[g.firstPart + p];
            const uint32_t first = g.firstIndex + 3 * part.firstTriangle;
            for (uint32_t i = first; i < first + 3 * part.triangleCount; ++i) {
                const glm::vec3& position =
                    scene.vertices[g.firstVertex + scene.indices[i]].position;
                box.min = glm::min(box.min, glm::dvec3(position));
                box.max = glm::max(box.max, glm::dvec3(position));
            }
        }
    return boxes;
}

Bounds partsWorldBounds(const Scene& scene, const PartSet& parts) {
    Bounds box = emptyBounds();
    for (const uint32_t id : parts.ids()) {
        const auto ref = scene.locate(id);
        if (!ref) continue;
        const Object& object = scene.objects[ref->object];
        const Geometry& g = scene.geometries[object.geometry];
        const Part& part = scene.part(object, ref->localPart);
        const uint32_t first = g.firstIndex + 3 * part.firstTriangle;
        for (uint32_t i = first; i < first + 3 * part.triangleCount; ++i) {
            const glm::dvec3 p =
                placed(object.world, scene.vertices[g.firstVertex + scene.indices[i]].position);
            box.min = glm::min(box.min, p);
            box.max = glm::max(box.max, p);
        }
    }
    return box;
}

Clusters partClusters(const Scene& scene, uint32_t maxTriangles) {
    // Numbered in Scene::parts order, so that the clusters of a run of parts are a run too.
    Clusters c;
    c.first.assign(scene.parts.size() + 1, 0);
    for (size_t p = 0; p < scene.parts.size(); ++p)
        c.first[p + 1] =
            c.first[p] + (scene.parts[p].triangleCount + maxTriangles - 1) / maxTriangles;
    c.boxes.assign(c.first.back(), emptyBounds());
    c.localPart.assign(c.first.back(), 0);
    c.firstTriangle.assign(c.first.back(), 0);
    c.triangleCount.assign(c.first.back(), 0);
    for (const Geometry& g : scene.geometries)
        for (uint32_t p = 0; p < g.partCount; ++p) {
            const Part& part = scene.parts[g.firstPart + p];
            uint32_t cluster = c.first[g.firstPart + p];
            for (uint32_t t = 0; t < part.triangleCount; t += maxTriangles, ++cluster) {
                Bounds& box = c.boxes[cluster];
                c.localPart[cluster] = p;
                c.firstTriangle[cluster] = part.firstTriangle + t;
                c.triangleCount[cluster] = std::min(maxTriangles, part.triangleCount - t);
                const uint32_t first = g.firstIndex + 3 * (part.firstTriangle + t);
                const uint32_t end = first + 3 * c.triangleCount[cluster];
                for (uint32_t i = first; i < end; ++i) {
                    const glm::vec3& position =
                        scene.vertices[g.firstVertex + scene.indices[i]].position;
                    box.min = glm::min(box.min, glm::dvec3(position));
                    box.max = glm::max(box.max, glm::dvec3(position));
                }
            }
        }
    return c;
}

Bounds partRangeBounds(const Scene& scene, const std::vector<Bounds>& parts, uint32_t g,
                       uint32_t firstPart, uint32_t count) {
    Bounds box = emptyBounds();
    const uint32_t first = scene.geometries[g].firstPart + firstPart;
    for (uint32_t p = first; p < first + count; ++p) box = unite(box, parts[p]);
    return box;
}

std::vector<Bounds> meshletBounds(const Meshlets& meshlets, const std::vector<Vertex>& vertices) {
    std::vector<Bounds> boxes;
    boxes.reserve(meshlets.meshlets.size());
    for (const Meshlet& m : meshlets.meshlets) {
        Bounds box = emptyBounds();
        for (uint32_t v = m.firstVertex; v < m.firstVertex + m.vertexCount; ++v) {
            const glm::vec3& position = vertices[meshlets.vertices[v]].position;
            box.min = glm::min(box.min, glm::dvec3(position));
            box.max = glm::max(box.max, glm::dvec3(position));
        }
        boxes.push_back(box);
    }
    return boxes;
}

} // namespace scene
