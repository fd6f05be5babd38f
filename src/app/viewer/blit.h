// blit.h - the commands between the scene pass and present: the scene's colour image
// onto the swapchain image, and the copy of the finished window image for screenshots.
#pragma once

#include <cstdint>
#include <vector>

#include "vk/resources.h"

namespace app {

// Blits the scene colour image (TRANSFER_SRC_OPTIMAL after the scene pass, RGBA8 already
// gamma-encoded) onto the acquired swapchain image, whose old contents are discarded, and
// leaves it in COLOR_ATTACHMENT_OPTIMAL for the panel pass. The frame's submit must wait for
// the acquire semaphore at the transfer stage.
void recordSceneToWindow(VkCommandBuffer cmd, const vk::Image& scene, VkImage window,
                         VkExtent2D windowExtent);

// A host-visible copy of the window image as presented (panel included).
class WindowCapture {
  public:
    WindowCapture(vk::Device& device, VkExtent2D extent);

    VkExtent2D extent() const { return extent_; }
    // After the panel pass: the image goes from PRESENT_SRC_KHR to the buffer and back.
    void record(VkCommandBuffer cmd, VkImage window) const;
    // Once the frame's fence has signalled: RGBA8, top row first, opaque.
    std::vector<uint8_t> rgba(VkFormat format) const;

  private:
    VkExtent2D extent_;
    vk::Buffer buffer_;
};

} // namespace app
