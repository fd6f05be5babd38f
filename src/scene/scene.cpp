// scene.cpp - unique part ID bookkeeping, bounds and consistency checks.
#include "scene/scene.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace scene {

uint32_t Scene::uniquePartCount() const {
    if (objects.empty()) return 0;
    const Object& last = objects.back();
    return last.uniquePartOffset + geometries[last.geometry].partCount;
}

uint64_t Scene::drawnTriangleCount() const {
    uint64_t total = 0;
    for (const auto& object : objects) total += geometries[object.geometry].triangleCount;
    return total;
}

std::optional<PartRef> Scene::locate(uint32_t uniquePartId) const {
    // Objects hold increasing, contiguous ID ranges: find the last one starting at or below.
    auto it =
        std::upper_bound(objects.begin(), objects.end(), uniquePartId,
                         [](uint32_t id, const Object& o) { return id < o.uniquePartOffset; });
    if (it == objects.begin()) return std::nullopt;
    --it;
    uint32_t local = uniquePartId - it->uniquePartOffset;
    if (local >= geometries[it->geometry].partCount) return std::nullopt;
    return PartRef{static_cast<uint32_t>(it - objects.begin()), local};
}

std::optional<PartInfo> describePart(const Scene& scene, uint32_t uniquePartId) {
    const auto ref = scene.locate(uniquePartId);
    if (!ref) return std::nullopt;
    const Object& object = scene.objects[ref->object];
    const Geometry& geometry = scene.geometries[object.geometry];
    PartInfo info{uniquePartId,
                  ref->object,
                  ref->localPart,
                  object.geometry,
                  scene.part(object, ref->localPart).triangleCount,
                  object.name,
                  object.path,
                  std::nullopt};
    if (ref->localPart < geometry.partFaces.size() && geometry.partFaces[ref->localPart] != kNoFace)
        info.face = geometry.partFaces[ref->localPart];
    return info;
}

PartSet emptyParts(const Scene& scene) {
    PartSet empty(scene.uniquePartCount());
    for (const Object& object : scene.objects) {
        const Geometry& g = scene.geometries[object.geometry];
        for (uint32_t p = 0; p < g.partCount; ++p)
            if (scene.parts[g.firstPart + p].empty()) empty.insert(object.uniquePartOffset + p);
    }
    return empty;
}

Bounds Scene::bounds() const {
    Bounds b;
    b.min = glm::dvec3(std::numeric_limits<double>::max());
    b.max = glm::dvec3(std::numeric_limits<double>::lowest());
    bool any = false;
    for (const auto& object : objects) {
        const Geometry& g = geometries[object.geometry];
        for (uint32_t v = 0; v < g.vertexCount; ++v) {
            const glm::dvec3 p = placed(object.world, vertices[g.firstVertex + v].position);
            b.min = glm::min(b.min, p);
            b.max = glm::max(b.max, p);
        }
        any = any || g.vertexCount > 0;
    }
    // Nothing meshed yet: a point, which cameras fit as they fit an empty scene.
    if (!any) b = {};
    return b;
}

uint32_t addObject(Scene& scene, uint32_t geometry, uint32_t material, const glm::dmat4& world,
                   std::string name, std::string path) {
    Object object;
    object.geometry = geometry;
    object.material = material;
    object.world = world;
    object.uniquePartOffset = scene.uniquePartCount();
    object.name = std::move(name);
    object.path = std::move(path);
    scene.objects.push_back(std::move(object));
    return static_cast<uint32_t>(scene.objects.size() - 1);
}

std::string joinPath(const std::string& group, const std::string& name) {
    return group.empty() ? name : group + '/' + name;
}

uint32_t addNamedObject(Scene& scene, uint32_t geometry, uint32_t material, const glm::dmat4& world,
                        const std::string& group, const std::string& name) {
    return addObject(scene, geometry, material, world, name, joinPath(group, name));
}

std::string NameCounter::next(const std::string& kind) {
    return kind + " #" + std::to_string(++counts_[kind]);
}

uint32_t NameCounter::add(Scene& scene, uint32_t geometry, uint32_t material,
                          const glm::dmat4& world, const std::string& group) {
    return addNamedObject(scene, geometry, material, world, group,
                          next(scene.geometries[geometry].name));
}

uint32_t addMaterial(Scene& scene, std::string name, glm::vec4 color) {
    scene.materials.push_back({std::move(name), color});
    return static_cast<uint32_t>(scene.materials.size() - 1);
}

static void fail(const std::string& what) {
    throw std::invalid_argument("invalid scene: " + what);
}

void validate(const Scene& scene) {
    for (size_t gi = 0; gi < scene.geometries.size(); ++gi) {
        const Geometry& g = scene.geometries[gi];
        const std::string name = "geometry " + std::to_string(gi) + " '" + g.name + "'";
        if (uint64_t(g.firstVertex) + g.vertexCount > scene.vertices.size())
            fail(name + " has vertices past the end of the vertex array");
        if (uint64_t(g.firstIndex) + 3ull * g.triangleCount > scene.indices.size())
            fail(name + " has triangles past the end of the index array");
        if (uint64_t(g.firstPart) + g.partCount > scene.parts.size())
            fail(name + " has parts past the end of the part array");
        if (g.partCount == 0) fail(name + " has no parts");
        uint32_t expected = 0;
        for (uint32_t p = 0; p < g.partCount; ++p) {
            const Part& part = scene.parts[g.firstPart + p];
            if (part.firstTriangle != expected)
                fail(name + " part " + std::to_string(p) + " does not follow the previous one");
            expected += part.triangleCount;
        }
        if (expected != g.triangleCount) fail(name + " parts do not cover all its triangles");
        // Bounds come from vertices: one without triangles would give an empty part a box.
        if (g.triangleCount == 0 && g.vertexCount != 0)
            fail(name + " has vertices but no triangles");
        for (uint32_t i = 0; i < 3 * g.triangleCount; ++i)
            if (scene.indices[g.firstIndex + i] >= g.vertexCount)
                fail(name + " indexes a vertex it does not own");
        if (!g.partMaterials.empty() && g.partMaterials.size() != g.partCount)
            fail(name + " has part materials for another number of parts");
        for (uint32_t m : g.partMaterials)
            if (m != gpu::OBJECT_MATERIAL && m >= scene.materials.size())
                fail(name + " gives a part a missing material");
    }
    uint32_t nextId = 0;
    for (size_t oi = 0; oi < scene.objects.size(); ++oi) {
        const Object& o = scene.objects[oi];
        if (o.geometry >= scene.geometries.size() || o.material >= scene.materials.size())
            fail("object " + std::to_string(oi) + " references a missing geometry or material");
        if (o.uniquePartOffset != nextId)
            fail("object " + std::to_string(oi) +
                 " unique part IDs do not follow the previous object");
        nextId += scene.geometries[o.geometry].partCount;
    }
}

} // namespace scene
