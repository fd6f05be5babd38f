// mesh_builder.h - builds one geometry of a Scene face by face. Every part (CAD face) gets
// vertices of its own, so shading edges between faces stay hard, as in CAD tessellations;
// vertex normals for meshes that come without them.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace scene {

// Area-weighted vertex normals of a triangle list (3 `corners` a triangle, indexing
// `positions`): a large face dominates the small slivers around a vertex. A vertex no triangle
// with an area touches gets +z.
std::vector<glm::vec3> areaWeightedNormals(std::span<const glm::vec3> positions,
                                           std::span<const uint32_t> corners);

class MeshBuilder {
  public:
    // Starts a new part; triangles added after this belong to it.
    void beginPart();
    uint32_t addVertex(glm::vec3 position, glm::vec3 normal);
    void addTriangle(uint32_t a, uint32_t b, uint32_t c);

    // One flat part from a convex polygon (counter-clockwise seen from the normal's side).
    void addFlatFace(std::span<const glm::vec3> corners);
    // Box centred at `center`: six parts.
    void addBox(glm::vec3 center, glm::vec3 size);
    // Prism around +z from z0 to z1 with `sides` flat side parts and two cap parts; a large
    // `sides` with smoothSides=true makes a cylinder whose mantle is one smooth part.
    void addPrism(glm::vec2 center, float radius, float z0, float z1, int sides, bool smoothSides);

    uint32_t partCount() const { return static_cast<uint32_t>(parts_.size()); }

    // Appends the geometry to `scene` and returns its index. The builder is left empty.
    uint32_t finish(Scene& scene, std::string name);

  private:
    std::vector<Vertex> vertices_;
    std::vector<uint32_t> indices_;
    std::vector<Part> parts_;
};

} // namespace scene
