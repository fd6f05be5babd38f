// meshlets.h - what the mesh-shader techniques draw: each geometry cut into meshlets by
// meshoptimizer (each part's triangles ordered for vertex reuse, then cut in order by
// meshopt_buildMeshletsScan), with the local part of every meshlet triangle. Plain C++,
// computed once per scene.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/part_vertices.h"
#include "scene/scene.h"

namespace scene {

// Limits of one meshlet (shared.h): 64 vertices and 124 triangles fit every device's mesh
// shader output limits (at least 256 each) and are the sizes NVIDIA recommends.
constexpr uint32_t meshletMaxVertices = gpu::MESHLET_MAX_VERTICES;
constexpr uint32_t meshletMaxTriangles = gpu::MESHLET_MAX_TRIANGLES;

struct Meshlet {
    uint32_t firstVertex = 0;   // into Meshlets::vertices
    uint32_t firstTriangle = 0; // into Meshlets::triangles
    uint32_t vertexCount = 0;
    uint32_t triangleCount = 0;
    uint32_t firstLocalTriangle = 0; // its first triangle's position in its geometry's list
    uint32_t firstLocalVertex = 0;   // its first vertex's position in its geometry's list
};

struct Meshlets {
    std::vector<Meshlet> meshlets;                    // geometry after geometry
    std::vector<uint32_t> firstMeshlet, meshletCount; // per geometry
    std::vector<uint32_t> geometryFirstTriangle;      // per geometry: into the per-triangle arrays
    std::vector<uint32_t> geometryFirstVertex;        // per geometry: into `vertices`
    // Per meshlet vertex: the vertex it is (absolute index into the vertex array meshed:
    // Scene::vertices, or PartVertices::vertices).
    std::vector<uint32_t> vertices;
    // Per meshlet vertex, when built over part vertices: the vertex's local part (the part of
    // every triangle that has it first). Empty otherwise.
    std::vector<uint32_t> vertexPart;
    // Per meshlet triangle: its three corners as meshlet-local vertex indices.
    std::vector<uint8_t> corners; // 3 per triangle
    // Per meshlet triangle, in the same order: its scene triangle within the geometry and
    // that triangle's local part. A geometry's meshlet triangles are a permutation of its
    // triangles.
    std::vector<uint32_t> sourceTriangle;
    std::vector<uint32_t> localPart;
};

// Meshlets over the scene's vertices and indices, or, given `partVertices`, over those: then
// each triangle keeps its first corner first, the vertex that carries its part.
Meshlets buildMeshlets(const Scene& scene, const PartVertices* partVertices = nullptr);

} // namespace scene
