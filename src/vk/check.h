// check.h - VkResult checking that stays on in release builds, and the error type it throws.
#pragma once

#include <stdexcept>
#include <string>
#include <vulkan/vulkan.h>

namespace vk {

// Thrown for any failure the program cannot continue from; main() prints what() and exits 1.
struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

const char* resultName(VkResult result);

// Throws Error("<what> failed: VK_ERROR_...") unless result is VK_SUCCESS. Calls that have
// other expected results (VK_NOT_READY, VK_SUBOPTIMAL_KHR, ...) handle them at the call site.
void check(VkResult result, const char* what);

} // namespace vk

namespace vk {

// A zeroed Vulkan struct with its sType set: `auto info = vk::init<VkFenceCreateInfo>(...)`.
// (Brace-initialising only sType trips -Wmissing-field-initializers.)
template <typename T>
T init(VkStructureType type) {
    T value{};
    value.sType = type;
    return value;
}

} // namespace vk
