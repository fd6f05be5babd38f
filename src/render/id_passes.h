// id_passes.h - compute passes over the scene pass's resolved ID image: the composition of
// the picture shown (compose.comp: the hovered part's blink, the selection's tint, edges and
// outlines over the shaded colour, and the part under the hovered pixel), and the set of
// unique parts inside pixel rectangles (part_set.comp: box selection, the visible parts),
// copied to the frame slot's readback like the pick. They run after the scene pass, or alone
// over the images the last one left (a viewer at rest). With MSAA they see the resolved IDs,
// sample 0 of each pixel, as the pick does.
#pragma once

#include <optional>
#include <vector>

#include "render/pick.h"
#include "render/pipeline.h"
#include "render/targets.h"
#include "shared.h"

namespace render {

class IdPasses {
  public:
    IdPasses(vk::Device& device, const vk::ShaderCompiler& compiler,
             const DiskPipelineCache& cache);

    // The composition into targets.color(), then the part sets. The images go from
    // TRANSFER_SRC_OPTIMAL (the scene pass's final layout) to GENERAL and back around the
    // passes. The part sets write `results` (one PartSetResult plus `words` words per query,
    // zeroed here) and are copied to `readback`. Without `tiles` the whole picture is
    // composed and the hovered part's tiles go to compose.boxAddress; with them, only those
    // tiles, over the picture the composition before left (it differed in the blink alone).
    void record(VkCommandBuffer cmd, const SceneTargets& targets, const gpu::ComposePush& compose,
                const std::optional<HoveredTiles>& tiles, const std::vector<PartSetQuery>& queries,
                uint32_t words, const vk::Buffer& results, const vk::Buffer& readback) const;

  private:
    void createCompose(const vk::ShaderCompiler& compiler, const DiskPipelineCache& cache);
    void dispatchPartSet(VkCommandBuffer cmd, const SceneTargets& targets,
                         const PartSetQuery& query, VkDeviceAddress result, uint32_t words,
                         const ComputePipeline& pass) const;
    void bindImages(VkCommandBuffer cmd, const SceneTargets& targets,
                    const ComputePipeline& pass) const;
    void compose(VkCommandBuffer cmd, const SceneTargets& targets, gpu::ComposePush push,
                 const std::optional<HoveredTiles>& tiles) const;
    // To GENERAL (keeping the composed colour or not) and back to TRANSFER_SRC_OPTIMAL.
    enum class Move { ToGeneral, ToGeneralKeepingColor, Back };
    void transition(VkCommandBuffer cmd, const SceneTargets& targets, Move move) const;

    vk::Device& device_;
    vk::Handle<VkDescriptorSetLayout> images_; // pushed per frame: IDs, colour
    // Pushed per frame: IDs, composed colour, shaded colour, depth (read with texelFetch).
    vk::Handle<VkDescriptorSetLayout> composeImages_;
    vk::Handle<VkSampler> depthSampler_;
    ComputePipeline compose_[2]; // depth single-sampled, multisampled
    ComputePipeline partSet_;
};

} // namespace render
