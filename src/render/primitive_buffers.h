// primitive_buffers.h - the derived geometry that vertex-fs and the mesh techniques draw
// instead of the scene's index buffer (scene/part_vertices.h, scene/meshlets.h), in device
// buffers. Each is built and uploaded once per scene, the first time a technique needs it;
// the draw buffers that use one hold it, so frames in flight keep it alive.
#pragma once

#include <memory>

#include "render/draw_list.h"
#include "vk/upload.h"

namespace render {

struct PartVertexBuffers {
    PartVertexBuffers(const scene::Scene& scene, vk::UploadBatch& upload);
    scene::PartVertices cpu; // vertices and indices dropped once uploaded
    vk::Buffer vertices, indices;
    uint64_t bytes = 0;
};

// Meshlets cut from part vertices of their own (the same as vertex-fs draws), uploaded
// with them: each triangle's first vertex carries its part, for mesh-vertex-fs; mesh-fs
// reads per-triangle indices, no-id-mesh nothing.
struct MeshletBuffers {
    MeshletBuffers(const scene::Scene& scene, vk::UploadBatch& upload);
    scene::PartVertices partVertices; // vertices and indices dropped once uploaded
    // What the draw lists read (the per-geometry layout, the parts of vertices and triangles);
    // the meshlets, their vertices, corners and source triangles dropped once uploaded.
    scene::Meshlets cpu;
    uint64_t meshletCount = 0;
    vk::Buffer meshlets; // gpu::Meshlet[]
    vk::Buffer data;     // uint[]: meshlet vertices, then packed corners
    vk::Buffer vertices; // the part vertices, read by address
    vk::Buffer boxes;    // gpu::CullBox[]: what the task shader culls by
    uint64_t bytes = 0;
};

// What buildDrawList needs of them (either may be null).
DerivedPrimitives derivedPrimitives(const PartVertexBuffers* partVertices,
                                    const MeshletBuffers* meshlets);

} // namespace render
