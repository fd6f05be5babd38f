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

// A compute pass that ends the compute path's scene pass (this resolve, or the visibility
// buffer's shading, render/visibility.h): one pipeline at 1x, one multisampled (its shader
// built with IDV_RESOLVE_MSAA), over a tile of ID_PASS_TILE pixels per workgroup. It reads
// depth and, with MSAA, the multisampled IDs and colour (bindings 0-2); it reads and writes
// the single-sample IDs and colour (3, 4), which afterwards are in TRANSFER_SRC_OPTIMAL as the
// pass path leaves them.
class ComputeEndPass {
  public:
    ComputeEndPass(vk::Device& device, const vk::ShaderCompiler& compiler,
                   const DiskPipelineCache& cache, const char* file, uint32_t pushBytes,
                   const std::string& name);
    // `push`: `pushBytes` of the shader's push block.
    void record(VkCommandBuffer cmd, const SceneTargets& targets, const void* push) const;

  private:
    // Around the dispatch: the single-sample images to GENERAL, after the pass's writes (1x,
    // where the pass drew into them) or discarding them (MSAA, overwritten whole); then to
    // TRANSFER_SRC_OPTIMAL for the copies, blits and passes that read them.
    void transition(VkCommandBuffer cmd, const SceneTargets& targets, bool before) const;

    vk::Device& device_;
    std::string name_;
    uint32_t pushBytes_;
    vk::Handle<VkDescriptorSetLayout> images_; // depth, sample IDs, sample colours, IDs, colour
    ComputePipeline pipelines_[2];             // 1x, multisampled
};

// One per renderer, with both its pipelines made up front.
class Resolver {
  public:
    Resolver(vk::Device& device, const vk::ShaderCompiler& compiler, const DiskPipelineCache& cache)
        : pass_(device, compiler, cache, "resolve.comp", sizeof(gpu::ResolvePush),
                "compute resolve") {}

    // After the compute path's scene pass (whole, or its second half) into `targets`.
    // `flags`: gpu::RESOLVE_KEEP_COLOR when the pass cleared colour (X-ray), RESOLVE_NO_IDS
    // when its pipeline wrote no IDs (the floors).
    void record(VkCommandBuffer cmd, const SceneTargets& targets, uint32_t flags) const;

  private:
    ComputeEndPass pass_;
};

} // namespace render
