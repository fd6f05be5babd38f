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
struct ImDrawData;

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

    // Records the overlay alone (ImGui's foreground list: hovered and selected edges, the
    // measure marks, a selection box) clipped to `only`, over a picture whose `only` was just
    // blitted from the scene (in COLOR_ATTACHMENT_OPTIMAL; left in TRANSFER_SRC_OPTIMAL).
    // Those pixels then equal what record() draws there, when the panel does not reach them.
    void recordOverlay(VkCommandBuffer cmd, const VkRect2D& only) const;

    // What ImGui::Render() made this frame: a hash of everything the backend would draw (equal
    // hashes draw equal pixels), the pixels the panel's triangles may touch and those the
    // overlay's may (none: nothing drawn).
    struct Drawn {
        uint64_t hash = 0;
        std::optional<VkRect2D> bounds, overlay;
    };
    static Drawn drawn();

  private:
    void recordPass(VkCommandBuffer cmd, ImDrawData* data) const;

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
