// pipeline_file.cpp - the pipeline cache file's header, written and checked (pipeline_file.h).
#include "render/pipeline_file.h"

#include <cstdio>
#include <cstring>

#include "util/hash64.h"

namespace render {

namespace {

constexpr char kMagic[8] = {'i', 'd', 'v', 'i', 'e', 'w', 'P', 'C'};

// The header as it lies in the file: every field at its natural alignment, no padding.
struct FileHeader {
    char magic[8];
    uint32_t version;
    uint32_t vendorId;
    uint32_t deviceId;
    uint32_t driverVersion;
    uint8_t uuid[VK_UUID_SIZE];
    uint64_t blobSize;
    uint64_t checksum;
};
static_assert(sizeof(FileHeader) == kPipelineFileHeaderBytes);
static_assert(sizeof(VkPipelineCacheHeaderVersionOne) == 32);

bool sameDevice(const FileHeader& h, const PipelineCacheIdentity& id) {
    return h.vendorId == id.vendorId && h.deviceId == id.deviceId &&
           h.driverVersion == id.driverVersion &&
           std::memcmp(h.uuid, id.uuid.data(), VK_UUID_SIZE) == 0;
}

// The driver's own header at the blob's start (the specification fixes its layout), so that
// a blob whose checksum holds but which another driver wrote never reaches this one.
const char* driverHeaderMismatch(std::string_view blob, const PipelineCacheIdentity& id) {
    VkPipelineCacheHeaderVersionOne h;
    if (blob.size() < sizeof h) return "the driver's header is cut short";
    std::memcpy(&h, blob.data(), sizeof h);
    if (h.headerVersion != VK_PIPELINE_CACHE_HEADER_VERSION_ONE) return "unknown driver header";
    if (h.headerSize < sizeof h || h.headerSize > blob.size()) return "bad driver header size";
    if (h.vendorID != id.vendorId || h.deviceID != id.deviceId ||
        std::memcmp(h.pipelineCacheUUID, id.uuid.data(), VK_UUID_SIZE) != 0)
        return "the driver's header names another device";
    return nullptr;
}

} // namespace

PipelineCacheIdentity pipelineCacheIdentity(VkPhysicalDevice device) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(device, &props);
    PipelineCacheIdentity id;
    id.vendorId = props.vendorID;
    id.deviceId = props.deviceID;
    id.driverVersion = props.driverVersion;
    std::memcpy(id.uuid.data(), props.pipelineCacheUUID, VK_UUID_SIZE);
    return id;
}

std::string pipelineFileName(const PipelineCacheIdentity& id) {
    char head[48];
    std::snprintf(head, sizeof head, "pipelines-%04x-%04x-", id.vendorId, id.deviceId);
    std::string name = head;
    for (uint8_t byte : id.uuid) {
        char hex[3];
        std::snprintf(hex, sizeof hex, "%02x", byte);
        name += hex;
    }
    return name + ".bin";
}

std::string encodePipelineFile(const PipelineCacheIdentity& id, std::string_view blob) {
    FileHeader h{};
    std::memcpy(h.magic, kMagic, sizeof kMagic);
    h.version = kPipelineFileVersion;
    h.vendorId = id.vendorId;
    h.deviceId = id.deviceId;
    h.driverVersion = id.driverVersion;
    std::memcpy(h.uuid, id.uuid.data(), VK_UUID_SIZE);
    h.blobSize = blob.size();
    h.checksum = util::hash64(blob.data(), blob.size());
    std::string file(reinterpret_cast<const char*>(&h), sizeof h);
    return file.append(blob);
}

std::optional<std::string_view>
decodePipelineFile(std::string_view file, const PipelineCacheIdentity& id, std::string& why) {
    FileHeader h;
    if (file.size() < sizeof h) {
        why = "truncated (" + std::to_string(file.size()) + " bytes, shorter than the header)";
        return std::nullopt;
    }
    std::memcpy(&h, file.data(), sizeof h);
    const std::string_view blob = file.substr(sizeof h);
    if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0)
        why = "not an idview pipeline cache";
    else if (h.version != kPipelineFileVersion)
        why = "format version " + std::to_string(h.version) + ", not " +
              std::to_string(kPipelineFileVersion);
    else if (!sameDevice(h, id))
        why = "made by another device or driver";
    else if (blob.size() < h.blobSize)
        why = "truncated (" + std::to_string(blob.size()) + " of " + std::to_string(h.blobSize) +
              " bytes)";
    else if (blob.size() > h.blobSize)
        why = std::to_string(blob.size() - h.blobSize) + " bytes after the data";
    else if (util::hash64(blob.data(), blob.size()) != h.checksum)
        why = "checksum mismatch";
    else if (const char* driver = driverHeaderMismatch(blob, id))
        why = driver;
    else
        return blob;
    return std::nullopt;
}

} // namespace render
