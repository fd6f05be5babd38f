// draw_buffers.h - a draw list on the GPU: the technique's ID data, the per-draw data and the
// indirect commands of the mdi modes, the derived geometry the draws read, and what culling
// needs of them (each draw's box, the meshlet bits, the passes' lists and counters). Built
// when the scene or what the list depends on changes, never per frame; recording a frame's
// draws from it is draw_recording.cpp's.
#pragma once

#include <memory>
#include <vector>

#include "render/culling.h"
#include "render/draw_list.h"
#include "render/primitive_buffers.h"
#include "render/scene_gpu.h"
#include "render/settings.h"

namespace render {

struct DrawBuffers {
    // What the CPU still reads of the list once it is uploaded: in push mode every draw's
    // range and data (recorded each frame), in the mdi modes only fullDetailDraws; the ID
    // data is on the GPU alone.
    DrawList list;
    RenderStats stats; // of the whole list, worked out before it was let go of
    vk::Buffer ids, draws, indirect, drawIndices;
    // The visibility buffer: its draws and the draw of each meshlet slot of payloads
    // (DrawList::visibilityDraws, visibilityBlocks); empty for the other techniques.
    vk::Buffer visibilityDraws, visibilityBlocks;
    // The compute rasterizer's lists (gpu::RasterEntry per listed meshlet after a dispatch
    // header per pass, shared_visibility.h), `rasterCapacity` entries a pass: every meshlet
    // of the list, all levels; empty for the other techniques.
    vk::Buffer rasterList;
    uint32_t rasterCapacity = 0;
    // The derived geometry the draws read, if the technique draws one.
    std::shared_ptr<const PartVertexBuffers> partVertices;
    std::shared_ptr<const MeshletBuffers> meshlets;
    PipelineKey key;     // effective key it was built for (technique, mode, batch)
    DrawSettings inputs; // and the draw settings
    bool levels = false; // and whether the list holds every level of detail (DrawList)
    // Culling: the GPU state (shared by the frames in flight), the bytes of one indirect
    // command, and the meshlets all draws launch.
    std::shared_ptr<const CullBuffers> cull;
    uint32_t commandBytes = 0;
    uint64_t meshletTotal = 0;
    // Push mode: each object's box, for the CPU's frustum test.
    std::vector<scene::Bounds> objectBoxes;
};

// The draws of `key` under `draws` over the scene on the GPU, every level of detail included
// where `levels`; `partVertices` and `meshlets` are the derived geometry, built by the
// caller when the technique draws it.
std::shared_ptr<DrawBuffers> buildDrawBuffers(vk::Device& device, const scene::Scene& scene,
                                              const SceneGpu& sceneGpu, const PipelineKey& key,
                                              const DrawSettings& draws,
                                              std::shared_ptr<const PartVertexBuffers> partVertices,
                                              std::shared_ptr<const MeshletBuffers> meshlets,
                                              bool levels, vk::UploadBatch& upload);

// What one frame draws of a list, and how, for draw_recording.cpp.
struct DrawContext {
    VkCommandBuffer cmd;
    const vk::Device& device;
    VkPipelineLayout layout;
    VkShaderStageFlags pushStages;
    const DrawBuffers& buffers;
};

// The whole list: one draw call per draw in push mode, indirect calls in the mdi modes.
void recordAllDraws(const DrawContext& c);
// Push mode with culling: the draws whose objects `objectShown` holds (indexed by object),
// with `phase` pushed for the task shader. Returns draws issued and their triangles.
struct Issued {
    uint32_t draws = 0;
    uint64_t triangles = 0;
};
Issued recordPushDraws(const DrawContext& c, const std::vector<uint8_t>& objectShown,
                       uint32_t phase);
// The mdi modes' lists cull.comp wrote: list `which` (0 early or only, 1 late), drawn by the
// count it wrote; runs of clusters (RunCommand) or whole draws.
void recordCulledDraws(const DrawContext& c, uint32_t which, uint32_t phase, bool runs);

} // namespace render
