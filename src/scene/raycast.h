// raycast.h - the CPU reference for "which part is at this pixel": a brute-force ray cast
// against every triangle of the scene, used by tests to check what the GPU wrote.
#pragma once

#include <optional>

#include "scene/camera.h"
#include "scene/scene.h"

namespace scene {

struct Hit {
    uint32_t uniquePartId = 0;
    uint32_t object = 0;
    uint32_t localPart = 0;
    float t = 0.0f; // along Ray::direction, 0 at the origin
};

std::optional<Hit> raycast(const Scene& scene, const Ray& ray);

} // namespace scene
