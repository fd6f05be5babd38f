// visibility.h - the visibility buffer's end of the scene pass (the visbuffer technique,
// shared_visibility.h): the pass, always on the compute clear path, wrote depth and per
// sample the payload of the triangle covering it, and no colour; this pass finds each
// sample's unique part through the part per triangle, shades it as the other techniques'
// fragment shaders do (material, part colour, headlight, section caps, X-ray's layers over
// it), resolves MSAA and reads the pick. It leaves the single-sample shaded colour and IDs as
// render/resolve.h does, so everything that reads the ID image afterwards is the same for
// every technique.
#pragma once

#include "render/resolve.h"

namespace render {

class VisibilityShading {
  public:
    VisibilityShading(vk::Device& device, const vk::ShaderCompiler& compiler,
                      const DiskPipelineCache& cache)
        : pass_(device, compiler, cache, "visibility.comp", sizeof(gpu::VisibilityPush),
                "visibility shading") {}

    // After the scene pass (whole, or its second half) into `targets`; `push` holds the
    // frame's and the draw list's addresses and the VIS_* flags, the rest is filled here.
    void record(VkCommandBuffer cmd, const SceneTargets& targets, gpu::VisibilityPush push) const {
        push.background = backgroundColor;
        push.extent = {targets.extent().width, targets.extent().height};
        push.samples = uint32_t(targets.pass().samples());
        pass_.record(cmd, targets, &push);
    }

  private:
    ComputeEndPass pass_;
};

} // namespace render
