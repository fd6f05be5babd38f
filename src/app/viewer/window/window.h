// window.h - the GLFW window: the library's lifetime, the window, its Vulkan surface and the
// callbacks that hand every event to the viewer's Input. Errors say what is missing (no
// display, no Vulkan loader) in one line.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/context.h"

struct GLFWwindow;

namespace app {

class Input;

class Window {
  public:
    // At `position` (screen coordinates of its top left corner) when given, pulled inside the
    // work area of the monitor it lies on (the primary one when none), so a position kept
    // from another screen layout never puts it out of reach.
    Window(uint32_t width, uint32_t height, std::optional<std::array<int, 2>> position = {});
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }
    // The instance extensions a surface for this window needs.
    std::vector<const char*> vulkanExtensions() const;
    VkSurfaceKHR createSurface(const vk::Instance& instance) const;

    // From now on GLFW's callbacks go to `input`, until stopListening().
    void listen(Input& input);
    void stopListening();

    VkExtent2D framebufferSize() const;
    // The window's size and its top left corner, in screen coordinates (for --size and
    // --window-pos next time).
    std::array<int, 2> size() const;
    std::array<int, 2> position() const;
    bool closing() const;
    void close();
    void setTitle(const std::string& title);
    // Wakes a loop sleeping in waitEvents(); any thread may call it.
    static void wake();
    // How many events the window has had since it opened (input, focus, exposure, resize).
    uint64_t events() const;
    void pollEvents();
    // Sleeps until an event comes, or `timeout` seconds at most.
    void waitEvents(std::optional<double> timeout);

  private:
    struct Library { // glfwInit and glfwTerminate
        Library();
        ~Library();
    };
    Library library_;
    GLFWwindow* window_ = nullptr;
};

} // namespace app
