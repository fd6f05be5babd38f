// mesh_inspect.h - inspect.h's answers for scenes without a B-rep (glTF, generated): the
// minimum distance between two sets of parts from their triangles, and an object's area, box
// and, where its triangles close, enclosed volume and centre. World coordinates, double.
#pragma once

#include <array>
#include <optional>

#include <glm/glm.hpp>

#include "scene/inspect.h"
#include "scene/scene.h"

namespace scene {

using Triangle = std::array<glm::dvec3, 3>;

struct ClosestPoints {
    double distance = 0.0;
    glm::dvec3 p0{0.0}, p1{0.0}; // on the first triangle, on the second
};

// The exact minimum distance between two triangles (0 where they touch or cross).
ClosestPoints triangleDistance(const Triangle& a, const Triangle& b);

// Both sides' parts only (an edge side gives nullopt: meshes have no B-rep edges).
std::optional<DistanceReport> meshDistance(const Scene& scene, const Thing& a, const Thing& b);

std::optional<SolidProperties> meshProperties(const Scene& scene, uint32_t object);

} // namespace scene
