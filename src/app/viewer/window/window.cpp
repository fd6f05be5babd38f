// window.cpp - GLFW set-up, the window and its callbacks.
#include "app/viewer/window/window.h"

#include <algorithm>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>

#include "app/viewer/window/input.h"
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

// `position` moved just enough for a window of `size` to lie inside the work area (the
// screen less panels and docks) of the monitor whose area holds its top left corner, else of
// the primary monitor; its top left corner stays inside even when it is larger.
std::array<int, 2> onScreen(std::array<int, 2> position, std::array<int, 2> size) {
    int count = 0;
    GLFWmonitor** monitors = glfwGetMonitors(&count);
    GLFWmonitor* chosen = glfwGetPrimaryMonitor();
    for (int i = 0; i < count; ++i) {
        int x = 0, y = 0, w = 0, h = 0;
        glfwGetMonitorWorkarea(monitors[i], &x, &y, &w, &h);
        if (position[0] >= x && position[0] < x + w && position[1] >= y && position[1] < y + h)
            chosen = monitors[i];
    }
    if (!chosen) return position; // no monitor known: the window system decides
    int x = 0, y = 0, w = 0, h = 0;
    glfwGetMonitorWorkarea(chosen, &x, &y, &w, &h);
    return {std::clamp(position[0], x, x + std::max(w - size[0], 0)),
            std::clamp(position[1], y, y + std::max(h - size[1], 0))};
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

Window::Window(uint32_t width, uint32_t height, std::optional<std::array<int, 2>> position) {
    if (!glfwVulkanSupported())
        throw vk::Error("cannot open a window: GLFW finds no Vulkan loader");
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API); // Vulkan, not OpenGL
    // Placed before it shows, so it never appears first where the window manager put it.
    glfwWindowHint(GLFW_VISIBLE, position ? GLFW_FALSE : GLFW_TRUE);
    window_ = glfwCreateWindow(int(width), int(height), "idview", nullptr, nullptr);
    if (!window_) throw vk::Error("cannot open a window: " + glfwProblem);
    if (position) {
        const std::array<int, 2> at = onScreen(*position, {int(width), int(height)});
        glfwSetWindowPos(window_, at[0], at[1]);
        glfwShowWindow(window_);
    }
}

std::array<int, 2> Window::size() const {
    std::array<int, 2> size{};
    glfwGetWindowSize(window_, &size[0], &size[1]);
    return size;
}

std::array<int, 2> Window::position() const {
    std::array<int, 2> position{};
    glfwGetWindowPos(window_, &position[0], &position[1]);
    return position;
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
        guarded(w, [&](Input& in) { in.onFocus(focused == GLFW_TRUE); });
    });
    glfwSetCursorEnterCallback(w, [](GLFWwindow* w, int entered) {
        ++windowEvents;
        ImGui_ImplGlfw_CursorEnterCallback(w, entered);
        guarded(w, [&](Input& in) { in.onCursorEnter(entered == GLFW_TRUE); });
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
