// swapchain.cpp - surface queries, swapchain (re)creation, acquire and present.
#include "vk/swapchain.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "vk/check.h"

namespace vk {

void checkPresentSupport(const DeviceInfo& info, VkSurfaceKHR surface) {
    if (!hasDeviceExtension(info.handle, VK_KHR_SWAPCHAIN_EXTENSION_NAME))
        throw Error(info.name +
                    " cannot show a window: it lacks VK_KHR_swapchain (use --headless)");
    // idview renders and presents on one queue, so that queue must be able to present.
    VkBool32 supported = VK_FALSE;
    check(vkGetPhysicalDeviceSurfaceSupportKHR(info.handle, info.graphicsQueueFamily, surface,
                                               &supported),
          "vkGetPhysicalDeviceSurfaceSupportKHR");
    if (!supported)
        throw Error(info.name + " cannot present to this window from its graphics queue (try "
                                "another --device, or --headless)");
}

Swapchain::Swapchain(Device& device, VkSurfaceKHR surface) : device_(device), surface_(surface) {
    const auto formats = enumerate<VkSurfaceFormatKHR>(
        "vkGetPhysicalDeviceSurfaceFormatsKHR", [&](uint32_t* n, VkSurfaceFormatKHR* v) {
            return vkGetPhysicalDeviceSurfaceFormatsKHR(device.physical(), surface, n, v);
        });
    if (formats.empty()) throw Error("the window surface offers no image formats");
    format_ = formats.front(); // whatever it is, rather than no window at all
    for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM}) {
        auto found = std::find_if(formats.begin(), formats.end(), [&](const auto& f) {
            return f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
        });
        if (found != formats.end()) {
            format_ = *found;
            break;
        }
    }
    // The scene image reaches the swapchain by a blit, which the format must support.
    VkFormatProperties props;
    vkGetPhysicalDeviceFormatProperties(device.physical(), format_.format, &props);
    if (!(props.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT))
        throw Error("the window's image format cannot be blitted to on " + device.info().name);
}

Swapchain::~Swapchain() {
    // Teardown: the presentation engine may still read the images.
    vkDeviceWaitIdle(device_.handle());
}

bool Swapchain::recreate(VkExtent2D size, bool vsync) {
    VkPhysicalDevice physical = device_.physical();
    // Vulkan 1.2 gives no fence for a present, so nothing says when the old images and their
    // semaphores are free but an idle queue. Resizing and vsync changes drain it once; no
    // technique, scene or MSAA change comes here.
    check(vkQueueWaitIdle(device_.queue()), "vkQueueWaitIdle (swapchain)");

    VkSurfaceCapabilitiesKHR caps;
    check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface_, &caps),
          "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    VkExtent2D extent = caps.currentExtent;
    if (extent.width == UINT32_MAX) // the surface takes the size of the swapchain
        extent = {std::clamp(size.width, caps.minImageExtent.width, caps.maxImageExtent.width),
                  std::clamp(size.height, caps.minImageExtent.height, caps.maxImageExtent.height)};
    if (extent.width == 0 || extent.height == 0) return false; // minimised: no images possible
    extent_ = extent;

    const auto modes = enumerate<VkPresentModeKHR>(
        "vkGetPhysicalDeviceSurfacePresentModesKHR", [&](uint32_t* n, VkPresentModeKHR* v) {
            return vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface_, n, v);
        });
    presentMode_ = VK_PRESENT_MODE_FIFO_KHR; // always offered
    if (!vsync)
        for (VkPresentModeKHR mode : {VK_PRESENT_MODE_IMMEDIATE_KHR, VK_PRESENT_MODE_MAILBOX_KHR})
            if (std::find(modes.begin(), modes.end(), mode) != modes.end()) {
                presentMode_ = mode;
                break;
            }

    // One image more than the minimum, so the CPU need not wait for the display to let go.
    uint32_t imageCount = caps.minImageCount + 1;
    if (caps.maxImageCount > 0) imageCount = std::min(imageCount, caps.maxImageCount);
    const VkImageUsageFlags needed =
        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if ((caps.supportedUsageFlags & needed) != needed)
        throw Error("the window's images cannot be rendered and blitted to");
    copyable_ = caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    VkCompositeAlphaFlagBitsKHR alpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    if (!(caps.supportedCompositeAlpha & alpha))
        for (uint32_t bit = 1; bit <= VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR; bit <<= 1)
            if (caps.supportedCompositeAlpha & bit) {
                alpha = static_cast<VkCompositeAlphaFlagBitsKHR>(bit);
                break;
            }

    auto info = vk::init<VkSwapchainCreateInfoKHR>(VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR);
    info.surface = surface_;
    info.minImageCount = imageCount;
    info.imageFormat = format_.format;
    info.imageColorSpace = format_.colorSpace;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = needed | (copyable_ ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0);
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = alpha;
    info.presentMode = presentMode_;
    info.clipped = VK_TRUE;
    info.oldSwapchain = swapchain_.get(); // lets the driver hand resources over
    // The old swapchain is retired by this call whether it succeeds or not.
    Handle<VkSwapchainKHR> old = std::move(swapchain_);
    images_.clear();
    swapchain_ = make(device_, vkCreateSwapchainKHR, info, "window swapchain");
    old.reset();
    createImages();
    return true;
}

void Swapchain::createImages() {
    const auto handles =
        enumerate<VkImage>("vkGetSwapchainImagesKHR", [&](uint32_t* n, VkImage* v) {
            return vkGetSwapchainImagesKHR(device_.handle(), swapchain_.get(), n, v);
        });
    for (uint32_t i = 0; i < handles.size(); ++i) {
        SwapchainImage& image = images_.emplace_back();
        image.image = handles[i];
        const std::string suffix = " (swapchain image " + std::to_string(i) + ")";
        device_.name(VK_OBJECT_TYPE_IMAGE, image.image, "window image" + suffix);
        auto view = vk::init<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
        view.image = image.image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = format_.format;
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        image.view = make(device_, vkCreateImageView, view, "window view" + suffix);
        image.renderFinished =
            make(device_, vkCreateSemaphore,
                 vk::init<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO),
                 "render finished" + suffix);
    }
}

Swapchain::Status Swapchain::acquire(VkSemaphore acquired, uint32_t& imageIndex) {
    const VkResult result = vkAcquireNextImageKHR(device_.handle(), swapchain_.get(), UINT64_MAX,
                                                  acquired, VK_NULL_HANDLE, &imageIndex);
    if (result == VK_ERROR_OUT_OF_DATE_KHR) return Status::OutOfDate;
    if (result == VK_SUBOPTIMAL_KHR) return Status::Suboptimal; // acquired: use it, then recreate
    check(result, "vkAcquireNextImageKHR");
    return Status::Ok;
}

Swapchain::Status Swapchain::present(uint32_t imageIndex) {
    auto info = vk::init<VkPresentInfoKHR>(VK_STRUCTURE_TYPE_PRESENT_INFO_KHR);
    info.waitSemaphoreCount = 1;
    const VkSemaphore finished = images_[imageIndex].renderFinished.get();
    const VkSwapchainKHR swapchain = swapchain_.get();
    info.pWaitSemaphores = &finished;
    info.swapchainCount = 1;
    info.pSwapchains = &swapchain;
    info.pImageIndices = &imageIndex;
    const VkResult result = vkQueuePresentKHR(device_.queue(), &info);
    if (result == VK_ERROR_OUT_OF_DATE_KHR) return Status::OutOfDate;
    if (result == VK_SUBOPTIMAL_KHR) return Status::Suboptimal;
    check(result, "vkQueuePresentKHR");
    return Status::Ok;
}

} // namespace vk
