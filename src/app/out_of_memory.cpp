// out_of_memory.cpp - the words of an out-of-memory refusal.
#include "app/out_of_memory.h"

#include <cstdio>
#include <filesystem>

namespace app {

std::string grouped(uint64_t count) {
    const std::string digits = std::to_string(count);
    std::string text;
    for (size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) text += ',';
        text += digits[i];
    }
    return text;
}

std::string loadingWhat(const std::string& path) {
    std::error_code unknown;
    const uintmax_t bytes = std::filesystem::file_size(path, unknown);
    if (unknown) return "loading it";
    char size[32];
    std::snprintf(size, sizeof size, "%.1f MB", double(bytes) / 1e6);
    return std::string("loading it (") + size + ")";
}

std::string levelsWhat(uint32_t levels, const scene::Scene& scene) {
    return "building " + std::to_string(levels) + " levels of detail of " +
           grouped(scene.geometries.size()) + " geometries";
}

std::string copiesWhat(uint32_t copies, const scene::Scene& scene) {
    return "making " + grouped(copies) + " copies (" +
           grouped(uint64_t(copies) * scene.objects.size()) + " objects)";
}

std::string uploadWhat(const scene::Scene& scene) {
    return "uploading " + grouped(scene.objects.size()) + " objects of " +
           grouped(scene.geometries.size()) + " geometries (" + grouped(scene.indices.size() / 3) +
           " triangles)";
}

} // namespace app
