// viewer_scene.cpp - applying settings: renderer configuration, MSAA (a new scene pass,
// targets and renderer), model copies and opening scenes. A failure keeps what worked before.
#include <cstdio>

#include "app/viewer_app.h"
#include "scene/copies.h"
#include "vk/check.h"

namespace app {
namespace {

render::RenderConfig renderConfig(const ViewerSettings& s, const Options& options) {
    render::RenderConfig config;
    config.technique = &render::techniques()[size_t(s.technique)];
    config.mode = &render::drawModes()[size_t(s.mode)];
    config.searchBatch = s.searchBatch;
    config.nsearch = s.nsearch;
    config.visible = s.visible;
    config.sortDraws = options.sortDraws;
    config.gsPassthrough = options.gsPassthrough;
    return config;
}

} // namespace

void Viewer::applySettings(const ViewerSettings& wanted) {
    if (wanted.vsync != settings_.vsync) {
        settings_.vsync = wanted.vsync;
        swapchainDirty_ = true; // the present mode is fixed at swapchain creation
    }
    settings_.partWeight = wanted.partWeight;
    settings_.colorizeDraws = wanted.colorizeDraws;
    settings_.ignoreMaterials = wanted.ignoreMaterials;
    settings_.animate = wanted.animate;
    if (wanted.componentParts != settings_.componentParts) {
        Options source = options_;
        source.model = base_.source;
        source.scene.clear();
        source.parts = wanted.componentParts ? "components" : "primitives";
        openScene(source); // keeps the old scene and its mode if the reload fails
    }
    if (wanted.copies != settings_.copies || wanted.copyAxes != settings_.copyAxes) {
        const uint32_t axes = settings_.copyAxes;
        settings_.copyAxes = wanted.copyAxes; // setCopies lays the grid out along these
        if (!setCopies(wanted.copies)) settings_.copyAxes = axes;
    }
    if (wanted.msaa != settings_.msaa) setMsaa(wanted.msaa);
    if (wanted.technique != settings_.technique || wanted.mode != settings_.mode ||
        wanted.searchBatch != settings_.searchBatch || wanted.nsearch != settings_.nsearch ||
        wanted.visible != settings_.visible)
        configure(wanted);
}

void Viewer::reloadShaders() {
    try {
        rig_->renderer.reloadShaders();
        error_.clear();
        std::printf("idview: shaders reloaded\n");
        std::fflush(stdout);
    } catch (const vk::ShaderError& e) {
        error_ = e.what(); // shown in the panel; the last good pipeline keeps drawing
        std::fprintf(stderr, "idview: %s\n", error_.c_str());
    }
}

void Viewer::configure(const ViewerSettings& wanted) {
    vk::check(vkDeviceWaitIdle(device_.handle()), "vkDeviceWaitIdle"); // buffers get replaced
    try {
        rig_->renderer.configure(scene(), renderConfig(wanted, options_));
    } catch (const vk::ShaderError& e) {
        // The renderer keeps its previous configuration; so do the settings.
        error_ = e.what();
        std::fprintf(stderr, "idview: %s\n", error_.c_str());
        return;
    }
    settings_.technique = wanted.technique;
    settings_.mode = wanted.mode;
    settings_.searchBatch = wanted.searchBatch;
    settings_.nsearch = wanted.nsearch;
    settings_.visible = wanted.visible;
    idBytes_ = scene::idDataBytes(scene(), settings_.searchBatch);
    error_.clear();
    updateTitle(elapsed(), true);
}

void Viewer::buildRig(uint32_t samples) {
    vk::check(vkDeviceWaitIdle(device_.handle()), "vkDeviceWaitIdle");
    rig_.reset(); // renderer, targets, then the pass they were made for
    rig_ = std::make_unique<SceneRig>(
        device_, compiler_, static_cast<VkSampleCountFlagBits>(samples), swapchain_.extent());
    rig_->renderer.setScene(scene());
    rig_->renderer.configure(scene(), renderConfig(settings_, options_));
    settings_.msaa = samples;
}

void Viewer::setMsaa(uint32_t samples) {
    if (!(sampleCounts_ & samples)) {
        error_ = "MSAA " + std::to_string(samples) + "x is not offered by " + device_.info().name;
        return;
    }
    const uint32_t previous = settings_.msaa;
    try {
        buildRig(samples);
        error_.clear();
    } catch (const vk::ShaderError& e) {
        error_ = e.what();
        std::fprintf(stderr, "idview: %s\n", error_.c_str());
        buildRig(previous);
    }
}

bool Viewer::openScene(const Options& source) {
    LoadedScene loaded;
    try {
        Options single = source;
        single.copies = 1; // the viewer makes copies itself, so changing them needs no reload
        loaded = loadScene(single);
    } catch (const std::exception& e) {
        error_ = e.what(); // one line naming the file; the previous scene stays
        std::fprintf(stderr, "idview: %s\n", error_.c_str());
        return false;
    }
    for (const auto& warning : loaded.warnings)
        std::fprintf(stderr, "idview: warning: %s: %s\n", loaded.source.c_str(), warning.c_str());
    vk::check(vkDeviceWaitIdle(device_.handle()), "vkDeviceWaitIdle");
    base_ = std::move(loaded);
    copies_.reset();
    if (settings_.copies > 1) copies_ = scene::replicate(base_.scene, settings_.copies, copyAxes());
    settings_.componentParts = source.parts == "components";
    sceneChanged(true);
    error_.clear();
    std::printf("idview: opened: %s (%zu objects, %u parts, %llu triangles)\n",
                base_.source.c_str(), scene().objects.size(), scene().uniquePartCount(),
                static_cast<unsigned long long>(scene().drawnTriangleCount()));
    std::fflush(stdout);
    return true;
}

// A count that cannot fit (IDs, host or GPU memory) is refused in the panel; the scene drawn
// before stays (Renderer::setScene uploads the new scene before letting go of the old).
bool Viewer::setCopies(uint32_t copies) {
    const uint32_t before = settings_.copies;
    std::optional<scene::Scene> next;
    bool swapped = false;
    try {
        if (copies > 1) {
            checkCopiesFit(base_.scene, copies);
            next = scene::replicate(base_.scene, copies, copyAxes());
        }
        vk::check(vkDeviceWaitIdle(device_.handle()), "vkDeviceWaitIdle");
        std::swap(copies_, next); // `next` now holds the previous copies
        swapped = true;
        settings_.copies = copies;
        sceneChanged(false);
        return true;
    } catch (const std::exception& e) {
        error_ = e.what();
        std::fprintf(stderr, "idview: %s\n", error_.c_str());
        if (swapped) std::swap(copies_, next);
        settings_.copies = before;
        return false;
    }
}

void Viewer::sceneChanged(bool newModel) {
    selection_.clear(); // part IDs name parts of the old scene
    pendingClick_.reset();
    pickingSince_.reset(); // and so do picks still in flight
    if (rig_) {
        rig_->renderer.setScene(scene());
        rig_->renderer.configure(scene(), renderConfig(settings_, options_));
    }
    idBytes_ = scene::idDataBytes(scene(), settings_.searchBatch);
    if (!newModel) {
        camera_.setBounds(scene().bounds()); // more copies: same view, planes follow
        return;
    }
    scene::Camera initial = initialCamera(base_, aspect());
    if (copies_) // the opening view of copy 0, drawn back to take in every copy
        initial = scene::fitCamera(scene().bounds(), initial.eye - initial.target, initial.up,
                                   initial.fovY, aspect());
    camera_ = OrbitCamera(initial, scene().bounds());
}

} // namespace app
