// swapchain.h - the window's surface and swapchain: format and present mode choice, images
// with their views, and one "render finished" semaphore per image (a present may still be
// waiting on it until that image is acquired again, so it cannot belong to a frame slot).
// Recreated on resize, VK_ERROR_OUT_OF_DATE_KHR, VK_SUBOPTIMAL_KHR and vsync changes.
#pragma once

#include <cstdint>
#include <vector>
#include <vulkan/vulkan.h>

#include "vk/context.h"
#include "vk/handle.h"

namespace vk {

// Owns a VkSurfaceKHR made by the windowing library; the window must outlive it.
class Surface {
  public:
    Surface(const Instance& instance, VkSurfaceKHR surface)
        : instance_(instance.handle()), surface_(surface) {}
    ~Surface() { vkDestroySurfaceKHR(instance_, surface_, nullptr); }
    Surface(const Surface&) = delete;
    Surface& operator=(const Surface&) = delete;
    VkSurfaceKHR handle() const { return surface_; }

  private:
    VkInstance instance_;
    VkSurfaceKHR surface_;
};

// Throws Error with one line when the device cannot present to `surface` from its graphics
// queue or lacks VK_KHR_swapchain. Call before creating the logical device.
void checkPresentSupport(const DeviceInfo& info, VkSurfaceKHR surface);

struct SwapchainImage {
    VkImage image = VK_NULL_HANDLE; // the swapchain's
    Handle<VkImageView> view;
    Handle<VkSemaphore> renderFinished; // signalled by the frame, waited by present
};

class Swapchain {
  public:
    // Chooses the format (B8G8R8A8_UNORM or R8G8B8A8_UNORM: the scene image is already
    // gamma-encoded, so an SRGB format would encode it twice). Creates nothing yet.
    Swapchain(Device& device, VkSurfaceKHR surface);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // Drains the queue (see swapchain.cpp) and (re)creates the swapchain for a framebuffer of
    // `size` (the surface's own extent wins where it has one). vsync: FIFO; otherwise IMMEDIATE or
    // MAILBOX, whichever the surface offers, FIFO as the fallback. Returns false, changing
    // nothing, while the surface has no area (a minimised window).
    bool recreate(VkExtent2D size, bool vsync);
    bool valid() const { return bool(swapchain_); }

    enum class Status { Ok, Suboptimal, OutOfDate };
    // Acquires the next image, signalling `acquired`. On OutOfDate nothing is signalled and
    // the caller recreates the swapchain.
    Status acquire(VkSemaphore acquired, uint32_t& imageIndex);
    // Presents `imageIndex` once its renderFinished semaphore is signalled.
    Status present(uint32_t imageIndex);

    VkFormat format() const { return format_.format; }
    VkExtent2D extent() const { return extent_; }
    VkPresentModeKHR presentMode() const { return presentMode_; }
    // The images can be copied from (TRANSFER_SRC usage): screenshots of the window.
    bool copyable() const { return copyable_; }
    const std::vector<SwapchainImage>& images() const { return images_; }

  private:
    void createImages();

    Device& device_;
    VkSurfaceKHR surface_;
    VkSurfaceFormatKHR format_{};
    Handle<VkSwapchainKHR> swapchain_;
    VkExtent2D extent_{};
    VkPresentModeKHR presentMode_ = VK_PRESENT_MODE_FIFO_KHR;
    bool copyable_ = false;
    std::vector<SwapchainImage> images_;
};

} // namespace vk
