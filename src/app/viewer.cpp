// viewer.cpp - the window and the Vulkan objects behind it, the callbacks that feed the input
// handlers, and the loop around the frames (viewer_frame.cpp).
#include "app/viewer.h"

#include <algorithm>
#include <cstdio>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>

#include "app/headless.h" // exitCode
#include "app/viewer_app.h"
#include "vk/check.h"

namespace app {
namespace {

std::string glfwProblem = "unknown GLFW error";

struct GlfwLibrary {
    GlfwLibrary() {
        glfwSetErrorCallback([](int, const char* text) { glfwProblem = text; });
        if (!glfwInit())
            throw vk::Error("cannot open a window: " + glfwProblem +
                            " (is DISPLAY set? use --headless to render without one)");
    }
    ~GlfwLibrary() { glfwTerminate(); }
};

struct Window {
    explicit Window(const Options& options) {
        if (!glfwVulkanSupported())
            throw vk::Error("cannot open a window: GLFW finds no Vulkan loader");
        glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API); // Vulkan, not OpenGL
        handle =
            glfwCreateWindow(int(options.width), int(options.height), "idview", nullptr, nullptr);
        if (!handle) throw vk::Error("cannot open a window: " + glfwProblem);
    }
    ~Window() { glfwDestroyWindow(handle); }
    GLFWwindow* handle = nullptr;
};

VkSurfaceKHR createSurface(const vk::Instance& instance, GLFWwindow* window) {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    vk::check(glfwCreateWindowSurface(instance.handle(), window, nullptr, &surface),
              "glfwCreateWindowSurface");
    return surface;
}

vk::DeviceInfo presentableDevice(const vk::Instance& instance, const std::string& request,
                                 VkSurfaceKHR surface) {
    const vk::DeviceInfo info = vk::chooseDevice(instance.devices(), request);
    vk::checkPresentSupport(info, surface);
    return info;
}

Viewer& self(GLFWwindow* window) {
    return *static_cast<Viewer*>(glfwGetWindowUserPointer(window));
}

// Exceptions must not cross GLFW's C frames: keep them for the loop to rethrow.
template <typename Fn>
void guarded(GLFWwindow* window, Fn&& handler) {
    try {
        handler(self(window));
    } catch (...) {
        self(window).fail(std::current_exception());
    }
}

void installCallbacks(GLFWwindow* w) {
    glfwSetKeyCallback(w, [](GLFWwindow* w, int key, int code, int action, int mods) {
        guarded(w, [&](Viewer& v) { v.onKey(key, code, action, mods); });
    });
    glfwSetCursorPosCallback(w, [](GLFWwindow* w, double x, double y) {
        guarded(w, [&](Viewer& v) { v.onCursor(x, y); });
    });
    glfwSetMouseButtonCallback(w, [](GLFWwindow* w, int button, int action, int mods) {
        guarded(w, [&](Viewer& v) { v.onButton(button, action, mods); });
    });
    glfwSetScrollCallback(w, [](GLFWwindow* w, double dx, double dy) {
        guarded(w, [&](Viewer& v) { v.onScroll(dx, dy); });
    });
    glfwSetDropCallback(w, [](GLFWwindow* w, int count, const char** paths) {
        guarded(w, [&](Viewer& v) {
            for (int i = 0; i < count; ++i) v.onDrop(paths[i]);
        });
    });
    glfwSetCharCallback(w, ImGui_ImplGlfw_CharCallback);
    glfwSetWindowFocusCallback(w, ImGui_ImplGlfw_WindowFocusCallback);
    glfwSetCursorEnterCallback(w, ImGui_ImplGlfw_CursorEnterCallback);
}

} // namespace

AcquireSemaphores::AcquireSemaphores(vk::Device& d) : device(d) {
    for (VkSemaphore& semaphore : handles) {
        auto info = vk::init<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
        VkResult result = vkCreateSemaphore(device.handle(), &info, nullptr, &semaphore);
        if (result != VK_SUCCESS) { // the destructor will not run: undo the ones made
            for (VkSemaphore made : handles)
                if (made) vkDestroySemaphore(device.handle(), made, nullptr);
            vk::check(result, "vkCreateSemaphore");
        }
        device.name(VK_OBJECT_TYPE_SEMAPHORE, semaphore, "image acquired");
    }
}

AcquireSemaphores::~AcquireSemaphores() {
    for (VkSemaphore& semaphore : handles)
        if (semaphore) vkDestroySemaphore(device.handle(), semaphore, nullptr);
    handles = {};
}

Viewer::Viewer(const Options& options, GLFWwindow* window, vk::Instance& instance,
               ScriptPlayer script)
    : options_(options), window_(window), instance_(instance),
      surface_(instance, createSurface(instance, window)),
      device_(instance, presentableDevice(instance, options.device, surface_.handle()),
              {VK_KHR_SWAPCHAIN_EXTENSION_NAME}),
      compiler_(vk::ShaderCompiler::locate(options.shaderDir)),
      swapchain_(device_, surface_.handle()), slots_(device_), acquired_(device_),
      script_(std::move(script)) {
    const auto& techniques = render::techniques();
    const auto& modes = render::drawModes();
    for (size_t i = 0; i < techniques.size(); ++i)
        if (options.renderer == techniques[i].name) settings_.technique = int(i);
    for (size_t i = 0; i < modes.size(); ++i)
        if (options.mode == modes[i].name) settings_.mode = int(i);
    settings_.searchBatch = options.searchBatch;
    settings_.partWeight = options.partWeight;
    settings_.colorizeDraws = options.colorizeDraws;
    settings_.ignoreMaterials = options.ignoreMaterials;
    settings_.nsearch = {options.nsearchN, options.nsearchGuess, options.nsearchLinear,
                         options.nsearchSteps};
    settings_.visible = options.visible;
    settings_.copies = options.copies;
    settings_.copyAxes = scene::parseCopyAxes(options.copyAxes); // checked by the CLI
    settings_.animate = options.animate;
    sampleCounts_ = render::supportedSampleCounts(device_);
    render::checkedSampleCount(device_, options.msaa); // one line naming what is offered

    if (!recreateSwapchain()) throw vk::Error("the window has no area to render to");
    ui_ = std::make_unique<ImGuiLayer>(window, instance, device_, swapchain_);
    if (!openScene(options)) throw vk::Error(error_); // at start, as headless: exit 1
    buildRig(options.msaa);
    glfwSetWindowUserPointer(window, this);
    installCallbacks(window);
}

Viewer::~Viewer() {
    // GLFW's window outlives the viewer: no callback may reach it any more.
    glfwSetWindowUserPointer(window_, nullptr);
    glfwSetKeyCallback(window_, nullptr);
    glfwSetCursorPosCallback(window_, nullptr);
    glfwSetMouseButtonCallback(window_, nullptr);
    glfwSetScrollCallback(window_, nullptr);
    glfwSetDropCallback(window_, nullptr);
    glfwSetCharCallback(window_, nullptr);
    glfwSetWindowFocusCallback(window_, nullptr);
    glfwSetCursorEnterCallback(window_, nullptr);
    vkDeviceWaitIdle(device_.handle()); // teardown: members go in reverse order after this
}

void Viewer::fail(std::exception_ptr error) {
    if (!failure_) failure_ = error;
    glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

double Viewer::elapsed() const {
    return start_ ? std::chrono::duration<double>(Clock::now() - *start_).count() : 0.0;
}

float Viewer::aspect() const {
    const VkExtent2D e = swapchain_.extent();
    return e.height ? float(e.width) / float(e.height) : float(options_.width) / options_.height;
}

void Viewer::run() {
    while (!glfwWindowShouldClose(window_) && !failure_) {
        glfwPollEvents();
        openDroppedFiles();
        int width = 0, height = 0;
        glfwGetFramebufferSize(window_, &width, &height);
        if (width == 0 || height == 0) { // minimised: render nothing, sleep until woken
            waitForEvents(elapsed());
            continue;
        }
        if (!start_) start_ = Clock::now();
        runScript(elapsed());
        if (glfwWindowShouldClose(window_) || failure_) break;
        const VkExtent2D extent = swapchain_.extent();
        if (swapchainDirty_ || extent.width != uint32_t(width) ||
            extent.height != uint32_t(height)) {
            if (!recreateSwapchain()) {
                waitForEvents(elapsed());
                continue;
            }
        }
        drawFrame(elapsed());
    }
    slots_.finish();
    if (failure_) std::rethrow_exception(failure_);
}

void Viewer::waitForEvents(double seconds) {
    // A script keeps its clock while the window is minimised.
    if (!steps_.empty())
        glfwWaitEventsTimeout(0.05);
    else if (auto next = script_.nextTime())
        glfwWaitEventsTimeout(std::clamp(*next - seconds, 0.01, 1.0));
    else
        glfwWaitEvents();
}

int runViewer(const Options& options) {
    // A bad script fails before any window opens.
    ScriptPlayer script(options.script.empty() ? std::vector<ScriptCommand>{}
                                               : loadScript(options.script));
    GlfwLibrary glfw;
    Window window(options);
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) throw vk::Error("cannot open a window: " + glfwProblem);
    vk::Instance instance({options.validation, std::vector<const char*>(names, names + count),
                           options.syncValidation});
    {
        Viewer viewer(options, window.handle, instance, std::move(script));
        viewer.run();
    }
    return exitCode(instance.validationMessages());
}

} // namespace app
