// primitive_buffers.cpp - building and uploading the derived geometry.
#include "render/primitive_buffers.h"

#include "scene/bounds.h"
#include "shared.h"

namespace render {
namespace {

template <typename T>
void release(std::vector<T>& values) {
    std::vector<T>().swap(values);
}

// Where the triangles' corner words start in the meshlet data: after every meshlet vertex.
uint32_t cornersStart(const scene::Meshlets& meshlets) {
    return static_cast<uint32_t>(meshlets.vertices.size());
}

} // namespace

PartVertexBuffers::PartVertexBuffers(const scene::Scene& scene, vk::UploadBatch& upload)
    : cpu(scene::buildPartVertices(scene)) {
    vertices = upload.add(cpu.vertices, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "part vertices");
    indices = upload.add(cpu.indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "part vertex indices");
    bytes = derivedBytes(&cpu, nullptr);
    release(cpu.vertices);
    release(cpu.indices);
}

MeshletBuffers::MeshletBuffers(const scene::Scene& scene, vk::UploadBatch& upload)
    : partVertices(scene::buildPartVertices(scene)),
      cpu(scene::buildMeshlets(scene, &partVertices)) {
    const VkBufferUsageFlags shaderRead =
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
    vertices = upload.add(partVertices.vertices, shaderRead, "meshlet part vertices");
    bytes = derivedBytes(&partVertices, &cpu);
    std::vector<gpu::CullBox> gpuBoxes;
    gpuBoxes.reserve(cpu.meshlets.size());
    for (const scene::Bounds& box : scene::meshletBounds(cpu, partVertices.vertices))
        gpuBoxes.push_back({box.min, 0, box.max, 0});
    boxes = upload.add(gpuBoxes.empty() ? std::vector<gpu::CullBox>(1) : gpuBoxes, shaderRead,
                       "meshlet boxes");
    std::vector<gpu::Meshlet> gpuMeshlets;
    gpuMeshlets.reserve(cpu.meshlets.size());
    for (const scene::Meshlet& m : cpu.meshlets)
        gpuMeshlets.push_back({m.firstVertex, cornersStart(cpu) + m.firstTriangle,
                               m.vertexCount | m.triangleCount << 16, m.firstLocalTriangle});
    meshlets = upload.add(gpuMeshlets, shaderRead, "meshlets");
    meshletCount = cpu.meshlets.size();
    // One uint array: each meshlet's vertices, then each triangle's corners in one word.
    std::vector<uint32_t> words = std::move(cpu.vertices);
    words.reserve(words.size() + cpu.sourceTriangle.size());
    for (size_t t = 0; t < cpu.sourceTriangle.size(); ++t) {
        const uint8_t* c = &cpu.corners[3 * t];
        words.push_back(uint32_t(c[0]) | uint32_t(c[1]) << 8 | uint32_t(c[2]) << 16);
    }
    data = upload.add(words, shaderRead, "meshlet vertices and triangles");
    release(cpu.meshlets);
    release(cpu.vertices);
    release(cpu.corners);
    release(cpu.sourceTriangle);
    release(partVertices.vertices);
    release(partVertices.indices);
}

DerivedPrimitives derivedPrimitives(const PartVertexBuffers* partVertices,
                                    const MeshletBuffers* meshlets) {
    DerivedPrimitives derived;
    if (partVertices) {
        derived.partVertices = &partVertices->cpu;
        derived.bytes += partVertices->bytes;
    }
    if (meshlets) {
        derived.meshlets = &meshlets->cpu;
        derived.bytes += meshlets->bytes;
        derived.meshletCount = meshlets->meshletCount;
        derived.partVertices = &meshlets->partVertices;
    }
    return derived;
}

} // namespace render
