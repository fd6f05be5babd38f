// exterior.cpp - cutting a scene down to kept parts (see exterior.h).
#include "scene/exterior.h"

#include <map>
#include <utility>

namespace scene {
namespace {

// Which of an object's parts are kept, as the key of the geometry made for them.
using Kept = std::vector<bool>;

Kept keptOf(const Scene& scene, const Object& object, const PartSet& keep) {
    const Geometry& geometry = scene.geometries[object.geometry];
    Kept kept(geometry.partCount);
    for (uint32_t p = 0; p < geometry.partCount; ++p)
        kept[p] = keep.contains(object.uniquePartOffset + p) && !scene.part(object, p).empty();
    return kept;
}

// A geometry of `from`'s kept parts, over the same vertices.
uint32_t addSubset(Scene& out, const Scene& source, uint32_t from, const Kept& kept) {
    const Geometry& original = source.geometries[from];
    Geometry geometry;
    geometry.name = original.name;
    geometry.firstVertex = original.firstVertex;
    geometry.vertexCount = original.vertexCount;
    geometry.firstIndex = uint32_t(out.indices.size());
    geometry.firstPart = uint32_t(out.parts.size());
    std::vector<uint32_t>& indices = out.indices.edit();
    for (uint32_t p = 0; p < original.partCount; ++p) {
        if (!kept[p]) continue;
        const Part& part = source.parts[original.firstPart + p];
        out.parts.push_back(Part{geometry.triangleCount, part.triangleCount});
        const uint32_t first = original.firstIndex + 3 * part.firstTriangle;
        indices.insert(indices.end(), source.indices.begin() + first,
                       source.indices.begin() + first + 3 * part.triangleCount);
        geometry.triangleCount += part.triangleCount;
        ++geometry.partCount;
        if (!original.partFaces.empty()) geometry.partFaces.push_back(original.partFaces[p]);
        if (!original.partSurfaces.empty())
            geometry.partSurfaces.push_back(original.partSurfaces[p]);
        if (!original.partMaterials.empty())
            geometry.partMaterials.push_back(original.partMaterials[p]);
    }
    out.geometries.push_back(std::move(geometry));
    return uint32_t(out.geometries.size() - 1);
}

bool all(const Kept& kept) {
    for (bool k : kept)
        if (!k) return false;
    return true;
}

bool any(const Kept& kept) {
    for (bool k : kept)
        if (k) return true;
    return false;
}

} // namespace

Scene keptParts(const Scene& scene, const PartSet& keep) {
    Scene out;
    out.vertices = scene.vertices;
    out.indices = scene.indices;
    out.parts = scene.parts;
    out.geometries = scene.geometries;
    out.materials = scene.materials;
    out.unit = scene.unit;
    out.precision = scene.precision;
    // Levels of detail point at geometries by index; the writer draws full detail alone.
    for (Geometry& geometry : out.geometries.edit()) geometry.levels.clear();
    std::map<std::pair<uint32_t, Kept>, uint32_t> subsets;
    for (const Object& object : scene.objects) {
        const Kept kept = keptOf(scene, object, keep);
        if (!any(kept)) continue;
        uint32_t geometry = object.geometry;
        if (!all(kept)) {
            const auto key = std::make_pair(object.geometry, kept);
            auto found = subsets.find(key);
            if (found == subsets.end())
                found = subsets.emplace(key, addSubset(out, scene, object.geometry, kept)).first;
            geometry = found->second;
        }
        addObject(out, geometry, object.material, object.world, object.name, object.path);
    }
    return out;
}

} // namespace scene
