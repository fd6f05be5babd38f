// barrier.h - a global memory barrier in one call, and the image barrier of a single-sample
// colour image: what passes record between their steps.
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

// A layout transition and memory dependency of a colour image of one level and layer.
inline VkImageMemoryBarrier colorImageBarrier(VkImage image, VkAccessFlags srcAccess,
                                              VkAccessFlags dstAccess, VkImageLayout oldLayout,
                                              VkImageLayout newLayout) {
    auto b = init<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    b.oldLayout = oldLayout;
    b.newLayout = newLayout;
    return b;
}

} // namespace vk
