// compute_raster.cpp - recording the compute rasterizer's passes (see compute_raster.h).
#include "render/compute_raster.h"

#include <array>

#include "vk/barrier.h"
#include "vk/debug.h"

namespace render {

VkDeviceSize rasterListBytes(uint32_t capacity) {
    return sizeof(uint32_t) * 8 + VkDeviceSize(capacity) * 2 * sizeof(gpu::RasterEntry);
}

VkDeviceSize rasterSampleBytes(const SceneTargets& targets) {
    return VkDeviceSize(targets.extent().width) * targets.extent().height *
           uint32_t(targets.pass().samples()) * sizeof(uint64_t);
}

ComputeRaster::ComputeRaster(vk::Device& device, const vk::ShaderCompiler& compiler,
                             const DiskPipelineCache& cache)
    : device_(device), pipeline_(createComputePipeline(device, compiler, cache, "raster.comp",
                                                       sizeof(gpu::RasterPush), VK_NULL_HANDLE,
                                                       "compute rasterizer")) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(device.physical(), &props);
    subpixelBits_ = props.limits.subPixelPrecisionBits;
}

void ComputeRaster::recordClear(VkCommandBuffer cmd, const vk::Buffer& samples,
                                const vk::Buffer& lists) const {
    // The last frame's raster, shading, pyramid and hover passes and its task shaders are done
    // with both before they are rewritten.
    const VkPipelineStageFlags users = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT |
                                       VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT |
                                       VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT;
    vk::memoryBarrier(cmd, users, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdFillBuffer(cmd, samples.handle(), 0, VK_WHOLE_SIZE, 0);
    // Per pass: no workgroups yet, and y and z of the indirect dispatch 1.
    const std::array<uint32_t, 8> headers = {0, 1, 1, 0, 0, 1, 1, 0};
    vkCmdUpdateBuffer(cmd, lists.handle(), 0, sizeof headers, headers.data());
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, users,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT |
                          VK_ACCESS_INDIRECT_COMMAND_READ_BIT);
}

void ComputeRaster::recordPass(VkCommandBuffer cmd, VkDeviceAddress frame, const vk::Buffer& lists,
                               uint32_t list, uint32_t samples) const {
    vk::CmdLabel label(device_.debug(), cmd, "compute rasterizer");
    // The task shader's lists, counts and dispatch sizes are written.
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                      VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_SHADER_READ_BIT);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.pipeline.get());
    gpu::RasterPush push{};
    push.frameAddress = frame;
    push.list = list;
    push.samples = samples;
    push.subpixelBits = subpixelBits_;
    vkCmdPushConstants(cmd, pipeline_.layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push,
                       &push);
    vkCmdDispatchIndirect(cmd, lists.handle(), VkDeviceSize(list) * 4 * sizeof(uint32_t));
    // The samples are read by the pyramid, the next pass's raster, the shading and the hover.
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}

} // namespace render
