// targets.h - the scene render pass and the images it renders to: colour, the R32_UINT part-ID
// attachment and depth. The window path (later) blits the colour image to the swapchain, so
// headless and windowed rendering share this pass unchanged.
#pragma once

#include "vk/resources.h"

namespace render {

class ScenePass {
  public:
    static constexpr VkFormat colorFormat = VK_FORMAT_R8G8B8A8_UNORM;
    static constexpr VkFormat idFormat = VK_FORMAT_R32_UINT;

    explicit ScenePass(vk::Device& device);
    ~ScenePass();
    ScenePass(const ScenePass&) = delete;
    ScenePass& operator=(const ScenePass&) = delete;

    VkRenderPass handle() const { return pass_; }
    VkFormat depthFormat() const { return depthFormat_; }

  private:
    vk::Device& device_;
    VkFormat depthFormat_ = VK_FORMAT_UNDEFINED;
    VkRenderPass pass_ = VK_NULL_HANDLE;
};

// After the pass, colour and ID images are in TRANSFER_SRC_OPTIMAL layout.
class SceneTargets {
  public:
    SceneTargets(vk::Device& device, const ScenePass& pass, VkExtent2D extent);
    ~SceneTargets();
    SceneTargets(const SceneTargets&) = delete;
    SceneTargets& operator=(const SceneTargets&) = delete;

    VkExtent2D extent() const { return extent_; }
    VkFramebuffer framebuffer() const { return framebuffer_; }
    const vk::Image& color() const { return color_; }
    const vk::Image& ids() const { return ids_; }

  private:
    void release();

    vk::Device& device_;
    VkExtent2D extent_;
    vk::Image color_, ids_, depth_;
    VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
};

} // namespace render
