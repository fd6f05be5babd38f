// imgui_layer.cpp - Dear ImGui backend set-up, font upload, panel pass and shutdown.
#include "app/viewer/imgui_layer.h"

#include <cfloat>

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include "vk/check.h"

namespace app {
namespace {

// ImGui's Vulkan backend reports its own calls' results here.
void checkImGuiResult(VkResult result) {
    vk::check(result, "Dear ImGui's Vulkan backend");
}

vk::Handle<VkRenderPass> createPanelPass(vk::Device& device, VkFormat format) {
    VkAttachmentDescription color{};
    color.format = format;
    color.samples = VK_SAMPLE_COUNT_1_BIT;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD; // the blitted scene stays under the panel
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &ref;
    // The blit's barrier already made the image ready; this orders the panel's blending
    // reads after earlier colour writes to the same image.
    VkSubpassDependency in{};
    in.srcSubpass = VK_SUBPASS_EXTERNAL;
    in.dstSubpass = 0;
    in.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    in.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    in.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    in.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    auto info = vk::init<VkRenderPassCreateInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO);
    info.attachmentCount = 1;
    info.pAttachments = &color;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 1;
    info.pDependencies = &in;
    return vk::make(device, vkCreateRenderPass, info, "panel pass");
}

} // namespace

ImGuiLayer::ImGuiLayer(GLFWwindow* window, const vk::Instance& instance, vk::Device& device,
                       const vk::Swapchain& swapchain)
    : device_(device) {
    pass_ = createPanelPass(device, swapchain.format());
    // One combined image sampler: the font texture, the only image the panel shows.
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
    auto poolInfo =
        vk::init<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
    poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &size;
    pool_ = vk::make(device, vkCreateDescriptorPool, poolInfo, "panel descriptors");

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    backends_.context = true;
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini left in the working directory
    // A blinking text cursor would need frames while the viewer rests.
    ImGui::GetIO().ConfigInputTextCursorBlink = false;
    ImGui::StyleColorsDark();
    // The viewer forwards GLFW's events itself (and injects scripted ones the same way).
    backends_.glfw = ImGui_ImplGlfw_InitForVulkan(window, false);
    if (!backends_.glfw) throw vk::Error("Dear ImGui's GLFW backend failed to start");

    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = instance.handle();
    info.PhysicalDevice = device.physical();
    info.Device = device.handle();
    info.QueueFamily = device.queueFamily();
    info.Queue = device.queue();
    info.DescriptorPool = pool_.get();
    // ImGui cycles its vertex buffers over ImageCount frames; FrameSlots waits for the frame
    // two back before recording, so two buffers are never in use at once.
    info.MinImageCount = 2;
    info.ImageCount = 2;
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = &checkImGuiResult;
    backends_.vulkan = ImGui_ImplVulkan_Init(&info, pass_.get());
    if (!backends_.vulkan) throw vk::Error("Dear ImGui's Vulkan backend failed to start");
    // The font atlas goes up once, at start-up; its staging buffer is freed right after.
    device.submitNow([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
    createFramebuffers(swapchain);
}

ImGuiLayer::~ImGuiLayer() {
    // Teardown: nothing the panel drew may still be in flight when its buffers go.
    vkDeviceWaitIdle(device_.handle());
}

ImGuiLayer::Backends::~Backends() {
    if (vulkan) ImGui_ImplVulkan_Shutdown();
    if (glfw) ImGui_ImplGlfw_Shutdown();
    if (context) ImGui::DestroyContext();
}

void ImGuiLayer::createFramebuffers(const vk::Swapchain& swapchain) {
    framebuffers_.clear();
    extent_ = swapchain.extent();
    for (const vk::SwapchainImage& image : swapchain.images()) {
        auto info = vk::init<VkFramebufferCreateInfo>(VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO);
        info.renderPass = pass_.get();
        info.attachmentCount = 1;
        const VkImageView view = image.view.get();
        info.pAttachments = &view;
        info.width = extent_.width;
        info.height = extent_.height;
        info.layers = 1;
        framebuffers_.push_back(vk::make(device_, vkCreateFramebuffer, info, "panel framebuffer"));
    }
}

void ImGuiLayer::newFrame(std::optional<glm::vec2> cursor) {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::GetIO().MousePos = cursor ? ImVec2(cursor->x, cursor->y) : ImVec2(-FLT_MAX, -FLT_MAX);
    ImGui::NewFrame();
}

void ImGuiLayer::record(VkCommandBuffer cmd, uint32_t index) const {
    auto begin = vk::init<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
    begin.renderPass = pass_.get();
    begin.framebuffer = framebuffers_.at(index).get();
    begin.renderArea = {{0, 0}, extent_};
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
    vkCmdEndRenderPass(cmd);
}

} // namespace app
