// compute_raster.h - the compute rasterizer of the visbuffer-compute technique
// (shared_visibility.h): the task shader lists, per pass, the meshlets whose triangles project
// small instead of launching the mesh shader for them, and after the pass raster.comp
// rasterizes them by Vulkan's rules (shaders/raster.glsl) into a 64-bit sample per
// framebuffer sample, atomicMax of (depth, inverted payload). The hardware path keeps its
// depth and payloads in the pass's attachments; the depth pyramid, the shading pass and the
// hover read both and keep the nearer, so the two paths make one visibility buffer.
#pragma once

#include <memory>

#include "render/pipeline.h"
#include "render/targets.h"

namespace render {

// The bytes of the lists for `capacity` meshlets a pass: a dispatch header per pass, then
// the entries (gpu::RasterEntry) of the early and the late pass.
VkDeviceSize rasterListBytes(uint32_t capacity);

class ComputeRaster {
  public:
    ComputeRaster(vk::Device& device, const vk::ShaderCompiler& compiler,
                  const DiskPipelineCache& cache);

    // The device's subpixel grid is one the compute pass can follow (raster.glsl's edge
    // functions assume at most 8 bits), at `samples` per pixel (1 or 4: the standard
    // locations it knows).
    bool runsAt(uint32_t samples) const {
        return subpixelBits_ <= 8 && (samples == 1 || samples == 4);
    }

    // Before the scene pass: zeroes `samples` (the frame's 64-bit samples) and the lists'
    // dispatch headers, after the last frame's readers are done.
    void recordClear(VkCommandBuffer cmd, const vk::Buffer& samples, const vk::Buffer& lists) const;
    // After a pass's hardware draws: the meshlets its task shader listed in `list` (0: the
    // early or only pass, 1: the late one), read by later compute passes.
    void recordPass(VkCommandBuffer cmd, VkDeviceAddress frame, const vk::Buffer& lists,
                    uint32_t list, uint32_t samples) const;

  private:
    vk::Device& device_;
    uint32_t subpixelBits_ = 8;
    ComputePipeline pipeline_;
};

// The frame's 64-bit samples for `targets`: one per framebuffer sample.
VkDeviceSize rasterSampleBytes(const SceneTargets& targets);

} // namespace render
