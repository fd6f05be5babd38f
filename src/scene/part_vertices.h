// part_vertices.h - what vertex-fs draws: the scene's triangles with their indices rotated
// (winding kept) so that each triangle's first vertex, the provoking vertex that a flat
// varying is taken from, belongs to the triangle's part. The part index then travels per
// vertex and the fragment shader never needs gl_PrimitiveID. A vertex is duplicated only
// where triangles of different parts share it and no rotation helps. Plain C++, computed
// once per scene.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace scene {

struct PartVertices {
    // The scene's vertices with each geometry's duplicates appended after its own vertices,
    // so geometries move: firstVertex/vertexCount replace Geometry's.
    std::vector<Vertex> vertices;
    std::vector<uint32_t> firstVertex; // per geometry
    std::vector<uint32_t> vertexCount; // per geometry
    // Like Scene::indices (same triangles in the same order, geometry-local), rotated.
    std::vector<uint32_t> indices;
    // Per vertex of `vertices`: the local part of every triangle that has it first.
    std::vector<uint32_t> localPart;
    uint64_t addedVertices = 0; // duplicates, over all geometries
};

PartVertices buildPartVertices(const Scene& scene);

} // namespace scene
