// targets.cpp - render pass and attachments of the scene pass.
#include "render/targets.h"

#include <array>
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include "vk/check.h"
#include "vk/upload.h"

namespace render {

// Float depth first: reversed depth (scene/camera.h) keeps its relative precision at every
// distance only in a float format. Vulkan guarantees D32_SFLOAT or X8_D24 (every desktop driver
// and lavapipe offer D32_SFLOAT); the fixed-point fallbacks draw, with far less precision far off.
static VkFormat pickDepthFormat(VkPhysicalDevice physical) {
    for (VkFormat format :
         {VK_FORMAT_D32_SFLOAT, VK_FORMAT_X8_D24_UNORM_PACK32, VK_FORMAT_D16_UNORM}) {
        VkFormatProperties props;
        vkGetPhysicalDeviceFormatProperties(physical, format, &props);
        if (props.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT)
            return format;
    }
    throw vk::Error("the device offers no depth attachment format");
}

// The framebuffer limits are what every format guarantees; the formats we render to may offer
// more (lavapipe: 4x for R32_UINT though its integer-colour limit says 1x), so ask per format.
VkSampleCountFlags supportedSampleCounts(const vk::Device& device) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(device.physical(), &props);
    VkSampleCountFlags counts =
        props.limits.framebufferColorSampleCounts & props.limits.framebufferDepthSampleCounts;
    const VkFormat depth = pickDepthFormat(device.physical());
    for (VkFormat format : {ScenePass::colorFormat, ScenePass::idFormat, depth}) {
        const VkImageUsageFlags usage = format == depth
                                            ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT
                                            : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
        VkImageFormatProperties formatProps{};
        if (vkGetPhysicalDeviceImageFormatProperties(device.physical(), format, VK_IMAGE_TYPE_2D,
                                                     VK_IMAGE_TILING_OPTIMAL, usage, 0,
                                                     &formatProps) != VK_SUCCESS)
            return VK_SAMPLE_COUNT_1_BIT;
        counts &= formatProps.sampleCounts;
    }
    return counts | VK_SAMPLE_COUNT_1_BIT;
}

VkSampleCountFlagBits checkedSampleCount(const vk::Device& device, uint32_t samples) {
    const VkSampleCountFlags supported = supportedSampleCounts(device);
    if ((samples & (samples - 1)) == 0 && (supported & samples))
        return static_cast<VkSampleCountFlagBits>(samples);
    std::string offered;
    for (uint32_t n = 1; n <= 64; n *= 2)
        if (supported & n) offered += (offered.empty() ? "" : ", ") + std::to_string(n);
    throw vk::Error("MSAA " + std::to_string(samples) + "x is not supported by " +
                    device.info().name + " (it offers " + offered + ")");
}

ScenePass::ScenePass(vk::Device& device, VkSampleCountFlagBits samples) : samples_(samples) {
    depthFormat_ = pickDepthFormat(device.physical());
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(device.physical(), &props);
    if (samples != VK_SAMPLE_COUNT_1_BIT && !props.limits.standardSampleLocations)
        throw vk::Error("MSAA needs the standard sample locations, which " +
                        std::string(props.deviceName) + " does not use");
    for (PassPart part : {PassPart::Whole, PassPart::First, PassPart::Second})
        for (ClearPath path : {ClearPath::Pass, ClearPath::Compute})
            for (bool clearColor : {false, true})
                passes_[variant(part, path, clearColor)] = create(device, part, path, clearColor);
}

namespace {

// What one variant of the scene pass is (ScenePass::create).
struct PassShape {
    bool msaa, first, second, compute, clearColor;
    // On the pass path with MSAA the whole pass and the second half resolve at their end.
    bool resolves() const { return msaa && !first && !compute; }
};

// 0 colour, 1 IDs, 2 depth; where the pass resolves, also 3 and 4, the single-sample colour
// and IDs the multisampled ones resolve into. The compute path clears depth alone (and colour
// under X-ray): its resolve writes the background (render/resolve.h).
std::vector<VkAttachmentDescription>
sceneAttachments(const PassShape& shape, VkSampleCountFlagBits samples, VkFormat depthFormat) {
    // The first half keeps what it drew for the second; the second starts from it.
    const VkImageLayout kept = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    const VkImageLayout sampledDepth = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
    // What the compute resolve reads: every sample with MSAA, else the images it completes.
    const VkImageLayout resolveReads =
        shape.msaa ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_GENERAL;
    auto colorAttachment = [&](VkFormat format, VkSampleCountFlagBits count, bool cleared) {
        VkAttachmentDescription a{};
        a.format = format;
        a.samples = count;
        a.loadOp = shape.second ? VK_ATTACHMENT_LOAD_OP_LOAD
                   : cleared    ? VK_ATTACHMENT_LOAD_OP_CLEAR
                                : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        a.initialLayout = shape.second ? kept : VK_IMAGE_LAYOUT_UNDEFINED; // started every frame
        a.finalLayout = shape.first     ? kept
                        : shape.compute ? resolveReads
                                        : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        return a;
    };
    std::vector<VkAttachmentDescription> attachments = {
        colorAttachment(ScenePass::colorFormat, samples, !shape.compute || shape.clearColor),
        colorAttachment(ScenePass::idFormat, samples, !shape.compute),
        colorAttachment(depthFormat, samples, true)};
    // Depth is kept after every part: the pyramid reads it between the halves, the compute
    // resolve after the pass, and the composition at the hovered pixel in every frame until
    // the next scene pass.
    VkAttachmentDescription& depth = attachments[2];
    depth.initialLayout = shape.second ? sampledDepth : VK_IMAGE_LAYOUT_UNDEFINED;
    depth.finalLayout = sampledDepth;
    if (!shape.resolves()) return attachments;
    // The multisampled colour and IDs are not kept past the resolve.
    for (uint32_t i : {0u, 1u}) {
        attachments[i].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        attachments[i].finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    }
    for (VkFormat format : {ScenePass::colorFormat, ScenePass::idFormat}) {
        attachments.push_back(colorAttachment(format, VK_SAMPLE_COUNT_1_BIT, false));
        attachments.back().loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE; // fully overwritten
        attachments.back().initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        attachments.back().finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    }
    return attachments;
}

// In: the previous frame's pass and its copies out of the colour and ID images must be done
// before this frame clears them; the second half waits for the first half's writes and for
// the pyramid's reads of depth. Out: the copies wait for the pass's writes; after the first
// half, the pyramid reads depth. The same for every part: compatible render passes have
// identical dependencies.
std::array<VkSubpassDependency, 2> sceneDependencies() {
    std::array<VkSubpassDependency, 2> deps{};
    deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    deps[0].dstSubpass = 0;
    deps[0].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                           VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT |
                           VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    deps[0].srcAccessMask =
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    deps[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                           VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                           VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    deps[0].dstAccessMask =
        VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    deps[1].srcSubpass = 0;
    deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    deps[1].srcStageMask =
        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    deps[1].srcAccessMask =
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    deps[1].dstStageMask = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
    deps[1].dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT;
    return deps;
}

} // namespace

vk::Handle<VkRenderPass> ScenePass::create(vk::Device& device, PassPart part, ClearPath path,
                                           bool clearColor) const {
    const PassShape shape{samples_ != VK_SAMPLE_COUNT_1_BIT, part == PassPart::First,
                          part == PassPart::Second, path == ClearPath::Compute, clearColor};
    const std::vector<VkAttachmentDescription> attachments =
        sceneAttachments(shape, samples_, depthFormat_);
    const std::array<VkAttachmentReference, 2> colorRefs = {
        VkAttachmentReference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
        VkAttachmentReference{1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}};
    const std::array<VkAttachmentReference, 2> resolveRefs = {
        VkAttachmentReference{3, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
        VkAttachmentReference{4, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}};
    const VkAttachmentReference depthRef{2, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = static_cast<uint32_t>(colorRefs.size());
    subpass.pColorAttachments = colorRefs.data();
    subpass.pResolveAttachments = shape.resolves() ? resolveRefs.data() : nullptr;
    subpass.pDepthStencilAttachment = &depthRef;
    const std::array<VkSubpassDependency, 2> deps = sceneDependencies();

    auto info = vk::init<VkRenderPassCreateInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO);
    info.attachmentCount = static_cast<uint32_t>(attachments.size());
    info.pAttachments = attachments.data();
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = static_cast<uint32_t>(deps.size());
    info.pDependencies = deps.data();
    const char* names[] = {"scene pass", "scene pass, first half", "scene pass, second half"};
    const std::string clears =
        shape.compute ? (clearColor ? ", clears depth and colour" : ", clears depth") : "";
    return vk::make(device, vkCreateRenderPass, info,
                    std::string(names[size_t(part)]) + " (" + std::to_string(samples_) + "x MSAA" +
                        clears + ")");
}

glm::vec2 ScenePass::sampleZero() const {
    switch (samples_) {
    case VK_SAMPLE_COUNT_2_BIT:
        return {0.75f, 0.75f};
    case VK_SAMPLE_COUNT_4_BIT:
        return {0.375f, 0.125f};
    case VK_SAMPLE_COUNT_8_BIT:
        return {0.5625f, 0.3125f};
    default:
        return {0.5f, 0.5f};
    }
}

SceneTargets::SceneTargets(vk::Device& device, const ScenePass& pass, VkExtent2D extent)
    : pass_(pass), extent_(extent) {
    // Storage: the passes over the ID image read the IDs and the shaded colour, and compose
    // the picture into `color_`, which the pass never touches.
    const VkImageUsageFlags readable = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                       VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_STORAGE_BIT;
    shaded_ = vk::Image(device, extent, ScenePass::colorFormat, readable, VK_IMAGE_ASPECT_COLOR_BIT,
                        "scene colour, shaded");
    color_ = vk::Image(device, extent, ScenePass::colorFormat,
                       VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_STORAGE_BIT,
                       VK_IMAGE_ASPECT_COLOR_BIT, "scene colour, composed");
    ids_ = vk::Image(device, extent, ScenePass::idFormat, readable, VK_IMAGE_ASPECT_COLOR_BIT,
                     "scene part IDs");
    const VkSampleCountFlagBits samples = pass.samples();
    // Sampled: the depth pyramid of occlusion culling reads it, and so does the composition
    // at the hovered pixel.
    depth_ = vk::Image(device, extent, pass.depthFormat(),
                       VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                       VK_IMAGE_ASPECT_DEPTH_BIT, "scene depth", samples);
    std::vector<VkImageView> views = {shaded_.view(), ids_.view(), depth_.view()};
    if (samples != VK_SAMPLE_COUNT_1_BIT) {
        // Rendered to, then resolved within the pass or by the compute resolve.
        // The compute path's resolve reads every sample of both.
        const VkImageUsageFlags inPass =
            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
        msColor_ = vk::Image(device, extent, ScenePass::colorFormat, inPass,
                             VK_IMAGE_ASPECT_COLOR_BIT, "scene colour (MSAA)", samples);
        msIds_ = vk::Image(device, extent, ScenePass::idFormat, inPass, VK_IMAGE_ASPECT_COLOR_BIT,
                           "scene part IDs (MSAA)", samples);
        views = {msColor_.view(), msIds_.view(), depth_.view(), shaded_.view(), ids_.view()};
    }
    auto info = vk::init<VkFramebufferCreateInfo>(VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO);
    info.renderPass = pass.handle();
    info.attachmentCount = static_cast<uint32_t>(views.size());
    info.pAttachments = views.data();
    info.width = extent.width;
    info.height = extent.height;
    info.layers = 1;
    framebuffer_ = vk::make(device, vkCreateFramebuffer, info, "scene framebuffer");
    // The first half resolves nothing: its attachments are the first three.
    info.renderPass = pass.handle(PassPart::First);
    info.attachmentCount = 3;
    firstFramebuffer_ =
        vk::make(device, vkCreateFramebuffer, info, "scene framebuffer, first half");

    // The header is written once here: it depends on the extent alone.
    pyramidHeader_ = pyramidLevels(extent);
    std::vector<std::byte> pyramid(pyramidBytes(pyramidHeader_));
    std::memcpy(pyramid.data(), &pyramidHeader_, sizeof pyramidHeader_);
    vk::UploadBatch upload(device);
    pyramid_ = std::make_shared<vk::Buffer>(
        upload.add(pyramid.data(), pyramid.size(),
                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                   "depth pyramid"));
    upload.keep(pyramid_);
    upload.submit();
}

gpu::PyramidHeader pyramidLevels(VkExtent2D extent) {
    gpu::PyramidHeader header{};
    uint32_t offset = 0;
    for (uint32_t k = 0; k < gpu::PYRAMID_MAX_LEVELS; ++k) {
        // Level k: a texel per 2^(k + 1) pixels, rounded up.
        const uint32_t w = (extent.width + (2u << k) - 1) >> (k + 1);
        const uint32_t h = (extent.height + (2u << k) - 1) >> (k + 1);
        header.level[k] = {offset, w, h, 0};
        offset += w * h;
        header.levels = k + 1;
        if (w == 1 && h == 1) break;
    }
    return header;
}

VkDeviceSize pyramidBytes(const gpu::PyramidHeader& header) {
    const gpu::PyramidLevel& top = header.level[header.levels - 1];
    return sizeof header + VkDeviceSize(top.offset + top.width * top.height) * sizeof(float);
}

} // namespace render
