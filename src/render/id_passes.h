// id_passes.h - compute passes over the scene pass's resolved ID image, recorded right after
// it: part edges and outlines written into the colour image (edges.comp), and the set of
// unique parts inside pixel rectangles (part_set.comp: box selection, the visible parts),
// copied to the frame slot's readback like the pick. With MSAA they see the resolved IDs,
// sample 0 of each pixel, as the pick does.
#pragma once

#include <vector>

#include "render/pick.h"
#include "render/pipeline.h"
#include "render/targets.h"
#include "shared.h"

namespace render {

class IdPasses {
  public:
    IdPasses(vk::Device& device, const vk::ShaderCompiler& compiler);

    // Both images from TRANSFER_SRC_OPTIMAL (the scene pass's final layout) to GENERAL and
    // back around the passes; `edges` null draws none. The part sets write `results` (one
    // PartSetResult plus `words` words per query, zeroed here) and are copied to `readback`.
    void record(VkCommandBuffer cmd, const SceneTargets& targets, const gpu::EdgePush* edges,
                const std::vector<PartSetQuery>& queries, uint32_t words, const vk::Buffer& results,
                const vk::Buffer& readback) const;

    // Culling's visible-part pass: every unique part of the resolved ID image into
    // `visible` (a gpu::PartSetResult, then `words` words), cleared first. The next frame's
    // culling reads it: what the last ID image showed is drawn first.
    void recordVisible(VkCommandBuffer cmd, const SceneTargets& targets, const vk::Buffer& visible,
                       uint32_t words) const;

  private:
    void dispatchPartSet(VkCommandBuffer cmd, const SceneTargets& targets,
                         const PartSetQuery& query, VkDeviceAddress result, uint32_t words) const;
    void bindImages(VkCommandBuffer cmd, const SceneTargets& targets,
                    const ComputePipeline& pass) const;
    void transition(VkCommandBuffer cmd, const SceneTargets& targets, bool toGeneral) const;

    vk::Device& device_;
    vk::Handle<VkDescriptorSetLayout> images_; // pushed per frame: IDs, colour
    ComputePipeline edges_, partSet_;
};

} // namespace render
