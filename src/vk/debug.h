// debug.h - VK_EXT_debug_utils object names and command labels, so validation messages and
// GPU captures name things. Both are no-ops when the extension is not enabled.
#pragma once

#include <vulkan/vulkan.h>

namespace vk {

struct DebugUtils {
    PFN_vkSetDebugUtilsObjectNameEXT setObjectName = nullptr;
    PFN_vkCmdBeginDebugUtilsLabelEXT beginLabel = nullptr;
    PFN_vkCmdEndDebugUtilsLabelEXT endLabel = nullptr;

    void load(VkInstance instance);
    void name(VkDevice device, VkObjectType type, uint64_t handle, const char* name) const;

    template <typename Handle>
    void name(VkDevice device, VkObjectType type, Handle handle, const char* text) const {
        name(device, type, reinterpret_cast<uint64_t>(handle), text);
    }
};

// Opens a label on construction and closes it at scope end.
class CmdLabel {
  public:
    CmdLabel(const DebugUtils& debug, VkCommandBuffer cmd, const char* text);
    ~CmdLabel();
    CmdLabel(const CmdLabel&) = delete;
    CmdLabel& operator=(const CmdLabel&) = delete;

  private:
    const DebugUtils& debug_;
    VkCommandBuffer cmd_;
};

} // namespace vk
