// census.h - the visibility census on the GPU: after each view's scene pass, a compute pass
// counts the pixels of every unique part in the ID image and folds them into per-part totals
// (shaders/shared_census.h). The counters stay on the device across views; the host reads
// the totals once, after the last view, so a census of many views costs their scene passes
// and two small dispatches each, never a read-back per view.
#pragma once

#include <vector>

#include "render/pipeline.h"
#include "render/targets.h"
#include "shared.h"

namespace render {

// The counters of one census over `parts` unique parts, and the host copy of the totals.
class CensusCounters {
  public:
    CensusCounters(vk::Device& device, uint32_t parts);

    uint32_t parts() const { return parts_; }
    // Once the fence of the frame that recorded CensusPass::record(..., last = true) has
    // passed: the totals, one per unique part.
    std::vector<gpu::CensusTotals> totals() const;

  private:
    friend class CensusPass;
    uint32_t parts_;
    vk::Buffer view_, totals_, readback_;
};

class CensusPass {
  public:
    CensusPass(vk::Device& device, const vk::ShaderCompiler& compiler,
               const DiskPipelineCache& cache);

    // After a scene pass into `targets` (its images in TRANSFER_SRC_OPTIMAL as
    // Renderer::record leaves them): counts its resolved ID image (sample 0 of each pixel
    // with MSAA, as the pick and the part sets read it) into
    // `counters`, zeroed first when `first`, and with `last` copies the totals for the host.
    // The ID image goes to GENERAL and back.
    void record(VkCommandBuffer cmd, const SceneTargets& targets, const CensusCounters& counters,
                bool first, bool last) const;

  private:
    void reset(VkCommandBuffer cmd, const CensusCounters& counters) const;
    void dispatch(VkCommandBuffer cmd, const SceneTargets& targets,
                  const CensusCounters& counters) const;
    void copyOut(VkCommandBuffer cmd, const CensusCounters& counters) const;

    vk::Device& device_;
    vk::Handle<VkDescriptorSetLayout> images_; // pushed per view: the IDs
    ComputePipeline pass_;
};

} // namespace render
