// debug.cpp - VK_EXT_debug_utils entry points for names and labels.
#include "vk/debug.h"

#include "vk/check.h"

namespace vk {

void DebugUtils::load(VkInstance instance) {
    setObjectName = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance, "vkSetDebugUtilsObjectNameEXT"));
    beginLabel = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance, "vkCmdBeginDebugUtilsLabelEXT"));
    endLabel = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance, "vkCmdEndDebugUtilsLabelEXT"));
}

void DebugUtils::name(VkDevice device, VkObjectType type, uint64_t handle, const char* text) const {
    if (!setObjectName || handle == 0) return;
    auto info =
        vk::init<VkDebugUtilsObjectNameInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT);
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = text;
    check(setObjectName(device, &info), "vkSetDebugUtilsObjectNameEXT");
}

CmdLabel::CmdLabel(const DebugUtils& debug, VkCommandBuffer cmd, const char* text)
    : debug_(debug), cmd_(cmd) {
    if (!debug_.beginLabel) return;
    auto label = vk::init<VkDebugUtilsLabelEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT);
    label.pLabelName = text;
    debug_.beginLabel(cmd_, &label);
}

CmdLabel::~CmdLabel() {
    if (debug_.endLabel) debug_.endLabel(cmd_);
}

} // namespace vk
