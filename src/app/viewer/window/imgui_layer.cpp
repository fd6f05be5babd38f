// imgui_layer.cpp - Dear ImGui backend set-up, font upload, panel pass and shutdown.
#include "app/viewer/window/imgui_layer.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cstring>

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

// The foreground list: what the viewer draws over the scene rather than in the panel's
// windows (edge_hover.cpp, measure.cpp, the selection box).
const ImDrawList* overlayList(const ImDrawData& data) {
    for (int l = 0; l < data.CmdListsCount; ++l)
        if (data.CmdLists[l]->_OwnerName &&
            std::strcmp(data.CmdLists[l]->_OwnerName, "##Foreground") == 0)
            return data.CmdLists[l];
    return nullptr;
}

// The box a draw list's vertices span, as the whole pixels its triangles may touch.
struct Span {
    glm::vec2 lo{FLT_MAX}, hi{-FLT_MAX};
    void add(ImVec2 p) {
        lo = glm::min(lo, glm::vec2(p.x, p.y));
        hi = glm::max(hi, glm::vec2(p.x, p.y));
    }
    std::optional<VkRect2D> pixels() const {
        if (lo.x > hi.x) return std::nullopt;
        // One more pixel each side for the rounding.
        const glm::ivec2 first = glm::ivec2(glm::floor(lo)) - 1,
                         last = glm::ivec2(glm::ceil(hi)) + 1;
        return VkRect2D{{first.x, first.y},
                        {uint32_t(last.x - first.x), uint32_t(last.y - first.y)}};
    }
};

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
    recordPass(cmd, ImGui::GetDrawData());
}

void ImGuiLayer::recordPass(VkCommandBuffer cmd, ImDrawData* data) const {
    auto begin = vk::init<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
    begin.renderPass = pass_.get();
    begin.framebuffer = framebuffer_.get();
    begin.renderArea = {{0, 0}, extent_};
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    ImGui_ImplVulkan_RenderDrawData(data, cmd);
    vkCmdEndRenderPass(cmd);
}

void ImGuiLayer::recordOverlay(VkCommandBuffer cmd, const VkRect2D& only) const {
    ImDrawData* whole = ImGui::GetDrawData();
    const ImDrawList* overlay = whole ? overlayList(*whole) : nullptr;
    ImDrawList* clipped = overlay ? overlay->CloneOutput() : nullptr;
    if (clipped) {
        // The backend scissors each command to its clip rectangle (ImGui's coordinates): the
        // overlay's pixels outside `only` are in the picture already and must not blend twice.
        const ImVec2 scale = whole->FramebufferScale, origin = whole->DisplayPos;
        const ImVec4 keep(origin.x + float(only.offset.x) / scale.x,
                          origin.y + float(only.offset.y) / scale.y,
                          origin.x + float(only.offset.x + int32_t(only.extent.width)) / scale.x,
                          origin.y + float(only.offset.y + int32_t(only.extent.height)) / scale.y);
        for (ImDrawCmd& c : clipped->CmdBuffer)
            c.ClipRect = ImVec4(std::max(c.ClipRect.x, keep.x), std::max(c.ClipRect.y, keep.y),
                                std::min(c.ClipRect.z, keep.z), std::min(c.ClipRect.w, keep.w));
    }
    ImDrawData data;
    data.Valid = true;
    data.CmdLists = &clipped;
    data.CmdListsCount = clipped ? 1 : 0;
    data.TotalVtxCount = clipped ? clipped->VtxBuffer.Size : 0;
    data.TotalIdxCount = clipped ? clipped->IdxBuffer.Size : 0;
    data.DisplayPos = whole ? whole->DisplayPos : ImVec2(0, 0);
    data.DisplaySize =
        whole ? whole->DisplaySize : ImVec2(float(extent_.width), float(extent_.height));
    data.FramebufferScale = whole ? whole->FramebufferScale : ImVec2(1, 1);
    recordPass(cmd, &data); // with nothing to draw, the pass still ends the layout's way
    IM_DELETE(clipped);
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
    Span panel, overlay;
    for (int l = 0; l < data->CmdListsCount; ++l) {
        const ImDrawList& list = *data->CmdLists[l];
        Span& span = &list == overlayList(*data) ? overlay : panel;
        add(list.VtxBuffer.Data, size_t(list.VtxBuffer.Size) * sizeof(ImDrawVert));
        add(list.IdxBuffer.Data, size_t(list.IdxBuffer.Size) * sizeof(ImDrawIdx));
        for (const ImDrawCmd& c : list.CmdBuffer) {
            add(&c.ClipRect, sizeof c.ClipRect);
            add(&c.TextureId, sizeof c.TextureId);
            add(&c.VtxOffset, sizeof c.VtxOffset);
            add(&c.IdxOffset, sizeof c.IdxOffset);
            add(&c.ElemCount, sizeof c.ElemCount);
        }
        for (const ImDrawVert& v : list.VtxBuffer) span.add(v.pos);
    }
    drawn.hash = hash;
    drawn.bounds = panel.pixels();
    drawn.overlay = overlay.pixels();
    return drawn;
}

} // namespace app
