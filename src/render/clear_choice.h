// clear_choice.h - ClearPath::Auto made concrete: both clear paths timed on this device, once
// per MSAA setting, and remembered beside the driver's pipeline cache in a file named for the
// device and driver (as the pipeline cache's is), so that a new driver times them again.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include <vulkan/vulkan.h>

#include "render/pipeline_file.h"
#include "render/settings.h"

namespace render {

// The size both paths are timed at: a full-HD frame, large enough that what a clear or a
// resolve costs per pixel dominates a dispatch's or a pass's fixed overhead, small enough to
// time in a blink on a software rasterizer.
constexpr uint32_t clearTimingWidth = 1920, clearTimingHeight = 1080;

// What the timing of one MSAA setting found: the median GPU time of a frame that draws
// nothing, from the first command to the resolved images, on each path.
struct ClearTiming {
    uint32_t samples = 1;
    double passMs = 0.0, computeMs = 0.0;
    bool remembered = false; // read from the file, not timed in this run
    ClearPath faster() const { return computeMs < passMs ? ClearPath::Compute : ClearPath::Pass; }
};

// The timings file's name for `identity`: "clear-paths-<vendor>-<device>-<UUID>.txt".
std::string clearTimingFileName(const PipelineCacheIdentity& identity);
// Its text and back; a file of another driver version or format reads as empty.
std::string encodeClearTimings(const PipelineCacheIdentity& identity,
                               const std::map<uint32_t, ClearTiming>& timings);
std::map<uint32_t, ClearTiming> decodeClearTimings(const std::string& text,
                                                   const PipelineCacheIdentity& identity);

} // namespace render
