// targets.cpp - render pass and attachments of the scene pass.
#include "render/targets.h"

#include <array>
#include <string>
#include <vector>

#include "vk/check.h"

namespace render {

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
    const bool msaa = samples != VK_SAMPLE_COUNT_1_BIT;
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(device.physical(), &props);
    if (msaa && !props.limits.standardSampleLocations)
        throw vk::Error("MSAA needs the standard sample locations, which " +
                        std::string(props.deviceName) + " does not use");

    auto colorAttachment = [](VkFormat format, VkSampleCountFlagBits count) {
        VkAttachmentDescription a{};
        a.format = format;
        a.samples = count;
        a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        a.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED; // cleared every frame
        a.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        return a;
    };
    // 0 colour, 1 IDs, 2 depth; with MSAA also 3 and 4, the single-sample colour and IDs the
    // multisampled ones resolve into (the multisampled contents are not kept).
    std::vector<VkAttachmentDescription> attachments = {colorAttachment(colorFormat, samples),
                                                        colorAttachment(idFormat, samples),
                                                        colorAttachment(depthFormat_, samples)};
    VkAttachmentDescription& depth = attachments[2];
    depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depth.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    std::array<VkAttachmentReference, 2> resolveRefs = {
        VkAttachmentReference{3, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
        VkAttachmentReference{4, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}};
    if (msaa) {
        for (uint32_t i : {0u, 1u}) {
            attachments[i].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
            attachments[i].finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        }
        for (VkFormat format : {colorFormat, idFormat}) {
            attachments.push_back(colorAttachment(format, VK_SAMPLE_COUNT_1_BIT));
            attachments.back().loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE; // fully overwritten
        }
    }

    std::array<VkAttachmentReference, 2> colorRefs = {
        VkAttachmentReference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
        VkAttachmentReference{1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}};
    VkAttachmentReference depthRef{2, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = static_cast<uint32_t>(colorRefs.size());
    subpass.pColorAttachments = colorRefs.data();
    subpass.pResolveAttachments = msaa ? resolveRefs.data() : nullptr;
    subpass.pDepthStencilAttachment = &depthRef;

    // In: the previous frame's pass and its copies out of the colour and ID images must be
    // done before this frame clears them. Out: the copies wait for this pass's writes.
    std::array<VkSubpassDependency, 2> deps{};
    deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    deps[0].dstSubpass = 0;
    deps[0].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                           VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT |
                           VK_PIPELINE_STAGE_TRANSFER_BIT;
    deps[0].srcAccessMask =
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    deps[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                           VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                           VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    deps[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                            VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                            VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    deps[1].srcSubpass = 0;
    deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    deps[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    deps[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;

    auto info = vk::init<VkRenderPassCreateInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO);
    info.attachmentCount = static_cast<uint32_t>(attachments.size());
    info.pAttachments = attachments.data();
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = static_cast<uint32_t>(deps.size());
    info.pDependencies = deps.data();
    pass_ = vk::make(device, vkCreateRenderPass, info,
                     "scene pass (" + std::to_string(samples) + "x MSAA)");
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
    // Storage: the passes over the ID image read the IDs and draw edges into the colour.
    const VkImageUsageFlags readable = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                       VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_STORAGE_BIT;
    color_ = vk::Image(device, extent, ScenePass::colorFormat, readable, VK_IMAGE_ASPECT_COLOR_BIT,
                       "scene colour");
    ids_ = vk::Image(device, extent, ScenePass::idFormat, readable, VK_IMAGE_ASPECT_COLOR_BIT,
                     "scene part IDs");
    const VkSampleCountFlagBits samples = pass.samples();
    depth_ =
        vk::Image(device, extent, pass.depthFormat(), VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                  VK_IMAGE_ASPECT_DEPTH_BIT, "scene depth", samples);
    std::vector<VkImageView> views = {color_.view(), ids_.view(), depth_.view()};
    if (samples != VK_SAMPLE_COUNT_1_BIT) {
        // Only ever rendered to and resolved within the pass.
        const VkImageUsageFlags inPass = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
        msColor_ = vk::Image(device, extent, ScenePass::colorFormat, inPass,
                             VK_IMAGE_ASPECT_COLOR_BIT, "scene colour (MSAA)", samples);
        msIds_ = vk::Image(device, extent, ScenePass::idFormat, inPass, VK_IMAGE_ASPECT_COLOR_BIT,
                           "scene part IDs (MSAA)", samples);
        views = {msColor_.view(), msIds_.view(), depth_.view(), color_.view(), ids_.view()};
    }
    auto info = vk::init<VkFramebufferCreateInfo>(VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO);
    info.renderPass = pass.handle();
    info.attachmentCount = static_cast<uint32_t>(views.size());
    info.pAttachments = views.data();
    info.width = extent.width;
    info.height = extent.height;
    info.layers = 1;
    framebuffer_ = vk::make(device, vkCreateFramebuffer, info, "scene framebuffer");
}

} // namespace render
