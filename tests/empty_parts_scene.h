// empty_parts_scene.h - a scene with empty parts (no triangles) made from one without: an
// empty part put at the start, in the middle and at the end of every geometry (its levels of
// detail alike), and an object of only empty parts after the first object; and the map from
// its unique part IDs back to the plain scene's, which numbers its parts without them. Also
// the small scene the unit tests make it from.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/mesh_builder.h"
#include "scene/procedural/shapes.h"
#include "scene/scene.h"

namespace testing_support {

// Four objects of three geometries: a box (6 parts, two of its own material), a turned part
// (5 bands of 64 triangles, with B-rep face numbers) and a square (1 part); the box twice.
inline scene::Scene fourObjectScene() {
    scene::Scene s;
    const uint32_t grey = scene::addMaterial(s, "grey", glm::vec4(0.6f, 0.6f, 0.6f, 1.0f));
    const uint32_t red = scene::addMaterial(s, "red", glm::vec4(0.8f, 0.1f, 0.1f, 1.0f));
    scene::MeshBuilder mb;
    mb.addBox({0, 0, 0}, {1, 1, 1});
    const uint32_t box = mb.finish(s, "box");
    const glm::vec2 profile[] = {{0.0f, 0.5f},  {0.4f, 0.5f},  {0.5f, 0.2f},
                                 {0.5f, -0.2f}, {0.4f, -0.5f}, {0.0f, -0.5f}};
    scene::addLathe(mb, scene::Frame{}, profile, 32);
    const uint32_t turned = mb.finish(s, "turned");
    const glm::vec3 square[] = {
        {-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}};
    mb.addFlatFace(square);
    const uint32_t face = mb.finish(s, "face");
    s.geometries[box].partMaterials = {gpu::OBJECT_MATERIAL, red,
                                       gpu::OBJECT_MATERIAL, red,
                                       gpu::OBJECT_MATERIAL, gpu::OBJECT_MATERIAL};
    for (uint32_t p = 0; p < s.geometries[turned].partCount; ++p)
        s.geometries[turned].partFaces.push_back(10 + p);
    auto at = [](double x, double y) { return glm::translate(glm::dmat4(1.0), {x, y, 0.0}); };
    scene::addObject(s, box, grey, at(0, 0), "box #1", "assembly/box #1");
    scene::addObject(s, turned, grey, at(3, 0), "turned", "assembly/turned");
    scene::addObject(s, face, red, at(-3, 0), "face", "face");
    scene::addObject(s, box, grey, at(0, 3), "box #2", "assembly/box #2");
    scene::validate(s);
    return s;
}

// What withEmptyParts() maps an empty part's ID to: no ID of any scene, nor the background.
constexpr uint32_t kEmptyPart = 0xFFFFFFF0u;
// The B-rep face an inserted empty part keeps, where the geometry's parts have faces.
constexpr uint32_t kEmptyPartFace = 999;

struct WithEmptyParts {
    scene::Scene scene;
    // Per unique part ID of `scene`: the plain scene's ID of the same part, or kEmptyPart.
    std::vector<uint32_t> plainId;
    uint32_t emptyObject = 1; // the object of only empty parts
};

// Where the empty parts go in a geometry of `parts` parts: before part 0, before part
// parts / 2 (where that is another place) and after the last.
inline std::vector<bool> emptySlots(uint32_t parts) {
    const uint32_t middle = parts / 2;
    std::vector<bool> slots;
    for (uint32_t p = 0; p <= parts; ++p) {
        if (p == 0 || p == parts || p == middle) slots.push_back(true);
        if (p < parts) slots.push_back(false);
    }
    return slots; // true: an empty part; false: the next of the plain geometry's parts
}

// Geometry `g` of `plain`, its parts appended to `parts` with empty ones in their slots, and
// its per-part arrays to match (an empty part has face kEmptyPartFace, its object's material).
inline void insertEmptyParts(const scene::Scene& plain, scene::Geometry& g,
                             std::vector<scene::Part>& parts) {
    const scene::Geometry from = g;
    g.firstPart = uint32_t(parts.size());
    g.partFaces.clear();
    g.partSurfaces.clear();
    g.partMaterials.clear();
    uint32_t next = 0, triangles = 0;
    for (bool empty : emptySlots(from.partCount)) {
        const uint32_t p = empty ? 0 : next++;
        const scene::Part part =
            empty ? scene::Part{triangles, 0} : plain.parts[from.firstPart + p];
        parts.push_back(part);
        triangles = part.firstTriangle + part.triangleCount;
        if (!from.partFaces.empty())
            g.partFaces.push_back(empty ? kEmptyPartFace : from.partFaces[p]);
        if (!from.partSurfaces.empty())
            g.partSurfaces.push_back(empty ? scene::SurfaceInfo{} : from.partSurfaces[p]);
        if (!from.partMaterials.empty())
            g.partMaterials.push_back(empty ? gpu::OBJECT_MATERIAL : from.partMaterials[p]);
    }
    g.partCount = uint32_t(parts.size()) - g.firstPart;
}

inline WithEmptyParts withEmptyParts(const scene::Scene& plain) {
    WithEmptyParts out;
    if (plain.objects.size() <= out.emptyObject)
        throw std::logic_error("withEmptyParts: the plain scene needs two objects");
    scene::Scene& s = out.scene;
    s = plain;
    s.parts.clear();
    s.objects.clear();
    for (scene::Geometry& g : s.geometries) insertEmptyParts(plain, g, s.parts.edit());
    // A geometry of three empty parts and nothing else, as a solid not meshed yet points to.
    scene::Geometry none;
    none.name = "not meshed";
    none.firstVertex = uint32_t(s.vertices.size());
    none.firstIndex = uint32_t(s.indices.size());
    none.firstPart = uint32_t(s.parts.size());
    none.partCount = 3;
    s.parts.resize(s.parts.size() + 3, scene::Part{0, 0});
    s.geometries.push_back(none);
    const uint32_t noneIndex = uint32_t(s.geometries.size() - 1);
    for (size_t o = 0; o < plain.objects.size(); ++o) {
        if (o == out.emptyObject) {
            scene::addObject(s, noneIndex, 0, glm::dmat4(1.0), "not meshed", "not meshed");
            out.plainId.resize(out.plainId.size() + 3, kEmptyPart);
        }
        const scene::Object& object = plain.objects[o];
        scene::addObject(s, object.geometry, object.material, object.world, object.name,
                         object.path);
        uint32_t next = object.uniquePartOffset;
        for (bool empty : emptySlots(plain.geometries[object.geometry].partCount))
            out.plainId.push_back(empty ? kEmptyPart : next++);
    }
    scene::validate(s);
    return out;
}

// `ids` (an ID image of the scene with empty parts) in the plain scene's IDs; an empty part's
// pixel becomes kEmptyPart, which no image of the plain scene holds.
inline std::vector<uint32_t> plainIds(const WithEmptyParts& scene, std::vector<uint32_t> ids) {
    for (uint32_t& id : ids)
        if (id != gpu::BACKGROUND_ID)
            id = id < scene.plainId.size() ? scene.plainId[id] : kEmptyPart;
    return ids;
}

} // namespace testing_support
