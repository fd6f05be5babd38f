// check.cpp - VkResult names for error messages.
#include "vk/check.h"

#include <atomic>

namespace vk {

const char* resultName(VkResult result) {
    switch (result) {
#define IDV_RESULT(r)                                                                              \
    case r:                                                                                        \
        return #r;
        IDV_RESULT(VK_SUCCESS)
        IDV_RESULT(VK_NOT_READY)
        IDV_RESULT(VK_TIMEOUT)
        IDV_RESULT(VK_INCOMPLETE)
        IDV_RESULT(VK_SUBOPTIMAL_KHR)
        IDV_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
        IDV_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        IDV_RESULT(VK_ERROR_INITIALIZATION_FAILED)
        IDV_RESULT(VK_ERROR_DEVICE_LOST)
        IDV_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
        IDV_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
        IDV_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
        IDV_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
        IDV_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
        IDV_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
        IDV_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
        IDV_RESULT(VK_ERROR_FRAGMENTED_POOL)
        IDV_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
        IDV_RESULT(VK_ERROR_SURFACE_LOST_KHR)
        IDV_RESULT(VK_ERROR_OUT_OF_DATE_KHR)
        IDV_RESULT(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
#undef IDV_RESULT
    default:
        return "unknown VkResult";
    }
}

void check(VkResult result, const char* what) {
    if (result == VK_SUCCESS) return;
    if (result == VK_ERROR_DEVICE_LOST)
        throw Error(std::string("the GPU was lost during ") + what +
                    " (VK_ERROR_DEVICE_LOST: a driver crash, a GPU reset or a removed device); "
                    "idview cannot continue");
    throw Error(std::string(what) + " failed: " + resultName(result) + " (" +
                std::to_string(static_cast<int>(result)) + ")");
}

namespace {
std::atomic<uint32_t> faultCountdown{0}; // 0: off
std::atomic<uint32_t> faultPasses{0};
} // namespace

void faultPoint(const char* what) {
    if (faultCountdown.load(std::memory_order_relaxed) == 0) return;
    faultPasses.fetch_add(1);
    if (faultCountdown.fetch_sub(1) == 1) throw Error(std::string("injected fault at ") + what);
}

void failAfter(uint32_t calls) {
    faultPasses = 0;
    faultCountdown = calls;
}

uint32_t faultPointsPassed() {
    return faultPasses.load();
}

} // namespace vk
