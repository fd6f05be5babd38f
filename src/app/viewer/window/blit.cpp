// blit.cpp - layout transitions, the blit into the window's picture, its copy onto the
// swapchain image and its readback.
#include "app/viewer/window/blit.h"

#include <algorithm>
#include <cstring>

#include "vk/barrier.h"
#include "vk/check.h"

namespace app {
namespace {

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                  VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                  VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    auto barrier = vk::init<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
    barrier.srcAccessMask = srcAccess;
    barrier.dstAccessMask = dstAccess;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

} // namespace

void recordSceneToPicture(VkCommandBuffer cmd, const vk::Image& scene, const vk::Image& picture,
                          const std::optional<VkRect2D>& only, bool drawnOver) {
    if (only && (only->extent.width == 0 || only->extent.height == 0)) return; // nothing changed
    // After the last frame's copy of the picture to the window (and to a screenshot).
    imageBarrier(cmd, picture.handle(),
                 only ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    // A blit rather than a copy: it swizzles RGBA into a BGRA picture, and scales.
    const VkRect2D from = only.value_or(VkRect2D{{0, 0}, scene.extent()});
    const VkRect2D to = only.value_or(VkRect2D{{0, 0}, picture.extent()});
    auto corners = [](const VkRect2D& r, VkOffset3D(&offsets)[2]) {
        offsets[0] = {r.offset.x, r.offset.y, 0};
        offsets[1] = {r.offset.x + int32_t(r.extent.width), r.offset.y + int32_t(r.extent.height),
                      1};
    };
    VkImageBlit region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    corners(from, region.srcOffsets);
    corners(to, region.dstOffsets);
    vkCmdBlitImage(cmd, scene.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, picture.handle(),
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
    if (only && !drawnOver)
        imageBarrier(cmd, picture.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_READ_BIT);
    else
        imageBarrier(cmd, picture.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
}

void recordPictureToWindow(VkCommandBuffer cmd, const vk::Image& picture, VkImage window) {
    // The source stage is the one the acquire semaphore is waited at, which chains the
    // transition after the presentation engine has let go of the image.
    imageBarrier(cmd, window, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                 VK_ACCESS_TRANSFER_WRITE_BIT);
    VkImageCopy region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.extent = {picture.extent().width, picture.extent().height, 1};
    vkCmdCopyImage(cmd, picture.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, window,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    // For present; the semaphore the submit signals covers the rest.
    imageBarrier(cmd, window, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                 VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
}

WindowCapture::WindowCapture(vk::Device& device, VkExtent2D extent)
    : extent_(extent),
      buffer_(vk::hostBuffer(device, VkDeviceSize(extent.width) * extent.height * 4,
                             VK_BUFFER_USAGE_TRANSFER_DST_BIT, "window screenshot")) {}

void WindowCapture::record(VkCommandBuffer cmd, const vk::Image& picture) const {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent_.width, extent_.height, 1};
    vkCmdCopyImageToBuffer(cmd, picture.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           buffer_.handle(), 1, &region);
    vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
}

std::vector<uint8_t> WindowCapture::rgba(VkFormat format) const {
    std::vector<uint8_t> pixels(size_t(extent_.width) * extent_.height * 4);
    std::memcpy(pixels.data(), buffer_.mapped(), pixels.size());
    const bool bgra = format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_B8G8R8A8_SRGB;
    for (size_t i = 0; i < pixels.size(); i += 4) {
        if (bgra) std::swap(pixels[i], pixels[i + 2]);
        pixels[i + 3] = 255; // the window is opaque whatever alpha the panel left
    }
    return pixels;
}

} // namespace app
