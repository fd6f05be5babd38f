// pipeline_cache_file.cpp - where the pipeline cache lives and its save at exit.
#include "app/pipeline_cache_file.h"

#include <cstdio>
#include <string>

#include "util/cache_file.h"

namespace app {

std::filesystem::path pipelineCacheFolder(const SceneSettings& scene) {
    return scene.cadCache ? util::cacheFolder() : std::filesystem::path{};
}

void savePipelineCache(const render::Renderer& renderer) {
    if (const std::string error = renderer.driverCache().save(); !error.empty())
        std::fprintf(stderr, "idview: warning: pipeline cache not saved: %s\n", error.c_str());
}

} // namespace app
