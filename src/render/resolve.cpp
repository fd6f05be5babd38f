// resolve.cpp - recording the compute clear path's resolve (see resolve.h).
#include "render/resolve.h"

#include <array>

#include "vk/barrier.h"
#include "vk/check.h"
#include "vk/debug.h"

namespace render {

ComputeEndPass::ComputeEndPass(vk::Device& device, const vk::ShaderCompiler& compiler,
                               const DiskPipelineCache& cache, const char* file, uint32_t pushBytes,
                               const std::string& name)
    : device_(device), name_(name), pushBytes_(pushBytes) {
    const VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    images_ = pushDescriptorLayout(device, {sampled, sampled, sampled, storage, storage},
                                   name + " images");
    for (const bool msaa : {false, true})
        pipelines_[msaa] = createComputePipeline(device, compiler, cache, file, pushBytes,
                                                 images_.get(), name + (msaa ? " (MSAA)" : ""),
                                                 {{"IDV_RESOLVE_MSAA", msaa ? "1" : "0"}});
}

void ComputeEndPass::transition(VkCommandBuffer cmd, const SceneTargets& targets,
                                bool before) const {
    const bool msaa = targets.pass().samples() != VK_SAMPLE_COUNT_1_BIT;
    std::array<VkImageMemoryBarrier, 2> barriers{};
    const std::array<VkImage, 2> images = {targets.ids().handle(), targets.shaded().handle()};
    for (size_t i = 0; i < barriers.size(); ++i)
        // Before, 1x: the pass drew into these images and left them in GENERAL; with MSAA
        // they are overwritten whole once the last frame's readers are done.
        barriers[i] =
            before
                ? vk::colorImageBarrier(images[i], msaa ? 0 : VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                                        VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
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

void ComputeEndPass::record(VkCommandBuffer cmd, const SceneTargets& targets,
                            const void* push) const {
    vk::CmdLabel label(device_.debug(), cmd, name_.c_str());
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
    if (msaa) { // at 1x the pass drew into the single-sample images themselves
        images.push_back({1, sampled, {VK_NULL_HANDLE, targets.multisampledIds().view(), read}});
        images.push_back({2, sampled, {VK_NULL_HANDLE, targets.multisampledColor().view(), read}});
    }
    const ComputePipeline& pass = pipelines_[msaa];
    bindWithImages(device_, cmd, pass, images);
    vkCmdPushConstants(cmd, pass.layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes_, push);
    const uint32_t tile = gpu::ID_PASS_TILE;
    const VkExtent2D extent = targets.extent();
    vkCmdDispatch(cmd, (extent.width + tile - 1) / tile, (extent.height + tile - 1) / tile, 1);
    transition(cmd, targets, false);
}

void Resolver::record(VkCommandBuffer cmd, const SceneTargets& targets, uint32_t flags) const {
    gpu::ResolvePush push{};
    push.background = backgroundColor;
    push.extent = {targets.extent().width, targets.extent().height};
    push.samples = uint32_t(targets.pass().samples());
    push.flags = flags;
    pass_.record(cmd, targets, &push);
}

} // namespace render
