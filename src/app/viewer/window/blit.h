// blit.h - the commands between the composition and present: the scene's colour into the
// window's kept picture, the picture onto the swapchain image, and the copy of the picture
// for screenshots.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "vk/resources.h"

namespace app {

// The window's picture is kept between frames in an image of the swapchain's format (see
// Presenter): the scene's colour blitted in, the panel drawn over it, then copied onto the
// acquired swapchain image, whose contents are not kept from one present to the next.

// Blits the scene colour image (TRANSFER_SRC_OPTIMAL after the composition, RGBA8 already
// gamma-encoded) into the picture. Whole: the picture's old contents go, it is scaled if the
// window changed size since the scene targets were made, and it is left in
// COLOR_ATTACHMENT_OPTIMAL for the panel pass. `only` a rectangle (the same size images):
// the rest of the picture stays as the last frame left it (TRANSFER_SRC_OPTIMAL), and so
// does the layout, unless `drawnOver` (the overlay is drawn again there: left in
// COLOR_ATTACHMENT_OPTIMAL).
void recordSceneToPicture(VkCommandBuffer cmd, const vk::Image& scene, const vk::Image& picture,
                          const std::optional<VkRect2D>& only, bool drawnOver = false);

// Copies the picture (TRANSFER_SRC_OPTIMAL) onto the acquired swapchain image, left in
// PRESENT_SRC_KHR. The frame's submit must wait for the acquire at the transfer stage.
void recordPictureToWindow(VkCommandBuffer cmd, const vk::Image& picture, VkImage window);

// A host-visible copy of the window's picture as presented (panel included).
class WindowCapture {
  public:
    WindowCapture(vk::Device& device, VkExtent2D extent);

    VkExtent2D extent() const { return extent_; }
    // Once the picture is made (TRANSFER_SRC_OPTIMAL).
    void record(VkCommandBuffer cmd, const vk::Image& picture) const;
    // Once the frame's fence has signalled: RGBA8, top row first, opaque.
    std::vector<uint8_t> rgba(VkFormat format) const;

  private:
    VkExtent2D extent_;
    vk::Buffer buffer_;
};

} // namespace app
