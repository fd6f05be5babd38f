// check.h - VkResult checking that stays on in release builds, and the error type it throws.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>
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

// Fault injection for the tests: every place idview creates a Vulkan object, allocates device
// memory, compiles a shader or submits an upload calls faultPoint() first. After
// failAfter(n), the n-th such call from then on throws Error("injected fault at ..."), so a
// test can prove that a throw at any of those points leaks nothing. Off (and one relaxed
// atomic load) unless a test arms it.
void faultPoint(const char* what);
void failAfter(uint32_t calls); // 0 disarms
// Calls to faultPoint() since the last failAfter(), for tests that count the points.
uint32_t faultPointsPassed();

} // namespace vk

namespace vk {

// Vulkan's two-call enumeration, count first, then the values: `call(&count, data)` is the
// Vulkan function with its other arguments bound.
template <typename T, typename Call>
std::vector<T> enumerate(const char* what, Call&& call) {
    uint32_t count = 0;
    check(call(&count, nullptr), what);
    std::vector<T> values(count);
    check(call(&count, values.data()), what);
    values.resize(count);
    return values;
}

// A zeroed Vulkan struct with its sType set: `auto info = vk::init<VkFenceCreateInfo>(...)`.
// (Brace-initialising only sType trips -Wmissing-field-initializers.)
template <typename T>
T init(VkStructureType type) {
    T value{};
    value.sType = type;
    return value;
}

} // namespace vk
