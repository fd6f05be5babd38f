// id_passes.cpp - recording the edge and part set passes (see id_passes.h).
#include "render/id_passes.h"

#include <array>

#include "vk/barrier.h"
#include "vk/check.h"
#include "vk/debug.h"

namespace render {
namespace {

uint32_t groups(uint32_t pixels) {
    return (pixels + gpu::ID_PASS_TILE - 1) / gpu::ID_PASS_TILE;
}

} // namespace

IdPasses::IdPasses(vk::Device& device, const vk::ShaderCompiler& compiler,
                   const DiskPipelineCache& cache)
    : device_(device) {
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    images_ = pushDescriptorLayout(device, {storage, storage}, "ID pass images");
    createCompose(compiler, cache);
    partSet_ = createComputePipeline(device, compiler, cache, "part_set.comp",
                                     sizeof(gpu::PartSetPush), images_.get(), "part sets");
}

void IdPasses::createCompose(const vk::ShaderCompiler& compiler, const DiskPipelineCache& cache) {
    // IDs, composed colour, shaded colour, depth.
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    composeImages_ = pushDescriptorLayout(
        device_, {storage, storage, storage, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
        "composition images");
    depthSampler_ = texelFetchSampler(device_, "composition depth sampler");
    for (const bool msaa : {false, true})
        compose_[msaa] = createComputePipeline(device_, compiler, cache, "compose.comp",
                                               sizeof(gpu::ComposePush), composeImages_.get(),
                                               msaa ? "composition (MSAA depth)" : "composition",
                                               {{"IDV_COMPOSE_MSAA", msaa ? "1" : "0"}});
}

void IdPasses::compose(VkCommandBuffer cmd, const SceneTargets& targets, gpu::ComposePush push,
                       const std::optional<HoveredTiles>& tiles) const {
    const ComputePipeline& pass = compose_[targets.pass().samples() != VK_SAMPLE_COUNT_1_BIT];
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    bindWithImages(
        device_, cmd, pass,
        {{0, storage, {VK_NULL_HANDLE, targets.ids().view(), VK_IMAGE_LAYOUT_GENERAL}},
         {1, storage, {VK_NULL_HANDLE, targets.color().view(), VK_IMAGE_LAYOUT_GENERAL}},
         {2, storage, {VK_NULL_HANDLE, targets.shaded().view(), VK_IMAGE_LAYOUT_GENERAL}},
         {3,
          VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
          {depthSampler_.get(), targets.depth().view(),
           VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL}}});
    push.step = tiles ? gpu::COMPOSE_TILES : gpu::COMPOSE_WHOLE;
    push.tileOrigin = tiles ? tiles->first : glm::uvec2(0);
    vkCmdPushConstants(cmd, pass.layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    const glm::uvec2 count =
        tiles ? tiles->count : glm::uvec2(groups(push.extent.x), groups(push.extent.y));
    if (count.x > 0 && count.y > 0) vkCmdDispatch(cmd, count.x, count.y, 1);
}

void IdPasses::bindImages(VkCommandBuffer cmd, const SceneTargets& targets,
                          const ComputePipeline& pass) const {
    const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    bindWithImages(
        device_, cmd, pass,
        {{0, storage, {VK_NULL_HANDLE, targets.ids().view(), VK_IMAGE_LAYOUT_GENERAL}},
         {1, storage, {VK_NULL_HANDLE, targets.color().view(), VK_IMAGE_LAYOUT_GENERAL}}});
}

// To GENERAL: after the pass's writes and its transition to the final layout (which the
// pass's outgoing dependency orders before the transfer stage), or after the last frame's
// passes and copies when no scene pass ran. A whole composition writes every pixel, so the
// composed colour's old contents go; one of the hovered part's tiles keeps the rest. Either
// way the last frame's blit or copy of it must be done first. Back: before the copies and
// blits that read the images, and the next frame's pass that overwrites them.
void IdPasses::transition(VkCommandBuffer cmd, const SceneTargets& targets, Move move) const {
    const bool toGeneral = move != Move::Back;
    std::array<VkImageMemoryBarrier, 3> barriers{};
    const std::array<VkImage, 3> images = {targets.ids().handle(), targets.shaded().handle(),
                                           targets.color().handle()};
    for (uint32_t i = 0; i < barriers.size(); ++i) {
        const bool composed = images[i] == targets.color().handle();
        const bool discard = composed && move == Move::ToGeneral;
        barriers[i] =
            toGeneral
                ? vk::colorImageBarrier(
                      images[i], composed ? 0 : VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
                      discard ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                      VK_IMAGE_LAYOUT_GENERAL)
                : vk::colorImageBarrier(images[i], VK_ACCESS_SHADER_WRITE_BIT,
                                        VK_ACCESS_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_GENERAL,
                                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    }
    const VkPipelineStageFlags src = toGeneral ? VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                     VK_PIPELINE_STAGE_TRANSFER_BIT |
                                                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT
                                               : VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    const VkPipelineStageFlags dst =
        toGeneral ? VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT : VK_PIPELINE_STAGE_TRANSFER_BIT;
    vkCmdPipelineBarrier(cmd, src, dst, 0, 0, nullptr, 0, nullptr,
                         static_cast<uint32_t>(barriers.size()), barriers.data());
}

void IdPasses::dispatchPartSet(VkCommandBuffer cmd, const SceneTargets& targets,
                               const PartSetQuery& query, VkDeviceAddress result, uint32_t words,
                               const ComputePipeline& pass) const {
    const glm::uvec2 last(targets.extent().width - 1, targets.extent().height - 1);
    gpu::PartSetPush push{};
    push.resultAddress = result;
    push.rectMin = glm::min(query.min, last);
    push.rectMax = glm::min(query.max, last);
    push.words = words;
    vkCmdPushConstants(cmd, pass.layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    const glm::uvec2 size = push.rectMax - push.rectMin + 1u;
    vkCmdDispatch(cmd, groups(size.x), groups(size.y), 1);
}

void IdPasses::record(VkCommandBuffer cmd, const SceneTargets& targets,
                      const gpu::ComposePush& composition, const std::optional<HoveredTiles>& tiles,
                      const std::vector<PartSetQuery>& queries, uint32_t words,
                      const vk::Buffer& results, const vk::Buffer& readback) const {
    vk::CmdLabel label(device_.debug(), cmd, "ID image passes");
    const VkDeviceSize stride = sizeof(gpu::PartSetResult) + VkDeviceSize(words) * 4;
    const VkDeviceSize bytes = stride * queries.size();
    if (!queries.empty()) {
        // The slot's buffers: the last frame that used them has finished (its fence).
        vkCmdFillBuffer(cmd, results.handle(), 0, bytes, 0);
        auto cleared = vk::init<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
        cleared.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        cleared.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                             VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &cleared, 0, nullptr, 0,
                             nullptr);
    }
    transition(cmd, targets, tiles ? Move::ToGeneralKeepingColor : Move::ToGeneral);
    compose(cmd, targets, composition, tiles);
    if (!queries.empty()) bindImages(cmd, targets, partSet_);
    for (size_t i = 0; i < queries.size(); ++i)
        dispatchPartSet(cmd, targets, queries[i], results.address() + stride * i, words, partSet_);
    transition(cmd, targets, Move::Back);
    if (queries.empty()) return;
    auto written = vk::init<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    written.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    written.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         0, 1, &written, 0, nullptr, 0, nullptr);
    const VkBufferCopy copy{0, 0, bytes};
    vkCmdCopyBuffer(cmd, results.handle(), readback.handle(), 1, &copy);
    auto toHost = vk::init<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &toHost, 0, nullptr, 0, nullptr);
}

} // namespace render
