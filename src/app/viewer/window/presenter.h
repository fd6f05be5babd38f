// presenter.h - what shows a frame in the window: the swapchain (remade on resize, when the
// driver says it is out of date or suboptimal, and when vsync changes), one acquire semaphore
// per frame slot, the window's picture (the scene image blitted in, the ImGui panel over it)
// copied onto the acquired image, present, and the copy of the picture for screenshots.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/viewer/window/blit.h"
#include "app/viewer/window/imgui_layer.h"
#include "app/viewer/window/window.h"
#include "render/frame_slots.h"
#include "vk/swapchain.h"

namespace app {

class Presenter {
  public:
    // Throws vk::Error when the window has no area to render to.
    Presenter(Window& window, const vk::Instance& instance, vk::Device& device,
              VkSurfaceKHR surface);

    // Remakes the swapchain if the window's size or `vsync` changed or the last acquire or
    // present asked for it. False while the window has no area (minimised).
    bool ready(bool vsync);
    // Starts the panel's ImGui frame; the cursor comes from the viewer's input.
    void beginPanel(std::optional<glm::vec2> cursor) { panel_->newFrame(cursor); }

    struct Image {
        uint32_t index = 0;
        VkSemaphore acquired = VK_NULL_HANDLE; // the slot's, signalled by the acquire
    };
    // The next swapchain image for frame `frameNumber` (its slot's semaphore is free: the
    // slot's fence has signalled). nullopt when the swapchain is out of date; the next
    // ready() remakes it.
    std::optional<Image> acquire(uint64_t frameNumber);
    // After the composition: the scene's colour into the window's picture, the panel over
    // it, the picture onto the image, and with `capture` a copy of it for capturedRgba().
    // `sceneChanged`: the scene image changed only there since the last frame (a step of
    // the blink); when the panel draws as it did and does not reach there, only that part
    // of the picture is made again and the panel is left as drawn.
    void record(VkCommandBuffer cmd, const Image& image, const vk::Image& scene,
                const std::optional<VkRect2D>& sceneChanged, bool capture);
    // Submits the slot (waiting for the acquire at the blit) and presents the image.
    void present(render::FrameSlots& slots, render::FrameSlot& slot, const Image& image);

    // The last capture, once its frame's fence has signalled: RGBA8, top row first.
    std::vector<uint8_t> capturedRgba() const;
    VkExtent2D capturedExtent() const { return capture_ ? capture_->extent() : VkExtent2D{}; }
    // Frames that kept the panel as drawn (see record).
    uint64_t keptPanels() const { return keptPanels_; }
    VkExtent2D extent() const { return swapchain_.extent(); }
    // "on", "off", or "off (FIFO only)" where the surface offers nothing but FIFO.
    std::string vsyncState() const;
    // What the swapchain was made with (ready()'s last `vsync`).
    bool vsync() const { return vsync_; }

  private:
    void makePicture(); // of the swapchain's size and format

    Window& window_;
    vk::Device& device_;
    vk::Swapchain swapchain_;
    std::array<vk::Handle<VkSemaphore>, render::FrameSlots::count> acquired_;
    // What the window shows, kept from frame to frame (the swapchain's images are not):
    // the scene blitted in and the panel drawn over it, copied to each acquired image.
    vk::Image picture_;
    std::optional<uint64_t> drawnPanel_; // ImGuiLayer::Drawn::hash of the panel it holds
    VkImage shownScene_ = VK_NULL_HANDLE;
    uint64_t keptPanels_ = 0;
    std::unique_ptr<ImGuiLayer> panel_;
    std::unique_ptr<WindowCapture> capture_;
    bool vsync_ = true;
    bool stale_ = false; // the driver asked for a new swapchain
};

} // namespace app
