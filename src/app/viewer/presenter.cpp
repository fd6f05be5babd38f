// presenter.cpp - swapchain upkeep, acquire, blit, panel, present and window captures.
#include "app/viewer/presenter.h"

#include <string>

#include "vk/check.h"

namespace app {

Presenter::Presenter(Window& window, const vk::Instance& instance, vk::Device& device,
                     VkSurfaceKHR surface)
    : window_(window), device_(device), swapchain_(device, surface) {
    for (size_t i = 0; i < acquired_.size(); ++i)
        acquired_[i] =
            vk::make(device, vkCreateSemaphore,
                     vk::init<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO),
                     "image acquired (slot " + std::to_string(i) + ")");
    const VkExtent2D size = window.framebufferSize();
    if (size.width == 0 || size.height == 0 || !swapchain_.recreate(size, vsync_))
        throw vk::Error("the window has no area to render to");
    panel_ = std::make_unique<ImGuiLayer>(window.handle(), instance, device, swapchain_);
}

bool Presenter::ready(bool vsync) {
    const VkExtent2D size = window_.framebufferSize();
    if (size.width == 0 || size.height == 0) return false;
    const VkExtent2D now = swapchain_.extent();
    if (!stale_ && vsync == vsync_ && now.width == size.width && now.height == size.height)
        return true;
    if (!swapchain_.recreate(size, vsync)) return false; // drains the queue first
    panel_->createFramebuffers(swapchain_);
    vsync_ = vsync;
    stale_ = false;
    return true;
}

std::optional<Presenter::Image> Presenter::acquire(uint64_t frameNumber) {
    Image image;
    image.acquired = acquired_[frameNumber % acquired_.size()].get();
    const vk::Swapchain::Status status = swapchain_.acquire(image.acquired, image.index);
    if (status == vk::Swapchain::Status::OutOfDate) {
        stale_ = true;
        return std::nullopt;
    }
    if (status == vk::Swapchain::Status::Suboptimal) stale_ = true; // usable; remade after
    return image;
}

void Presenter::record(VkCommandBuffer cmd, const Image& image, const vk::Image& scene,
                       bool capture) {
    const VkImage window = swapchain_.images()[image.index].image;
    recordSceneToWindow(cmd, scene, window, swapchain_.extent());
    panel_->record(cmd, image.index);
    if (!capture) return;
    const VkExtent2D size = swapchain_.extent();
    // The capture buffer is only reused after the frame that filled it was read back.
    if (!capture_ || capture_->extent().width != size.width ||
        capture_->extent().height != size.height)
        capture_ = std::make_unique<WindowCapture>(device_, size);
    capture_->record(cmd, window);
}

void Presenter::present(render::FrameSlots& slots, render::FrameSlot& slot, const Image& image) {
    const VkSemaphore finished = swapchain_.images()[image.index].renderFinished.get();
    slots.submit(slot, {image.acquired}, {VK_PIPELINE_STAGE_TRANSFER_BIT}, {finished});
    if (swapchain_.present(image.index) != vk::Swapchain::Status::Ok) stale_ = true;
}

std::vector<uint8_t> Presenter::capturedRgba() const {
    return capture_ ? capture_->rgba(swapchain_.format()) : std::vector<uint8_t>{};
}

std::string Presenter::vsyncState() const {
    if (vsync_) return "on";
    return swapchain_.presentMode() == VK_PRESENT_MODE_FIFO_KHR ? "off (FIFO only)" : "off";
}

} // namespace app
