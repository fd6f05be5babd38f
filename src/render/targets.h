// targets.h - the scene render pass and the images it renders to: colour, the R32_UINT part-ID
// attachment and depth, multisampled or not. The window blits the (resolved) colour image to
// the swapchain, so headless and windowed rendering share this pass unchanged.
//
// With MSAA the pass (or, on the compute path, render/resolve.h) resolves colour (average)
// and IDs into single-sample images. Part IDs cannot be averaged: they resolve to sample 0,
// so sample 0 decides which part a pixel shows, and the pick follows the same rule (see
// scene.frag).
#pragma once

#include <array>
#include <memory>

#include <glm/glm.hpp>

#include "render/settings.h"
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

    // The pass of `part` on `path` (Pass or Compute, render/settings.h). The compute path's
    // pass clears depth alone, but for `clearColor`: X-ray blends over the background, so
    // its frames clear colour too. At 1x every variant is compatible with every other; with
    // MSAA the two paths' are not (one resolves), so pipelines are built per path.
    VkRenderPass handle(PassPart part = PassPart::Whole, ClearPath path = ClearPath::Pass,
                        bool clearColor = false) const {
        return passes_[variant(part, path, clearColor)].get();
    }
    VkFormat depthFormat() const { return depthFormat_; }
    VkSampleCountFlagBits samples() const { return samples_; }
    // Position of sample 0 inside a pixel: Vulkan's standard locations, which the pass
    // requires of MSAA devices (standardSampleLocations, checked at construction).
    glm::vec2 sampleZero() const;

  private:
    static size_t variant(PassPart part, ClearPath path, bool clearColor) {
        return size_t(part) * 4 + (path == ClearPath::Compute ? 2 : 0) + (clearColor ? 1 : 0);
    }
    vk::Handle<VkRenderPass> create(vk::Device& device, PassPart part, ClearPath path,
                                    bool clearColor) const;

    VkSampleCountFlagBits samples_;
    VkFormat depthFormat_ = VK_FORMAT_UNDEFINED;
    std::array<vk::Handle<VkRenderPass>, 12> passes_; // by variant()
};

// The colour of background pixels, as the pass clears it or the compute path writes it.
constexpr glm::vec4 backgroundColor{0.16f, 0.17f, 0.19f, 1.0f};

// After the pass (and on the compute path its resolve, render/resolve.h), the single-sample
// shaded colour and ID images are in TRANSFER_SRC_OPTIMAL
// layout and depth in DEPTH_STENCIL_READ_ONLY_OPTIMAL; after the composition (id_passes.h) the
// composed colour is in TRANSFER_SRC_OPTIMAL. The pass must outlive the targets.
class SceneTargets {
  public:
    SceneTargets(vk::Device& device, const ScenePass& pass, VkExtent2D extent);

    const ScenePass& pass() const { return pass_; }
    VkExtent2D extent() const { return extent_; }
    // The compute path's passes and the first half render into the pass's own attachments
    // alone (the first three); the pass path's whole pass and second half also resolve.
    VkFramebuffer framebuffer(PassPart part = PassPart::Whole,
                              ClearPath path = ClearPath::Pass) const {
        return part == PassPart::First || path == ClearPath::Compute ? firstFramebuffer_.get()
                                                                     : framebuffer_.get();
    }
    // The picture shown: the shaded colour with the highlights, edges and outlines composed
    // over it (id_passes.h). Headless readbacks and the window read this one.
    const vk::Image& color() const { return color_; }
    // What the scene pass shaded, untouched by the composition, so that a new composition
    // (a hover, a blink, a selection) needs no scene pass.
    const vk::Image& shaded() const { return shaded_; }
    const vk::Image& ids() const { return ids_; }
    // With MSAA, the multisampled IDs and colour: the compute path keeps both in
    // SHADER_READ_ONLY_OPTIMAL for its resolve to read every sample. Where a sample's depth is
    // the clear value no triangle covered it, and its ID and colour are undefined there.
    const vk::Image& multisampledIds() const { return msIds_; }
    const vk::Image& multisampledColor() const { return msColor_; }
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
