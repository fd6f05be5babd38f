// census.cpp - recording the visibility census's counting and folding (see census.h).
#include "render/census.h"

#include <cstring>

#include "vk/barrier.h"
#include "vk/check.h"
#include "vk/debug.h"

namespace render {
namespace {

constexpr uint32_t kFoldGroup = gpu::ID_PASS_TILE * gpu::ID_PASS_TILE;
constexpr uint32_t kMaxGroupsX = 65535; // the smallest maxComputeWorkGroupCount[0] allowed

uint32_t tiles(uint32_t pixels) {
    return (pixels + gpu::ID_PASS_TILE - 1) / gpu::ID_PASS_TILE;
}

VkDeviceSize viewBytes(uint32_t parts) {
    return VkDeviceSize(std::max(parts, 1u)) * sizeof(uint32_t);
}

VkDeviceSize totalsBytes(uint32_t parts) {
    return VkDeviceSize(std::max(parts, 1u)) * sizeof(gpu::CensusTotals);
}

} // namespace

CensusCounters::CensusCounters(vk::Device& device, uint32_t parts)
    : parts_(parts), view_(device, viewBytes(parts),
                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                               VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                           VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, "census view counters"),
      totals_(device, totalsBytes(parts),
              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                  VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
              VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, "census totals"),
      readback_(vk::hostBuffer(device, totalsBytes(parts), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                               "census totals readback")) {}

std::vector<gpu::CensusTotals> CensusCounters::totals() const {
    std::vector<gpu::CensusTotals> totals(parts_);
    std::memcpy(totals.data(), readback_.mapped(), totals.size() * sizeof(gpu::CensusTotals));
    return totals;
}

CensusPass::CensusPass(vk::Device& device, const vk::ShaderCompiler& compiler,
                       const DiskPipelineCache& cache)
    : device_(device) {
    images_ = pushDescriptorLayout(device, {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, "census IDs");
    pass_ = createComputePipeline(device, compiler, cache, "census.comp", sizeof(gpu::CensusPush),
                                  images_.get(), "visibility census");
}

void CensusPass::reset(VkCommandBuffer cmd, const CensusCounters& counters) const {
    vkCmdFillBuffer(cmd, counters.view_.handle(), 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cmd, counters.totals_.handle(), 0, VK_WHOLE_SIZE, 0);
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}

void CensusPass::dispatch(VkCommandBuffer cmd, const SceneTargets& targets,
                          const CensusCounters& counters) const {
    gpu::CensusPush push{};
    push.viewAddress = counters.view_.address();
    push.totalsAddress = counters.totals_.address();
    push.extent = {targets.extent().width, targets.extent().height};
    push.parts = counters.parts_;
    push.step = gpu::CENSUS_COUNT;
    bindWithImage(device_, cmd, pass_, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                  {VK_NULL_HANDLE, targets.ids().view(), VK_IMAGE_LAYOUT_GENERAL});
    const VkShaderStageFlags stage = VK_SHADER_STAGE_COMPUTE_BIT;
    vkCmdPushConstants(cmd, pass_.layout.get(), stage, 0, sizeof push, &push);
    vkCmdDispatch(cmd, tiles(push.extent.x), tiles(push.extent.y), 1);
    // The fold reads what every counting invocation added.
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    push.step = gpu::CENSUS_FOLD;
    vkCmdPushConstants(cmd, pass_.layout.get(), stage, 0, sizeof push, &push);
    const uint32_t groups = (std::max(push.parts, 1u) + kFoldGroup - 1) / kFoldGroup;
    const uint32_t x = std::min(groups, kMaxGroupsX);
    vkCmdDispatch(cmd, x, (groups + x - 1) / x, 1);
}

void CensusPass::copyOut(VkCommandBuffer cmd, const CensusCounters& counters) const {
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                      VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    const VkBufferCopy copy{0, 0, counters.totals_.size()};
    vkCmdCopyBuffer(cmd, counters.totals_.handle(), counters.readback_.handle(), 1, &copy);
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
}

void CensusPass::record(VkCommandBuffer cmd, const SceneTargets& targets,
                        const CensusCounters& counters, bool first, bool last) const {
    vk::CmdLabel label(device_.debug(), cmd, "visibility census");
    if (first) reset(cmd, counters);
    // From the layout the scene pass and the ID passes leave (after their writes and
    // copies), and back before whatever comes next writes or copies the image.
    const VkImage ids = targets.ids().handle();
    VkImageMemoryBarrier barrier =
        vk::colorImageBarrier(ids, VK_ACCESS_MEMORY_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT,
                              VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr, 0, nullptr, 1,
                         &barrier);
    dispatch(cmd, targets, counters);
    barrier = vk::colorImageBarrier(ids, 0, 0, VK_IMAGE_LAYOUT_GENERAL,
                                    VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0, nullptr, 1,
                         &barrier);
    if (last) copyOut(cmd, counters);
}

} // namespace render
