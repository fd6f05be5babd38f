// viewer_frame.cpp - one frame: swapchain upkeep, picking, recording, present, screenshots,
// the panel's snapshot and the window title.
#include <algorithm>
#include <cstdio>
#include <numeric>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app/image_io.h"
#include "app/viewer_app.h"
#include "scene/explode.h"
#include "vk/check.h"

namespace app {

bool Viewer::recreateSwapchain() {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    if (width == 0 || height == 0) return false;
    // Frames in flight still use the framebuffers and images about to go.
    vk::check(vkDeviceWaitIdle(device_.handle()), "vkDeviceWaitIdle");
    if (ui_) ui_->releaseFramebuffers();
    const bool made = swapchain_.recreate({uint32_t(width), uint32_t(height)}, settings_.vsync);
    if (ui_ && swapchain_.valid()) ui_->createFramebuffers(swapchain_);
    if (!made) return false;
    const VkExtent2D extent = swapchain_.extent();
    if (rig_ && (rig_->targets->extent().width != extent.width ||
                 rig_->targets->extent().height != extent.height)) {
        rig_->targets.reset(); // the device is idle: recreate() waited
        rig_->targets = std::make_unique<render::SceneTargets>(device_, rig_->pass, extent);
    }
    swapchainDirty_ = false;
    updateTitle(elapsed(), true); // vsync may have changed
    return true;
}

std::optional<glm::vec2> Viewer::cursorInWindow() const {
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    if (cursor_.x < 0 || cursor_.y < 0 || cursor_.x >= width || cursor_.y >= height)
        return std::nullopt;
    return glm::vec2(cursor_);
}

std::optional<glm::uvec2> Viewer::pickPixel() const {
    const auto cursor = cursorInWindow();
    if (!cursor || ImGui::GetIO().WantCaptureMouse) return std::nullopt; // over the panel
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    // Window coordinates to scene image pixels (they differ on high-DPI screens).
    const VkExtent2D extent = rig_->targets->extent();
    const glm::uvec2 pixel(cursor->x * float(extent.width) / float(width),
                           cursor->y * float(extent.height) / float(height));
    if (pixel.x >= extent.width || pixel.y >= extent.height) return std::nullopt;
    return pixel;
}

void Viewer::updatePicking() {
    // Picks arrive a frame or two late; only those since the cursor came over the scene
    // count, so an old pick never shows as the hover after leaving the panel.
    const auto& pick = slots_.latestPick();
    if (!pickingSince_) {
        selection_.hover(std::nullopt);
        pendingClick_.reset();
        return;
    }
    if (pick && pick->frame >= *pickingSince_) {
        selection_.hover(pick->part);
        hoveredDepth_ = pick->depth;
    }
    // A click selects what was under the cursor in the frame after the click.
    if (pendingClick_ && pick && pick->frame >= *pendingClick_) {
        selection_.click();
        selectedDepth_ = hoveredDepth_;
        pendingClick_.reset();
        reportSelection();
    }
}

void Viewer::reportSelection() const {
    // One stdout line per change, so tests see what a click selected.
    const auto part = selection_.selected();
    const auto info = part ? scene::describePart(scene(), *part) : std::nullopt;
    if (info)
        std::printf("idview: selected: part %u (object %u, local part %u)\n", info->uniquePartId,
                    info->object, info->localPart);
    else
        std::printf("idview: selected: none\n");
    std::fflush(stdout);
}

void Viewer::drawFrame(double seconds) {
    // The panel first: its changes apply before this frame records anything.
    ui_->newFrame(cursorInWindow());
    const ViewerSettings wanted = panelVisible_ ? drawPanel(settings_, panelInfo()) : settings_;
    ImGui::Render();
    applySettings(wanted);
    if (swapchainDirty_) return; // vsync changed: the loop recreates the swapchain first

    render::FrameSlot& slot = slots_.begin(frameNumber_);
    updatePicking();
    VkSemaphore acquired = acquired_.handles[frameNumber_ % render::FrameSlots::count];
    uint32_t index = 0;
    const vk::Swapchain::Status status = swapchain_.acquire(acquired, index);
    if (status == vk::Swapchain::Status::OutOfDate) {
        slots_.submit(slot); // nothing to draw on, but the slot's fence must still signal
        ++frameNumber_;
        swapchainDirty_ = true;
        return;
    }
    if (status == vk::Swapchain::Status::Suboptimal) swapchainDirty_ = true; // after present

    const VkExtent2D extent = rig_->targets->extent();
    // The exploded view pushes objects out to twice their distance from the centre.
    const scene::Camera camera = camera_.camera(settings_.animate ? 2.0f : 1.0f);
    render::FrameParams params;
    params.viewProj = camera.viewProjection(float(extent.width) / float(extent.height));
    params.eye = camera.eye;
    params.partColorWeight = settings_.partWeight;
    params.colorizeDraws = settings_.colorizeDraws;
    params.ignoreMaterials = settings_.ignoreMaterials;
    params.time = float(seconds);
    params.pickPixel = pickPixel();
    if (!params.pickPixel)
        pickingSince_.reset();
    else if (!pickingSince_)
        pickingSince_ = frameNumber_;
    params.selectedPart = selection_.selected().value_or(gpu::BACKGROUND_ID);
    params.explode = settings_.animate ? scene::explodeLoop(float(seconds)) : 0.0f;

    const auto recordStart = Clock::now();
    rig_->renderer.record(slot, *rig_->targets, params);
    cpuRecordMs_.push_back(
        std::chrono::duration<double, std::milli>(Clock::now() - recordStart).count());
    if (cpuRecordMs_.size() > 30) cpuRecordMs_.pop_front();

    const vk::SwapchainImage& image = swapchain_.images()[index];
    recordSceneToWindow(slot.cmd, rig_->targets->color(), image.image, swapchain_.extent());
    ui_->record(slot.cmd, index);
    std::string screenshot;
    std::swap(screenshot, screenshotPath_);
    if (!screenshot.empty() && !swapchain_.copyable()) {
        error_ = "screenshot: this window's images cannot be copied from";
        std::fprintf(stderr, "idview: %s\n", error_.c_str());
        screenshot.clear();
    }
    if (!screenshot.empty()) {
        const VkExtent2D size = swapchain_.extent();
        if (!capture_ || capture_->extent().width != size.width ||
            capture_->extent().height != size.height)
            capture_ = std::make_unique<WindowCapture>(device_, size);
        capture_->record(slot.cmd, image.image);
    }
    slots_.submit(slot, {acquired}, {VK_PIPELINE_STAGE_TRANSFER_BIT}, {image.renderFinished});
    if (swapchain_.present(index) != vk::Swapchain::Status::Ok) swapchainDirty_ = true;
    if (!screenshot.empty()) {
        slots_.finish(); // the copy is done once the slot's fence has signalled
        const VkExtent2D size = capture_->extent();
        writePng(screenshot, size.width, size.height, capture_->rgba(swapchain_.format()));
        std::printf("idview: screenshot: %s (%ux%u)\n", screenshot.c_str(), size.width,
                    size.height);
        std::fflush(stdout);
    }
    ++frameNumber_;
    updateTitle(seconds, false);
}

PanelInfo Viewer::panelInfo() const {
    PanelInfo info;
    info.device = device_.info().name;
    info.source = base_.source;
    info.gltf = base_.source.ends_with(".gltf") || base_.source.ends_with(".glb");
    info.error = error_;
    info.scene = &scene();
    info.stats = rig_->renderer.stats();
    info.idBytes = idBytes_;
    info.sampleCounts = sampleCounts_;
    info.fps = fps_;
    const auto& gpu = slots_.gpuMilliseconds();
    const size_t recent = std::min<size_t>(gpu.size(), 30);
    if (recent) info.gpuMs = std::accumulate(gpu.end() - long(recent), gpu.end(), 0.0) / recent;
    if (!cpuRecordMs_.empty())
        info.cpuRecordMs = std::accumulate(cpuRecordMs_.begin(), cpuRecordMs_.end(), 0.0) /
                           double(cpuRecordMs_.size());
    for (size_t i = gpu.size() - std::min<size_t>(gpu.size(), 200); i < gpu.size(); ++i)
        info.gpuHistory.push_back(float(gpu[i]));
    auto describe = [&](std::optional<uint32_t> part, float depth) {
        return PartLine{part ? scene::describePart(scene(), *part) : std::nullopt, depth};
    };
    info.hovered = describe(selection_.hovered(), hoveredDepth_);
    info.selected = describe(selection_.selected(), selectedDepth_);
    return info;
}

void Viewer::updateTitle(double seconds, bool now) {
    // A few times a second; fps counts the frames since the last update.
    if (!now && seconds - titleTime_ < 0.25) return;
    if (seconds > titleTime_) fps_ = double(frameNumber_ - titleFrame_) / (seconds - titleTime_);
    titleTime_ = seconds;
    titleFrame_ = frameNumber_;
    const auto& gpu = slots_.gpuMilliseconds();
    const size_t recent = std::min<size_t>(gpu.size(), 30);
    const double gpuMs =
        recent ? std::accumulate(gpu.end() - long(recent), gpu.end(), 0.0) / recent : 0.0;
    const bool fifoOnly = !settings_.vsync && swapchain_.presentMode() == VK_PRESENT_MODE_FIFO_KHR;
    char text[256];
    std::snprintf(text, sizeof text, "idview - %s + %s - vsync %s - %.0f fps - GPU %.2f ms",
                  render::techniques()[size_t(settings_.technique)].name,
                  render::drawModes()[size_t(settings_.mode)].name,
                  settings_.vsync ? "on" : (fifoOnly ? "off (FIFO only)" : "off"), fps_, gpuMs);
    if (title_ == text) return;
    title_ = text;
    glfwSetWindowTitle(window_, text);
    std::printf("idview: title: %s\n", text); // tests follow the title through stdout
    std::fflush(stdout);
}

} // namespace app
