// imgui_layer.h - Dear ImGui (1.86, Debian's libimgui) drawn over the scene in the window's
// picture: its GLFW and Vulkan backends, the descriptor pool its font texture needs, a render
// pass that keeps what the blit put there (loadOp LOAD) and ends ready to be copied to the
// window, and the framebuffer of the window's picture (Presenter).
#pragma once

#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

#include "vk/context.h"
#include "vk/handle.h"
#include "vk/resources.h"

struct GLFWwindow;

namespace app {

class ImGuiLayer {
  public:
    ImGuiLayer(GLFWwindow* window, const vk::Instance& instance, vk::Device& device,
               const vk::Image& picture);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    // For a new picture (the window changed size): the framebuffer held the old one's view.
    void createFramebuffer(const vk::Image& picture);

    // Starts an ImGui frame. The cursor comes from the viewer's input state (window
    // coordinates, nullopt outside the window) instead of the backend polling the window
    // system, so scripted input moves ImGui's cursor exactly like real input.
    void newFrame(std::optional<glm::vec2> cursor);
    // Records the panel pass on the picture (in COLOR_ATTACHMENT_OPTIMAL; left in
    // TRANSFER_SRC_OPTIMAL). ImGui::Render() must have run this frame.
    void record(VkCommandBuffer cmd) const;

    // What ImGui::Render() made this frame: a hash of everything the backend would draw (equal
    // hashes draw equal pixels) and the pixels its triangles may touch (none: nothing drawn).
    struct Drawn {
        uint64_t hash = 0;
        std::optional<VkRect2D> bounds;
    };
    static Drawn drawn();

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
    vk::Handle<VkFramebuffer> framebuffer_;
    VkExtent2D extent_{};
};

} // namespace app
