// resolve.cpp - recording the compute clear path's resolve (see resolve.h).
#include "render/resolve.h"

#include <array>

#include "vk/barrier.h"
#include "vk/check.h"
#include "vk/debug.h"

namespace render {

Resolver::Resolver(vk::Device& device, const vk::ShaderCompiler& compiler,
                   const DiskPipelineCache& cache)
    : device_(device) {
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    images_ = pushDescriptorLayout(device, {sampled, sampled, sampled, storage, storage},
                                   "resolve images");
    for (const bool msaa : {false, true})
        resolve_[msaa] = createComputePipeline(
            device, compiler, cache, "resolve.comp", sizeof(gpu::ResolvePush), images_.get(),
            msaa ? "compute resolve (MSAA)" : "compute background",
            {{"IDV_RESOLVE_MSAA", msaa ? "1" : "0"}});
}

void Resolver::transition(VkCommandBuffer cmd, const SceneTargets& targets, bool before) const {
    const bool msaa = targets.pass().samples() != VK_SAMPLE_COUNT_1_BIT;
    std::array<VkImageMemoryBarrier, 2> barriers{};
    const std::array<VkImage, 2> images = {targets.ids().handle(), targets.shaded().handle()};
    for (size_t i = 0; i < barriers.size(); ++i)
        // Before, 1x: the pass drew into these images and left them in GENERAL; with MSAA
        // they are overwritten whole once the last frame's readers are done.
        barriers[i] =
            before
                ? vk::colorImageBarrier(images[i], msaa ? 0 : VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                                        VK_ACCESS_SHADER_WRITE_BIT,
                                        msaa ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_GENERAL,
                                        VK_IMAGE_LAYOUT_GENERAL)
                : vk::colorImageBarrier(images[i], VK_ACCESS_SHADER_WRITE_BIT,
                                        VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT,
                                        VK_IMAGE_LAYOUT_GENERAL,
                                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    const VkPipelineStageFlags src = before ? VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                  VK_PIPELINE_STAGE_TRANSFER_BIT |
                                                  VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT
                                            : VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    const VkPipelineStageFlags dst =
        before ? VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT
               : VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
    vkCmdPipelineBarrier(cmd, src, dst, 0, 0, nullptr, 0, nullptr,
                         static_cast<uint32_t>(barriers.size()), barriers.data());
}

void Resolver::record(VkCommandBuffer cmd, const SceneTargets& targets, uint32_t flags) const {
    vk::CmdLabel label(device_.debug(), cmd, "compute resolve");
    const bool msaa = targets.pass().samples() != VK_SAMPLE_COUNT_1_BIT;
    transition(cmd, targets, true);
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    const VkImageLayout read = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    std::vector<BoundImage> images = {
        {0,
         sampled,
         {VK_NULL_HANDLE, targets.depth().view(), VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL}},
        {3, storage, {VK_NULL_HANDLE, targets.ids().view(), VK_IMAGE_LAYOUT_GENERAL}},
        {4, storage, {VK_NULL_HANDLE, targets.shaded().view(), VK_IMAGE_LAYOUT_GENERAL}}};
    if (msaa) { // 1x reads depth alone
        images.push_back({1, sampled, {VK_NULL_HANDLE, targets.multisampledIds().view(), read}});
        images.push_back({2, sampled, {VK_NULL_HANDLE, targets.multisampledColor().view(), read}});
    }
    const ComputePipeline& pass = resolve_[msaa];
    bindWithImages(device_, cmd, pass, images);
    gpu::ResolvePush push{};
    push.background = backgroundColor;
    push.extent = {targets.extent().width, targets.extent().height};
    push.samples = uint32_t(targets.pass().samples());
    push.flags = flags;
    vkCmdPushConstants(cmd, pass.layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    const uint32_t tile = gpu::ID_PASS_TILE;
    vkCmdDispatch(cmd, (push.extent.x + tile - 1) / tile, (push.extent.y + tile - 1) / tile, 1);
    transition(cmd, targets, false);
}

} // namespace render
