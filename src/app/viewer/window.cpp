// window.cpp - GLFW set-up, the window and its callbacks.
#include "app/viewer/window.h"

#include <algorithm>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>

#include "app/viewer/input.h"
#include "vk/check.h"

namespace app {
namespace {

std::string glfwProblem = "unknown GLFW error";
// Events the window has had (input, focus, exposure, resize): the viewer draws a frame after
// each, so that the panel and the picture follow, and otherwise rests (Window::events).
uint64_t windowEvents = 0;

Input& inputOf(GLFWwindow* window) {
    return *static_cast<Input*>(glfwGetWindowUserPointer(window));
}

// Exceptions must not cross GLFW's C frames: keep them for the loop to rethrow.
template <typename Fn>
void guarded(GLFWwindow* window, Fn&& handler) {
    ++windowEvents;
    try {
        handler(inputOf(window));
    } catch (...) {
        inputOf(window).fail(std::current_exception());
    }
}

} // namespace

Window::Library::Library() {
    glfwSetErrorCallback([](int, const char* text) { glfwProblem = text; });
    if (!glfwInit())
        throw vk::Error("cannot open a window: " + glfwProblem +
                        " (is DISPLAY set? use --headless to render without one)");
}

Window::Library::~Library() {
    glfwTerminate();
}

Window::Window(uint32_t width, uint32_t height) {
    if (!glfwVulkanSupported())
        throw vk::Error("cannot open a window: GLFW finds no Vulkan loader");
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API); // Vulkan, not OpenGL
    window_ = glfwCreateWindow(int(width), int(height), "idview", nullptr, nullptr);
    if (!window_) throw vk::Error("cannot open a window: " + glfwProblem);
}

Window::~Window() {
    glfwDestroyWindow(window_);
}

std::vector<const char*> Window::vulkanExtensions() const {
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) throw vk::Error("cannot open a window: " + glfwProblem);
    return {names, names + count};
}

VkSurfaceKHR Window::createSurface(const vk::Instance& instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    vk::check(glfwCreateWindowSurface(instance.handle(), window_, nullptr, &surface),
              "glfwCreateWindowSurface");
    return surface;
}

void Window::listen(Input& input) {
    GLFWwindow* w = window_;
    glfwSetWindowUserPointer(w, &input);
    glfwSetKeyCallback(w, [](GLFWwindow* w, int key, int code, int action, int mods) {
        guarded(w, [&](Input& in) { in.onKey(key, code, action, mods); });
    });
    glfwSetCursorPosCallback(w, [](GLFWwindow* w, double x, double y) {
        guarded(w, [&](Input& in) { in.onCursor(x, y); });
    });
    glfwSetMouseButtonCallback(w, [](GLFWwindow* w, int button, int action, int mods) {
        guarded(w, [&](Input& in) { in.onButton(button, action, mods); });
    });
    glfwSetScrollCallback(w, [](GLFWwindow* w, double dx, double dy) {
        guarded(w, [&](Input& in) { in.onScroll(dx, dy); });
    });
    glfwSetDropCallback(w, [](GLFWwindow* w, int count, const char** paths) {
        guarded(w, [&](Input& in) {
            for (int i = 0; i < count; ++i) in.onDrop(paths[i]);
        });
    });
    glfwSetCharCallback(w, [](GLFWwindow* w, unsigned int c) {
        ++windowEvents;
        ImGui_ImplGlfw_CharCallback(w, c);
    });
    glfwSetWindowFocusCallback(w, [](GLFWwindow* w, int focused) {
        ++windowEvents;
        ImGui_ImplGlfw_WindowFocusCallback(w, focused);
    });
    glfwSetCursorEnterCallback(w, [](GLFWwindow* w, int entered) {
        ++windowEvents;
        ImGui_ImplGlfw_CursorEnterCallback(w, entered);
    });
    glfwSetWindowRefreshCallback(w, [](GLFWwindow*) { ++windowEvents; });
    glfwSetFramebufferSizeCallback(w, [](GLFWwindow*, int, int) { ++windowEvents; });
}

void Window::wake() {
    glfwPostEmptyEvent();
}

uint64_t Window::events() const {
    return windowEvents;
}

void Window::stopListening() {
    glfwSetWindowUserPointer(window_, nullptr);
    glfwSetKeyCallback(window_, nullptr);
    glfwSetCursorPosCallback(window_, nullptr);
    glfwSetMouseButtonCallback(window_, nullptr);
    glfwSetScrollCallback(window_, nullptr);
    glfwSetDropCallback(window_, nullptr);
    glfwSetCharCallback(window_, nullptr);
    glfwSetWindowFocusCallback(window_, nullptr);
    glfwSetCursorEnterCallback(window_, nullptr);
    glfwSetWindowRefreshCallback(window_, nullptr);
    glfwSetFramebufferSizeCallback(window_, nullptr);
}

VkExtent2D Window::framebufferSize() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return {uint32_t(std::max(width, 0)), uint32_t(std::max(height, 0))};
}

bool Window::closing() const {
    return glfwWindowShouldClose(window_);
}

void Window::close() {
    glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void Window::setTitle(const std::string& title) {
    glfwSetWindowTitle(window_, title.c_str());
}

void Window::pollEvents() {
    glfwPollEvents();
}

void Window::waitEvents(std::optional<double> timeout) {
    if (timeout)
        glfwWaitEventsTimeout(*timeout);
    else
        glfwWaitEvents();
}

} // namespace app
