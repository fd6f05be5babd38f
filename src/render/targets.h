// targets.h - the scene render pass and the images it renders to: colour, the R32_UINT part-ID
// attachment and depth, multisampled or not. The window blits the (resolved) colour image to
// the swapchain, so headless and windowed rendering share this pass unchanged.
//
// With MSAA the pass resolves colour (average) and IDs into single-sample images at its end.
// Part IDs cannot be averaged: integer attachments resolve to sample 0, so sample 0 decides
// which part a pixel shows, and the pick follows the same rule (see scene.frag).
#pragma once

#include <array>
#include <memory>

#include <glm/glm.hpp>

#include "shared.h"
#include "vk/handle.h"
#include "vk/resources.h"

namespace render {

// Sample counts the device can render the scene pass with: colour, integer colour and depth.
VkSampleCountFlags supportedSampleCounts(const vk::Device& device);
// Throws vk::Error naming the counts the device offers when `samples` is not among them.
VkSampleCountFlagBits checkedSampleCount(const vk::Device& device, uint32_t samples);

// The scene pass, whole, or split in two around the depth pyramid of occlusion culling
// (render/culling.h): the first half clears and keeps every attachment, leaving depth ready
// to be sampled; the second loads them, draws on and resolves. All three render into the
// same attachments, so the pipelines built for the whole pass draw in either half.
enum class PassPart { Whole, First, Second };

class ScenePass {
  public:
    static constexpr VkFormat colorFormat = VK_FORMAT_R8G8B8A8_UNORM;
    static constexpr VkFormat idFormat = VK_FORMAT_R32_UINT;

    ScenePass(vk::Device& device, VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT);

    VkRenderPass handle(PassPart part = PassPart::Whole) const {
        return passes_[size_t(part)].get();
    }
    VkFormat depthFormat() const { return depthFormat_; }
    VkSampleCountFlagBits samples() const { return samples_; }
    // Position of sample 0 inside a pixel: Vulkan's standard locations, which the pass
    // requires of MSAA devices (standardSampleLocations, checked at construction).
    glm::vec2 sampleZero() const;

  private:
    vk::Handle<VkRenderPass> create(vk::Device& device, PassPart part) const;

    VkSampleCountFlagBits samples_;
    VkFormat depthFormat_ = VK_FORMAT_UNDEFINED;
    std::array<vk::Handle<VkRenderPass>, 3> passes_; // by PassPart
};

// After the pass, the single-sample shaded colour and ID images are in TRANSFER_SRC_OPTIMAL
// layout and depth in DEPTH_STENCIL_READ_ONLY_OPTIMAL; after the composition (id_passes.h) the
// composed colour is in TRANSFER_SRC_OPTIMAL. The pass must outlive the targets.
class SceneTargets {
  public:
    SceneTargets(vk::Device& device, const ScenePass& pass, VkExtent2D extent);

    const ScenePass& pass() const { return pass_; }
    VkExtent2D extent() const { return extent_; }
    VkFramebuffer framebuffer(PassPart part = PassPart::Whole) const {
        return part == PassPart::First ? firstFramebuffer_.get() : framebuffer_.get();
    }
    // The picture shown: the shaded colour with the highlights, edges and outlines composed
    // over it (id_passes.h). Headless readbacks and the window read this one.
    const vk::Image& color() const { return color_; }
    // What the scene pass shaded, untouched by the composition, so that a new composition
    // (a hover, a blink, a selection) needs no scene pass.
    const vk::Image& shaded() const { return shaded_; }
    const vk::Image& ids() const { return ids_; }
    // With MSAA, the multisampled IDs: the second half of a split pass keeps them, in
    // SHADER_READ_ONLY_OPTIMAL, for culling's visible-part pass to read every sample.
    const vk::Image& multisampledIds() const { return msIds_; }
    // Sampled by the depth pyramid between the two halves of the pass (layout
    // DEPTH_STENCIL_READ_ONLY_OPTIMAL then).
    const vk::Image& depth() const { return depth_; }
    // The depth pyramid of these targets (gpu::PyramidHeader, written when they are made,
    // then the levels' floats), built by render/culling.h; `pyramidHeader` is its header.
    const vk::Buffer& pyramid() const { return *pyramid_; }
    const gpu::PyramidHeader& pyramidHeader() const { return pyramidHeader_; }

  private:
    const ScenePass& pass_;
    VkExtent2D extent_;
    vk::Image shaded_, color_, ids_, depth_;
    vk::Image msColor_, msIds_; // multisampled attachments, resolved into shaded_ and ids_
    vk::Handle<VkFramebuffer> framebuffer_, firstFramebuffer_;
    gpu::PyramidHeader pyramidHeader_{};
    // Shared with its upload, which may still be writing it when the targets go.
    std::shared_ptr<vk::Buffer> pyramid_;
};

// The levels of the depth pyramid over `extent` (shared.h PyramidHeader), and its size in
// bytes, header included.
gpu::PyramidHeader pyramidLevels(VkExtent2D extent);
VkDeviceSize pyramidBytes(const gpu::PyramidHeader& header);

} // namespace render
