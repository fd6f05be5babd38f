// pipeline_cache_file.h - the driver's pipeline cache kept between runs, for headless runs and
// the viewer alike.
#pragma once

#include <filesystem>

#include "app/live_settings.h"
#include "render/renderer.h"

namespace app {

// Where the driver's pipeline cache is kept between runs: scene::cacheFolder(), nothing
// (memory only) with --no-cache.
std::filesystem::path pipelineCacheFolder(const SceneSettings& scene);
// At exit (headless and the viewer), so that the next start finds what this run compiled: a
// file that cannot be written is a warning on stderr, as it costs only the next start time.
void savePipelineCache(const render::Renderer& renderer);

} // namespace app
