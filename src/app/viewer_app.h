// viewer_app.h - the viewer's state. Set-up and the loop are in viewer.cpp, one frame in
// viewer_frame.cpp, input and scripts in viewer_input.cpp, settings and scene changes in
// viewer_scene.cpp. Internal to the viewer.
#pragma once

#include <array>
#include <chrono>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "app/cli.h"
#include "app/input_script.h"
#include "app/orbit_camera.h"
#include "app/scene_source.h"
#include "app/selection.h"
#include "app/viewer_blit.h"
#include "app/viewer_imgui.h"
#include "app/viewer_ui.h"
#include "render/frame_slots.h"
#include "render/renderer.h"
#include "render/targets.h"
#include "scene/copies.h"
#include "vk/shader_compiler.h"
#include "vk/swapchain.h"

struct GLFWwindow;

namespace app {

// The scene pass, its targets and the renderer that records into them: one set per MSAA
// setting, rebuilt together when the sample count changes.
struct SceneRig {
    SceneRig(vk::Device& device, const vk::ShaderCompiler& compiler, VkSampleCountFlagBits samples,
             VkExtent2D extent)
        : pass(device, samples),
          targets(std::make_unique<render::SceneTargets>(device, pass, extent)),
          renderer(device, compiler, pass) {}
    render::ScenePass pass;
    std::unique_ptr<render::SceneTargets> targets; // remade at the window's size
    render::Renderer renderer;
};

// The frame slots' acquire semaphores: slot i's is free again once its fence has signalled.
struct AcquireSemaphores {
    explicit AcquireSemaphores(vk::Device& device);
    ~AcquireSemaphores();
    AcquireSemaphores(const AcquireSemaphores&) = delete;
    AcquireSemaphores& operator=(const AcquireSemaphores&) = delete;
    vk::Device& device;
    std::array<VkSemaphore, render::FrameSlots::count> handles{};
};

class Viewer {
  public:
    Viewer(const Options& options, GLFWwindow* window, vk::Instance& instance, ScriptPlayer script);
    ~Viewer();
    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    void run();

    // Input handlers: GLFW's callbacks and the script both end here.
    void onKey(int key, int scancode, int action, int mods);
    void onCursor(double x, double y);
    void onButton(int button, int action, int mods);
    void onScroll(double dx, double dy);
    void onDrop(const std::string& path);
    // A handler threw inside a GLFW callback (C code): the loop stops and rethrows it.
    void fail(std::exception_ptr error);

  private:
    using Clock = std::chrono::steady_clock;

    // viewer_frame.cpp: the frame.
    bool recreateSwapchain();
    void drawFrame(double seconds);
    void updatePicking();
    void reportSelection() const;
    std::optional<glm::uvec2> pickPixel() const;
    std::optional<glm::vec2> cursorInWindow() const;
    PanelInfo panelInfo() const;
    void updateTitle(double seconds, bool now);
    void waitForEvents(double seconds); // viewer.cpp: a minimised window sleeps

    // viewer_input.cpp and viewer_scene.cpp: scripts, settings, scenes.
    void runScript(double seconds);
    void queueCommand(const ScriptCommand& command);
    void openDroppedFiles();
    void applySettings(const ViewerSettings& wanted);
    void configure(const ViewerSettings& wanted);
    void reloadShaders(); // R: recompile from shaders/, keep the last good pipeline on error
    void buildRig(uint32_t samples);
    void setMsaa(uint32_t samples);
    bool openScene(const Options& source);
    bool setCopies(uint32_t copies); // false: refused, the error is in the panel
    uint32_t copyAxes() const { return settings_.copyAxes; }
    void sceneChanged(bool newModel);
    const scene::Scene& scene() const { return copies_ ? *copies_ : base_.scene; }
    float aspect() const;
    double elapsed() const; // seconds since the first frame

    Options options_;
    GLFWwindow* window_;
    vk::Instance& instance_;
    vk::Surface surface_;
    vk::Device device_;
    vk::ShaderCompiler compiler_;
    vk::Swapchain swapchain_;
    render::FrameSlots slots_;
    AcquireSemaphores acquired_;
    std::unique_ptr<SceneRig> rig_;
    std::unique_ptr<ImGuiLayer> ui_;
    std::unique_ptr<WindowCapture> capture_;

    LoadedScene base_;                   // as loaded, one copy
    std::optional<scene::Scene> copies_; // with model copies, when more than one
    ViewerSettings settings_;
    VkSampleCountFlags sampleCounts_ = VK_SAMPLE_COUNT_1_BIT;
    OrbitCamera camera_;
    Selection selection_;
    float hoveredDepth_ = 1.0f, selectedDepth_ = 1.0f;
    std::string error_;
    scene::IdDataBytes idBytes_;
    std::exception_ptr failure_;

    // Input state.
    glm::dvec2 cursor_{-1.0, -1.0};
    struct Drag {
        int button;
        bool pan;
        glm::dvec2 start;
        double moved; // farthest distance from the start, in window pixels
    };
    std::optional<Drag> drag_;
    std::optional<uint64_t> pendingClick_; // the frame whose pick the click selects from
    std::optional<uint64_t> pickingSince_; // first frame of the current run of picks
    std::vector<std::string> drops_;       // dropped files, opened between frames
    bool panelVisible_ = true;
    bool swapchainDirty_ = true;

    // Script: commands and the steps of multi-frame ones (a click is a move, then the
    // press and release a frame later, as a hand would do it).
    struct Step {
        std::function<void()> run;
        bool endsFrame; // the next step waits for a frame, as a hand would
    };
    ScriptPlayer script_;
    std::deque<Step> steps_;
    std::string screenshotPath_;

    // Frame timing.
    uint64_t frameNumber_ = 0;
    std::optional<Clock::time_point> start_;
    std::deque<double> cpuRecordMs_;
    double titleTime_ = 0.0, fps_ = 0.0;
    uint64_t titleFrame_ = 0;
    std::string title_;
};

} // namespace app
