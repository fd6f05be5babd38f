// scene.h - the CAD scene model: geometries made of parts, objects placing geometries, and
// the unique part IDs that name every (object, part) pair. Plain C++, no Vulkan.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/part_set.h"
#include "scene/shared_array.h"
#include "scene/surface_info.h"
#include "scene/units.h"
#include "shared.h"

namespace scene {

class BrepShapes; // scene/cad/brep_shapes.h

using Vertex = gpu::Vertex;

// A CAD face: a contiguous range of its geometry's triangles. The range may be empty (a face
// that did not triangulate, a solid not meshed yet): an empty part keeps its unique part ID
// (and its B-rep face) but draws nothing, is never picked, and has no bounds, so fits, box
// selections, ray casts, levels of detail and exports pass over it.
struct Part {
    uint32_t firstTriangle = 0; // relative to the geometry's first triangle
    uint32_t triangleCount = 0;
    bool empty() const { return triangleCount == 0; }
};

// Geometry::partFaces of a part whose face the file lists but its reader did not give.
constexpr uint32_t kNoFace = 0xFFFFFFFFu;

// Vertices and triangles in the scene's shared arrays, drawable as one draw call. A geometry
// has at least one part; all of them may be empty, and then it has no triangles and no
// vertices (an object whose solid is not meshed yet points to one) and draws nothing.
struct Geometry {
    std::string name;
    uint32_t firstVertex = 0; // into Scene::vertices; the draw's vertexOffset
    uint32_t vertexCount = 0;
    uint32_t firstIndex = 0; // into Scene::indices (3 per triangle, geometry-local vertices)
    uint32_t triangleCount = 0;
    uint32_t firstPart = 0; // into Scene::parts
    uint32_t partCount = 0;
    // CAD files: each part's B-rep face, numbered as TopExp::MapShapes orders the shape's
    // faces, or kNoFace for a face the file lists that Open CASCADE did not give. Empty for
    // other sources, whose parts are no faces.
    std::vector<uint32_t> partFaces;
    // CAD files: each part's face as the B-rep knows it (surface type, exact area, plane,
    // axis, radius), in the order of partFaces; empty for other sources.
    std::vector<SurfaceInfo> partSurfaces;
    // A material per part, or gpu::OBJECT_MATERIAL where the object's applies (CAD faces
    // with colours of their own); empty when every part takes its object's.
    std::vector<uint32_t> partMaterials;
    // Levels of detail (scene/lod.h): a full-detail geometry lists its coarser levels, finest
    // first; a level records which it is and its geometric error in model units (the largest
    // distance between its surface and full detail's, as levelError in scene/lod_error.h
    // measures it).
    std::vector<uint32_t> levels;
    uint32_t level = 0;
    float lodError = 0.0f;
};

struct Material {
    std::string name;
    glm::vec4 color{0.7f, 0.7f, 0.7f, 1.0f};
};

// One placement of a geometry. Its parts have unique IDs uniquePartOffset + local index.
// Placements are double: a part kilometres from the origin keeps its millimetres here, and the
// GPU gets it relative to a point near the camera (render::eyeRelative), rounded once.
struct Object {
    uint32_t geometry = 0;
    uint32_t material = 0;
    glm::dmat4 world{1.0};
    uint32_t uniquePartOffset = 0;
    std::string name; // what a person calls it, e.g. "bolt M10 #12"
    // The names of the nodes from the scene root down to this object, joined by '/'; the last
    // one is the object's own name, e.g. "car/wheel front left/tyre front left".
    std::string path;
};

// A box in world (or geometry) coordinates, double like the placements it is computed from.
struct Bounds {
    glm::dvec3 min{0.0};
    glm::dvec3 max{0.0};
    glm::dvec3 center() const { return (min + max) * 0.5; }
    double radius() const { return glm::length(max - min) * 0.5; }
};

// Which object and which of its geometry's parts a unique part ID names.
struct PartRef {
    uint32_t object = 0;
    uint32_t localPart = 0;
};

// Everything a viewer shows about one unique part.
struct PartInfo {
    uint32_t uniquePartId = 0;
    uint32_t object = 0;
    uint32_t localPart = 0;
    uint32_t geometry = 0;
    uint32_t triangleCount = 0;
    std::string name; // the object's
    std::string path;
    std::optional<uint32_t> face; // CAD files: the part's B-rep face (Geometry::partFaces)
};

// A copy of a scene shares its geometry (vertices, indices, parts, geometries with their
// per-part arrays, materials) until one of them changes it (scene/shared_array.h): model copies
// and the exploded view copy only the objects they place.
struct Scene {
    SharedArray<Vertex> vertices;
    SharedArray<uint32_t> indices;
    SharedArray<Part> parts;
    SharedArray<Geometry> geometries;
    SharedArray<Material> materials;
    std::vector<Object> objects;
    // What the coordinates are in: set where the scene is loaded (app::loadScene), for every
    // length the viewer and the JSON show.
    LengthUnit unit = generatedUnit();
    // How finely its lengths are known, for the numbers the viewer shows: set where the scene
    // is loaded (app::loadScene, scenePrecision) like `unit`.
    Precision precision;
    // CAD files: the exact shapes behind the geometries (scene/cad/brep_shapes.h), shared by
    // copies of the scene; null for glTF and generated scenes.
    std::shared_ptr<const BrepShapes> brep;

    const Part& part(const Object& object, uint32_t localPart) const {
        return parts[geometries[object.geometry].firstPart + localPart];
    }
    // Unique part IDs run from 0 to uniquePartCount() - 1 without gaps.
    uint32_t uniquePartCount() const;
    // Triangles drawn for all objects (instanced geometry counted per object).
    uint64_t drawnTriangleCount() const;
    std::optional<PartRef> locate(uint32_t uniquePartId) const;
    // The box of every object's vertices; a point at the origin when none has any.
    Bounds bounds() const;
};

// Where a vertex position of a geometry lies once `world` places it, in double.
inline glm::dvec3 placed(const glm::dmat4& world, const glm::vec3& position) {
    return glm::dvec3(world * glm::dvec4(glm::dvec3(position), 1.0));
}

// nullopt when the ID names no part of `scene` (background, or a stale ID after a reload).
std::optional<PartInfo> describePart(const Scene& scene, uint32_t uniquePartId);

// The unique parts without triangles (Part::empty): what no image can show.
PartSet emptyParts(const Scene& scene);

// Adds an object and gives it the next free range of unique part IDs.
uint32_t addObject(Scene& scene, uint32_t geometry, uint32_t material, const glm::dmat4& world,
                   std::string name = {}, std::string path = {});
uint32_t addMaterial(Scene& scene, std::string name, glm::vec4 color);

// `group` + '/' + `name`, or just `name` at the root (empty `group`).
std::string joinPath(const std::string& group, const std::string& name);

// For generated scenes: adds an object called `name` whose path is `group`/`name`.
uint32_t addNamedObject(Scene& scene, uint32_t geometry, uint32_t material, const glm::dmat4& world,
                        const std::string& group, const std::string& name);

// Numbers generated object names per kind so that they are unique within a scene: the first
// next("bolt M10") is "bolt M10 #1", the second "bolt M10 #2", whatever came in between.
class NameCounter {
  public:
    std::string next(const std::string& kind);
    // addNamedObject for one more object of `geometry`'s kind, numbered after the geometry's
    // name: the 12th of geometry "bolt M10" is "bolt M10 #12".
    uint32_t add(Scene& scene, uint32_t geometry, uint32_t material, const glm::dmat4& world,
                 const std::string& group);

  private:
    std::map<std::string, uint32_t> counts_;
};

// A model that cannot be loaded, from any importer. what() is one line: "<path>: <reason>".
struct ModelError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws std::invalid_argument naming the first inconsistency (index out of range, parts not
// covering their geometry's triangles in order, a geometry without parts, overlapping unique
// IDs, ...). Empty parts and geometries without triangles are consistent: an empty part
// starts where the triangles before it end.
void validate(const Scene& scene);

} // namespace scene
