// imgui_layer.cpp - Dear ImGui backend set-up, font upload, panel pass and shutdown.
#include "app/viewer/imgui_layer.h"

#include <array>
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
    color.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL; // copied to the window
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
    // The copies of the picture wait for the panel.
    VkSubpassDependency out{};
    out.srcSubpass = 0;
    out.dstSubpass = VK_SUBPASS_EXTERNAL;
    out.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    out.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    out.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    out.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    const std::array<VkSubpassDependency, 2> dependencies = {in, out};
    auto info = vk::init<VkRenderPassCreateInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO);
    info.attachmentCount = 1;
    info.pAttachments = &color;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = static_cast<uint32_t>(dependencies.size());
    info.pDependencies = dependencies.data();
    return vk::make(device, vkCreateRenderPass, info, "panel pass");
}

} // namespace

ImGuiLayer::ImGuiLayer(GLFWwindow* window, const vk::Instance& instance, vk::Device& device,
                       const vk::Image& picture)
    : device_(device) {
    pass_ = createPanelPass(device, picture.format());
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
    createFramebuffer(picture);
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

void ImGuiLayer::createFramebuffer(const vk::Image& picture) {
    extent_ = picture.extent();
    auto info = vk::init<VkFramebufferCreateInfo>(VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO);
    info.renderPass = pass_.get();
    info.attachmentCount = 1;
    const VkImageView view = picture.view();
    info.pAttachments = &view;
    info.width = extent_.width;
    info.height = extent_.height;
    info.layers = 1;
    framebuffer_ = vk::make(device_, vkCreateFramebuffer, info, "panel framebuffer");
}

void ImGuiLayer::newFrame(std::optional<glm::vec2> cursor) {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::GetIO().MousePos = cursor ? ImVec2(cursor->x, cursor->y) : ImVec2(-FLT_MAX, -FLT_MAX);
    ImGui::NewFrame();
}

void ImGuiLayer::record(VkCommandBuffer cmd) const {
    auto begin = vk::init<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
    begin.renderPass = pass_.get();
    begin.framebuffer = framebuffer_.get();
    begin.renderArea = {{0, 0}, extent_};
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
    vkCmdEndRenderPass(cmd);
}

// FNV-1a over the bytes ImGui hands the backend, and the box its vertices span.
ImGuiLayer::Drawn ImGuiLayer::drawn() {
    Drawn drawn;
    const ImDrawData* data = ImGui::GetDrawData();
    if (!data) return drawn;
    uint64_t hash = 0xcbf29ce484222325ull;
    auto add = [&](const void* bytes, size_t size) {
        for (size_t i = 0; i < size; ++i) {
            hash ^= static_cast<const uint8_t*>(bytes)[i];
            hash *= 0x100000001b3ull;
        }
    };
    glm::vec2 lo(FLT_MAX), hi(-FLT_MAX);
    for (int l = 0; l < data->CmdListsCount; ++l) {
        const ImDrawList& list = *data->CmdLists[l];
        add(list.VtxBuffer.Data, size_t(list.VtxBuffer.Size) * sizeof(ImDrawVert));
        add(list.IdxBuffer.Data, size_t(list.IdxBuffer.Size) * sizeof(ImDrawIdx));
        for (const ImDrawCmd& c : list.CmdBuffer) {
            add(&c.ClipRect, sizeof c.ClipRect);
            add(&c.TextureId, sizeof c.TextureId);
            add(&c.VtxOffset, sizeof c.VtxOffset);
            add(&c.IdxOffset, sizeof c.IdxOffset);
            add(&c.ElemCount, sizeof c.ElemCount);
        }
        for (const ImDrawVert& v : list.VtxBuffer) {
            lo = glm::min(lo, glm::vec2(v.pos.x, v.pos.y));
            hi = glm::max(hi, glm::vec2(v.pos.x, v.pos.y));
        }
    }
    drawn.hash = hash;
    if (lo.x <= hi.x) {
        // Whole pixels that any triangle may touch, one more each side for the rounding.
        const glm::ivec2 first = glm::ivec2(glm::floor(lo)) - 1,
                         last = glm::ivec2(glm::ceil(hi)) + 1;
        drawn.bounds =
            VkRect2D{{first.x, first.y}, {uint32_t(last.x - first.x), uint32_t(last.y - first.y)}};
    }
    return drawn;
}

} // namespace app
