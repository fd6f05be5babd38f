// barrier.h - a global memory barrier in one call: what passes record between their steps.
#pragma once

#include <vulkan/vulkan.h>

#include "vk/check.h"

namespace vk {

inline void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags srcStages,
                          VkAccessFlags srcAccess, VkPipelineStageFlags dstStages,
                          VkAccessFlags dstAccess) {
    auto barrier = init<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    barrier.srcAccessMask = srcAccess;
    barrier.dstAccessMask = dstAccess;
    vkCmdPipelineBarrier(cmd, srcStages, dstStages, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

} // namespace vk
