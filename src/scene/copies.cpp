// copies.cpp - grid replication of a scene's objects.
#include "scene/copies.h"

#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>
#include <string>

namespace scene {

Scene replicate(const Scene& scene, uint32_t copies, uint32_t axes) {
    checkCopyGrid(copies, axes);
    const uint64_t ids = uint64_t(scene.uniquePartCount()) * copies;
    if (ids >= 0xFFFFFFFFull)
        throw std::invalid_argument(std::to_string(copies) + " copies of " +
                                    std::to_string(scene.uniquePartCount()) + " parts need " +
                                    std::to_string(ids) +
                                    " unique part IDs, more than 32-bit IDs can name");
    // The copy shares the scene's geometry (scene/shared_array.h): only its objects are new.
    Scene result = scene;
    result.objects.clear();
    result.objects.reserve(scene.objects.size() * copies);
    const Bounds bounds = scene.bounds();
    const glm::dvec3 step = copyStep(bounds.max - bounds.min);
    for (uint32_t copy = 0; copy < copies; ++copy) {
        const glm::dmat4 move =
            glm::translate(glm::dmat4(1.0), copyShift(copy, copies, axes, step));
        // Copy 0 is the original; copy k (the (k+1)-th) keeps its objects' names and puts
        // "copy k/" in front of their paths, so that paths stay unique across copies.
        const std::string group = copy ? "copy " + std::to_string(copy) : std::string();
        for (const Object& o : scene.objects)
            addObject(result, o.geometry, o.material, move * o.world, o.name,
                      joinPath(group, o.path));
    }
    return result;
}

} // namespace scene
