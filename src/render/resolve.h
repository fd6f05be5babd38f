// resolve.h - the compute clear path's end of the scene pass (ClearPath::Compute, settings.h):
// the pass cleared depth alone, and this pass writes the background's colour and ID where
// depth says no triangle covered a sample, resolving MSAA on the way (resolve.comp,
// shared_id_passes.h ResolvePush). Afterwards the single-sample shaded colour and IDs are in
// TRANSFER_SRC_OPTIMAL, as the pass path's pass leaves them, so every later reader of the ID
// image (picks, edges, part sets, culling's visible parts, the composition) is the same on
// both paths.
#pragma once

#include "render/pipeline.h"
#include "render/targets.h" // and shared.h, whose RESOLVE_* flags record() takes

namespace render {

// One per renderer, with both its pipelines (1x and multisampled) made up front.
class Resolver {
  public:
    Resolver(vk::Device& device, const vk::ShaderCompiler& compiler,
             const DiskPipelineCache& cache);

    // After the compute path's scene pass (whole, or its second half) into `targets`.
    // `flags`: gpu::RESOLVE_KEEP_COLOR when the pass cleared colour (X-ray), RESOLVE_NO_IDS
    // when its pipeline wrote no IDs (the floors).
    void record(VkCommandBuffer cmd, const SceneTargets& targets, uint32_t flags) const;

  private:
    // Around the dispatch: the single-sample images to GENERAL, after the pass's writes (1x,
    // where the pass drew into them) or discarding them (MSAA, overwritten whole); then to
    // TRANSFER_SRC_OPTIMAL for the copies, blits and passes that read them.
    void transition(VkCommandBuffer cmd, const SceneTargets& targets, bool before) const;

    vk::Device& device_;
    vk::Handle<VkDescriptorSetLayout> images_; // depth, sample IDs, sample colours, IDs, colour
    ComputePipeline resolve_[2];               // 1x, multisampled
};

} // namespace render
