// pipeline_file.h - the file the driver's pipeline cache is kept in between runs
// (render/disk_pipeline_cache.h): what names it, and its bytes. The driver's blob goes behind
// a header of idview's own, so that a file of another device or driver, of another format
// version, cut short or damaged is told from a good one before the driver sees a byte of it.
// Plain functions over bytes, unit-tested without a GPU.
//
// File layout (host byte order, 56 bytes before the blob): "idviewPC" (8 bytes), format
// version (u32), vendorID, deviceID, driverVersion (u32 each), pipelineCacheUUID (16 bytes),
// blob size (u64), blob checksum (u64, util::hash64), blob (what vkGetPipelineCacheData
// gave, starting with the driver's VkPipelineCacheHeaderVersionOne).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vulkan/vulkan.h>

namespace render {

// Bumped whenever the layout above changes.
constexpr uint32_t kPipelineFileVersion = 1;
constexpr size_t kPipelineFileHeaderBytes = 56;

// What a driver's pipeline cache data is only valid for.
struct PipelineCacheIdentity {
    uint32_t vendorId = 0;
    uint32_t deviceId = 0;
    uint32_t driverVersion = 0;
    std::array<uint8_t, VK_UUID_SIZE> uuid{};
    bool operator==(const PipelineCacheIdentity&) const = default;
};

PipelineCacheIdentity pipelineCacheIdentity(VkPhysicalDevice device);

// "pipelines-<vendor>-<device>-<UUID>.bin", in hexadecimal: one file per device and driver
// build, so that two GPUs (or a GPU and lavapipe) do not overwrite each other's.
std::string pipelineFileName(const PipelineCacheIdentity& identity);

// The file's bytes for the driver's `blob`.
std::string encodePipelineFile(const PipelineCacheIdentity& identity, std::string_view blob);

// The blob inside `file` (a view into it), or nullopt with `why` ("truncated", "checksum
// mismatch", "made by another device or driver", ...) when the file is not to be handed to
// the driver: idview's header and the driver's own must both match `identity`.
std::optional<std::string_view>
decodePipelineFile(std::string_view file, const PipelineCacheIdentity& identity, std::string& why);

} // namespace render
