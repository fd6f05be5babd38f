// test_pipeline_file.cpp - the pipeline cache file's header (render/pipeline_file.h), without
// a GPU: a file round-trips to the very blob, and each way a file can be wrong (another
// device or driver, another format, cut short, a flipped byte, a wrong checksum, a driver
// header of another device) is rejected with its reason.
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "render/pipeline_file.h"

namespace {

using namespace render;

PipelineCacheIdentity identity() {
    PipelineCacheIdentity id;
    id.vendorId = 0x10de;
    id.deviceId = 0x2330;
    id.driverVersion = 0x8a1c4000;
    for (uint8_t i = 0; i < VK_UUID_SIZE; ++i) id.uuid[i] = uint8_t(0xa0 + i);
    return id;
}

// What a driver would hand out: its VkPipelineCacheHeaderVersionOne for `id`, then `payload`.
std::string driverBlob(const PipelineCacheIdentity& id, const std::string& payload) {
    VkPipelineCacheHeaderVersionOne h{};
    h.headerSize = sizeof h;
    h.headerVersion = VK_PIPELINE_CACHE_HEADER_VERSION_ONE;
    h.vendorID = id.vendorId;
    h.deviceID = id.deviceId;
    std::memcpy(h.pipelineCacheUUID, id.uuid.data(), VK_UUID_SIZE);
    return std::string(reinterpret_cast<const char*>(&h), sizeof h) + payload;
}

const std::string kPayload = "compiled pipelines, as the driver keeps them";

// Why `file` is rejected for identity(), or "accepted".
std::string verdict(const std::string& file) {
    std::string why;
    return decodePipelineFile(file, identity(), why) ? "accepted" : why;
}

TEST(PipelineFile, RoundTripsTheDriversBlob) {
    const std::string blob = driverBlob(identity(), kPayload);
    const std::string file = encodePipelineFile(identity(), blob);
    ASSERT_EQ(file.size(), kPipelineFileHeaderBytes + blob.size());
    EXPECT_EQ(file.substr(0, 8), "idviewPC");
    std::string why;
    const auto decoded = decodePipelineFile(file, identity(), why);
    ASSERT_TRUE(decoded) << why;
    EXPECT_EQ(*decoded, blob);
}

TEST(PipelineFile, NameSaysDeviceAndCacheUuid) {
    EXPECT_EQ(pipelineFileName(identity()),
              "pipelines-10de-2330-a0a1a2a3a4a5a6a7a8a9aaabacadaeaf.bin");
}

TEST(PipelineFile, AnotherDeviceOrDriverIsRejected) {
    const std::string blob = driverBlob(identity(), kPayload);
    PipelineCacheIdentity other = identity();
    other.uuid[7] ^= 1;
    EXPECT_EQ(verdict(encodePipelineFile(other, blob)), "made by another device or driver");
    other = identity();
    other.driverVersion += 1;
    EXPECT_EQ(verdict(encodePipelineFile(other, blob)), "made by another device or driver");
    other = identity();
    other.deviceId += 1;
    EXPECT_EQ(verdict(encodePipelineFile(other, blob)), "made by another device or driver");
}

TEST(PipelineFile, DriverHeaderOfAnotherDeviceIsRejected) {
    // Our header right and its checksum over the blob right: only the driver's header lies.
    PipelineCacheIdentity other = identity();
    other.uuid[0] ^= 0x80;
    EXPECT_EQ(verdict(encodePipelineFile(identity(), driverBlob(other, kPayload))),
              "the driver's header names another device");
    std::string blob = driverBlob(identity(), kPayload);
    blob[4] = 7; // headerVersion
    EXPECT_EQ(verdict(encodePipelineFile(identity(), blob)), "unknown driver header");
    blob = driverBlob(identity(), kPayload);
    blob[0] = 8; // headerSize below the header's own
    EXPECT_EQ(verdict(encodePipelineFile(identity(), blob)), "bad driver header size");
    EXPECT_EQ(verdict(encodePipelineFile(identity(), "short")), "the driver's header is cut short");
}

TEST(PipelineFile, TruncatedFilesAreRejected) {
    const std::string file = encodePipelineFile(identity(), driverBlob(identity(), kPayload));
    EXPECT_EQ(verdict(""), "truncated (0 bytes, shorter than the header)");
    EXPECT_EQ(verdict(file.substr(0, kPipelineFileHeaderBytes - 1)),
              "truncated (55 bytes, shorter than the header)");
    const size_t blob = file.size() - kPipelineFileHeaderBytes;
    EXPECT_EQ(verdict(file.substr(0, file.size() - 10)), "truncated (" + std::to_string(blob - 10) +
                                                             " of " + std::to_string(blob) +
                                                             " bytes)");
    EXPECT_EQ(verdict(file + "xy"), "2 bytes after the data");
}

TEST(PipelineFile, EveryFlippedBlobByteFailsTheChecksum) {
    const std::string file = encodePipelineFile(identity(), driverBlob(identity(), kPayload));
    for (size_t i = kPipelineFileHeaderBytes; i < file.size(); ++i) {
        std::string damaged = file;
        damaged[i] ^= 0x10;
        EXPECT_EQ(verdict(damaged), "checksum mismatch") << "byte " << i;
    }
    std::string wrongSum = file;
    wrongSum[kPipelineFileHeaderBytes - 1] ^= 1; // the checksum's last byte
    EXPECT_EQ(verdict(wrongSum), "checksum mismatch");
}

TEST(PipelineFile, OtherFilesAndFormatsAreRejected) {
    std::string file = encodePipelineFile(identity(), driverBlob(identity(), kPayload));
    std::string magic = file;
    magic[6] = 'T'; // a tessellation cache entry's magic
    EXPECT_EQ(verdict(magic), "not an idview pipeline cache");
    file[8] = char(kPipelineFileVersion + 1);
    EXPECT_EQ(verdict(file), "format version " + std::to_string(kPipelineFileVersion + 1) +
                                 ", not " + std::to_string(kPipelineFileVersion));
}

} // namespace
