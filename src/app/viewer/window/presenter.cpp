// presenter.cpp - swapchain upkeep, acquire, the window's picture, present and captures.
#include "app/viewer/window/presenter.h"

#include <string>

#include "vk/check.h"

namespace app {
namespace {

bool overlap(const VkRect2D& a, const VkRect2D& b) {
    auto apart = [](int32_t from, uint32_t size, int32_t otherFrom) {
        return int64_t(from) + size <= otherFrom;
    };
    return !apart(a.offset.x, a.extent.width, b.offset.x) &&
           !apart(b.offset.x, b.extent.width, a.offset.x) &&
           !apart(a.offset.y, a.extent.height, b.offset.y) &&
           !apart(b.offset.y, b.extent.height, a.offset.y);
}

} // namespace

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
    makePicture();
    panel_ = std::make_unique<ImGuiLayer>(window.handle(), instance, device, picture_);
}

bool Presenter::ready(bool vsync) {
    const VkExtent2D size = window_.framebufferSize();
    if (size.width == 0 || size.height == 0) return false;
    const VkExtent2D now = swapchain_.extent();
    if (!stale_ && vsync == vsync_ && now.width == size.width && now.height == size.height)
        return true;
    if (!swapchain_.recreate(size, vsync)) return false; // drains the queue first
    makePicture();
    panel_->createFramebuffer(picture_);
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

void Presenter::makePicture() {
    picture_ = vk::Image(device_, swapchain_.extent(), swapchain_.format(),
                         VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                             VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                         VK_IMAGE_ASPECT_COLOR_BIT, "window picture");
    drawnPanel_.reset();
}

void Presenter::record(VkCommandBuffer cmd, const Image& image, const vk::Image& scene,
                       const std::optional<VkRect2D>& sceneChanged, bool capture) {
    const VkExtent2D size = picture_.extent();
    // The panel's draw data is hashed only in frames that could keep it (a frame that drew
    // the scene anew, every frame with vsync off, cannot): it is the next such frame that
    // compares with it.
    std::optional<ImGuiLayer::Drawn> panel;
    if (sceneChanged) panel = ImGuiLayer::drawn();
    // The picture keeps the panel when the panel drew the same as when it was drawn in, and
    // the scene changed only where the panel's windows do not reach. The overlay over the
    // scene (a hovered edge lies in the hovered part's tiles) is drawn again there alone.
    const bool keep = panel && drawnPanel_ == panel->hash && shownScene_ == scene.handle() &&
                      scene.extent().width == size.width && scene.extent().height == size.height &&
                      !(panel->bounds && overlap(*panel->bounds, *sceneChanged));
    shownScene_ = scene.handle();
    if (keep) {
        const bool overlay = panel->overlay && overlap(*panel->overlay, *sceneChanged) &&
                             sceneChanged->extent.width > 0 && sceneChanged->extent.height > 0;
        recordSceneToPicture(cmd, scene, picture_, sceneChanged, overlay);
        if (overlay) panel_->recordOverlay(cmd, *sceneChanged);
        ++keptPanels_;
    } else {
        recordSceneToPicture(cmd, scene, picture_, std::nullopt);
        panel_->record(cmd);
        drawnPanel_ = panel ? std::optional(panel->hash) : std::nullopt;
    }
    recordPictureToWindow(cmd, picture_, swapchain_.images()[image.index].image);
    if (!capture) return;
    // The capture buffer is only reused after the frame that filled it was read back.
    if (!capture_ || capture_->extent().width != size.width ||
        capture_->extent().height != size.height)
        capture_ = std::make_unique<WindowCapture>(device_, size);
    capture_->record(cmd, picture_);
}

void Presenter::present(render::FrameSlots& slots, render::FrameSlot& slot, const Image& image) {
    const VkSemaphore finished = swapchain_.images()[image.index].renderFinished.get();
    slots.submit(slot, {image.acquired}, {VK_PIPELINE_STAGE_TRANSFER_BIT}, {finished});
    if (swapchain_.present(image.index) != vk::Swapchain::Status::Ok) stale_ = true;
}

std::vector<uint8_t> Presenter::capturedRgba() const {
    return capture_ ? capture_->rgba(picture_.format()) : std::vector<uint8_t>{};
}

std::string Presenter::vsyncState() const {
    if (vsync_) return "on";
    return swapchain_.presentMode() == VK_PRESENT_MODE_FIFO_KHR ? "off (FIFO only)" : "off";
}

} // namespace app
