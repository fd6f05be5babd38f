// copies.cpp - grid replication of a scene's objects.
#include "scene/copies.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>
#include <string>

namespace scene {

Scene replicate(const Scene& scene, uint32_t copies) {
    if (copies == 0) throw std::invalid_argument("copies must be at least 1");
    const uint64_t ids = uint64_t(scene.uniquePartCount()) * copies;
    if (ids >= 0xFFFFFFFFull)
        throw std::invalid_argument(std::to_string(copies) + " copies of " +
                                    std::to_string(scene.uniquePartCount()) + " parts need " +
                                    std::to_string(ids) +
                                    " unique part IDs, more than 32-bit IDs can name");
    Scene result = scene;
    result.objects.clear();
    result.objects.reserve(scene.objects.size() * copies);
    const Bounds bounds = scene.bounds();
    const glm::vec3 step = (bounds.max - bounds.min) * 1.1f;
    const uint32_t columns = static_cast<uint32_t>(std::ceil(std::sqrt(double(copies))));
    for (uint32_t copy = 0; copy < copies; ++copy) {
        const glm::vec3 shift(float(copy % columns) * step.x, float(copy / columns) * step.y, 0.0f);
        const glm::mat4 move = glm::translate(glm::mat4(1.0f), shift);
        for (const Object& o : scene.objects)
            addObject(result, o.geometry, o.material, move * o.world);
    }
    return result;
}

} // namespace scene
