// swapchain.cpp - surface queries, swapchain (re)creation, acquire and present.
#include "vk/swapchain.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "vk/check.h"

namespace vk {

void checkPresentSupport(const DeviceInfo& info, VkSurfaceKHR surface) {
    uint32_t count = 0;
    check(vkEnumerateDeviceExtensionProperties(info.handle, nullptr, &count, nullptr),
          "vkEnumerateDeviceExtensionProperties");
    std::vector<VkExtensionProperties> extensions(count);
    check(vkEnumerateDeviceExtensionProperties(info.handle, nullptr, &count, extensions.data()),
          "vkEnumerateDeviceExtensionProperties");
    const bool swapchain = std::any_of(extensions.begin(), extensions.end(), [](const auto& e) {
        return std::strcmp(e.extensionName, VK_KHR_SWAPCHAIN_EXTENSION_NAME) == 0;
    });
    if (!swapchain)
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
    uint32_t count = 0;
    check(vkGetPhysicalDeviceSurfaceFormatsKHR(device.physical(), surface, &count, nullptr),
          "vkGetPhysicalDeviceSurfaceFormatsKHR");
    std::vector<VkSurfaceFormatKHR> formats(count);
    check(vkGetPhysicalDeviceSurfaceFormatsKHR(device.physical(), surface, &count, formats.data()),
          "vkGetPhysicalDeviceSurfaceFormatsKHR");
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
    // Teardown: a failed wait cannot be acted on, and the images must be unused.
    vkDeviceWaitIdle(device_.handle());
    releaseImages();
    if (swapchain_) vkDestroySwapchainKHR(device_.handle(), swapchain_, nullptr);
}

void Swapchain::releaseImages() {
    for (SwapchainImage& image : images_) {
        if (image.renderFinished)
            vkDestroySemaphore(device_.handle(), image.renderFinished, nullptr);
        if (image.view) vkDestroyImageView(device_.handle(), image.view, nullptr);
    }
    images_.clear();
}

bool Swapchain::recreate(VkExtent2D size, bool vsync) {
    VkDevice dev = device_.handle();
    VkPhysicalDevice physical = device_.physical();
    check(vkDeviceWaitIdle(dev), "vkDeviceWaitIdle (swapchain)");

    VkSurfaceCapabilitiesKHR caps;
    check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface_, &caps),
          "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    VkExtent2D extent = caps.currentExtent;
    if (extent.width == UINT32_MAX) // the surface takes the size of the swapchain
        extent = {std::clamp(size.width, caps.minImageExtent.width, caps.maxImageExtent.width),
                  std::clamp(size.height, caps.minImageExtent.height, caps.maxImageExtent.height)};
    if (extent.width == 0 || extent.height == 0) return false; // minimised: no images possible
    extent_ = extent;

    uint32_t count = 0;
    check(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface_, &count, nullptr),
          "vkGetPhysicalDeviceSurfacePresentModesKHR");
    std::vector<VkPresentModeKHR> modes(count);
    check(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface_, &count, modes.data()),
          "vkGetPhysicalDeviceSurfacePresentModesKHR");
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
    info.oldSwapchain = swapchain_; // lets the driver hand resources over
    VkSwapchainKHR created = VK_NULL_HANDLE;
    const VkResult result = vkCreateSwapchainKHR(dev, &info, nullptr, &created);
    releaseImages();
    if (swapchain_) vkDestroySwapchainKHR(dev, swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
    check(result, "vkCreateSwapchainKHR");
    swapchain_ = created;
    device_.name(VK_OBJECT_TYPE_SWAPCHAIN_KHR, swapchain_, "window swapchain");

    check(vkGetSwapchainImagesKHR(dev, swapchain_, &count, nullptr), "vkGetSwapchainImagesKHR");
    std::vector<VkImage> handles(count);
    check(vkGetSwapchainImagesKHR(dev, swapchain_, &count, handles.data()),
          "vkGetSwapchainImagesKHR");
    for (uint32_t i = 0; i < count; ++i) {
        SwapchainImage& image = images_.emplace_back();
        image.image = handles[i];
        const std::string suffix = " (swapchain image " + std::to_string(i) + ")";
        device_.name(VK_OBJECT_TYPE_IMAGE, image.image, "window image" + suffix);
        auto view = vk::init<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
        view.image = image.image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = format_.format;
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        check(vkCreateImageView(dev, &view, nullptr, &image.view), "vkCreateImageView");
        device_.name(VK_OBJECT_TYPE_IMAGE_VIEW, image.view, "window view" + suffix);
        auto semaphore = vk::init<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
        check(vkCreateSemaphore(dev, &semaphore, nullptr, &image.renderFinished),
              "vkCreateSemaphore");
        device_.name(VK_OBJECT_TYPE_SEMAPHORE, image.renderFinished, "render finished" + suffix);
    }
    return true;
}

Swapchain::Status Swapchain::acquire(VkSemaphore acquired, uint32_t& imageIndex) {
    const VkResult result = vkAcquireNextImageKHR(device_.handle(), swapchain_, UINT64_MAX,
                                                  acquired, VK_NULL_HANDLE, &imageIndex);
    if (result == VK_ERROR_OUT_OF_DATE_KHR) return Status::OutOfDate;
    if (result == VK_SUBOPTIMAL_KHR) return Status::Suboptimal; // acquired: use it, then recreate
    check(result, "vkAcquireNextImageKHR");
    return Status::Ok;
}

Swapchain::Status Swapchain::present(uint32_t imageIndex) {
    auto info = vk::init<VkPresentInfoKHR>(VK_STRUCTURE_TYPE_PRESENT_INFO_KHR);
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &images_[imageIndex].renderFinished;
    info.swapchainCount = 1;
    info.pSwapchains = &swapchain_;
    info.pImageIndices = &imageIndex;
    const VkResult result = vkQueuePresentKHR(device_.queue(), &info);
    if (result == VK_ERROR_OUT_OF_DATE_KHR) return Status::OutOfDate;
    if (result == VK_SUBOPTIMAL_KHR) return Status::Suboptimal;
    check(result, "vkQueuePresentKHR");
    return Status::Ok;
}

} // namespace vk
