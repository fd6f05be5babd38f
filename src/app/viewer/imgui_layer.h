// imgui_layer.h - Dear ImGui (1.86, Debian's libimgui) drawn over the scene on the swapchain
// image: its GLFW and Vulkan backends, the descriptor pool its font texture needs, a render
// pass that keeps what the blit put there (loadOp LOAD) and ends in PRESENT_SRC, and one
// framebuffer per swapchain image.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "vk/context.h"
#include "vk/handle.h"
#include "vk/swapchain.h"

struct GLFWwindow;

namespace app {

class ImGuiLayer {
  public:
    ImGuiLayer(GLFWwindow* window, const vk::Instance& instance, vk::Device& device,
               const vk::Swapchain& swapchain);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    // After Swapchain::recreate: the framebuffers held the old image views.
    void createFramebuffers(const vk::Swapchain& swapchain);
    void releaseFramebuffers() { framebuffers_.clear(); }

    // Starts an ImGui frame. The cursor comes from the viewer's input state (window
    // coordinates, nullopt outside the window) instead of the backend polling the window
    // system, so scripted input moves ImGui's cursor exactly like real input.
    void newFrame(std::optional<glm::vec2> cursor);
    // Records the panel pass on swapchain image `index` (in COLOR_ATTACHMENT_OPTIMAL; left in
    // PRESENT_SRC_KHR). ImGui::Render() must have run this frame.
    void record(VkCommandBuffer cmd, uint32_t index) const;

  private:
    // Dear ImGui's context and backends, shut down in reverse order of their start.
    struct Backends {
        bool context = false, glfw = false, vulkan = false;
        Backends() = default;
        Backends(const Backends&) = delete;
        Backends& operator=(const Backends&) = delete;
        ~Backends();
    };

    vk::Device& device_;
    vk::Handle<VkRenderPass> pass_;
    vk::Handle<VkDescriptorPool> pool_;
    Backends backends_; // after the pool and pass: shut down before they go
    std::vector<vk::Handle<VkFramebuffer>> framebuffers_;
    VkExtent2D extent_{};
};

} // namespace app
