// copies.cpp - grid replication of a scene's objects.
#include "scene/copies.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace scene {

uint32_t parseCopyAxes(const std::string& text) {
    uint32_t axes = 0;
    for (char c : text) {
        const uint32_t bit = c == 'x' ? COPY_X : c == 'y' ? COPY_Y : c == 'z' ? COPY_Z : 0u;
        if (!bit || (axes & bit))
            throw std::invalid_argument("expects some of x, y and z, each at most once, not '" +
                                        text + "'");
        axes |= bit;
    }
    if (!axes) throw std::invalid_argument("expects at least one of x, y and z");
    return axes;
}

std::string copyAxesName(uint32_t axes) {
    std::string name;
    if (axes & COPY_X) name += 'x';
    if (axes & COPY_Y) name += 'y';
    if (axes & COPY_Z) name += 'z';
    return name;
}

namespace {

// The smallest side such that side^dimensions >= copies: the grid is as compact as it can be.
uint32_t gridSide(uint32_t copies, int dimensions) {
    auto fits = [&](uint64_t side) {
        uint64_t cells = 1;
        for (int d = 0; d < dimensions && cells < copies; ++d) cells *= side;
        return cells >= copies;
    };
    uint64_t side = uint64_t(std::max(1.0, std::floor(std::pow(double(copies), 1.0 / dimensions))));
    while (side > 1 && fits(side - 1)) --side; // pow's rounding, either way
    while (!fits(side)) ++side;
    return uint32_t(side);
}

} // namespace

Scene replicate(const Scene& scene, uint32_t copies, uint32_t axes) {
    if ((axes & (COPY_X | COPY_Y | COPY_Z)) == 0 || (axes & ~uint32_t(COPY_X | COPY_Y | COPY_Z)))
        throw std::invalid_argument("copy axes must be a non-empty set of x, y and z");
    if (copies == 0) throw std::invalid_argument("copies must be at least 1");
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
    glm::dvec3 step = (bounds.max - bounds.min) * 1.1;
    // A flat scene would put its copies on top of each other along its flat axis.
    const double largest = std::max(step.x, std::max(step.y, step.z));
    for (int a = 0; a < 3; ++a)
        if (step[a] <= 0.0) step[a] = largest > 0.0 ? largest : 1.0;
    std::vector<int> chosen;
    for (int a = 0; a < 3; ++a)
        if (axes & (1u << a)) chosen.push_back(a);
    const uint32_t side = gridSide(copies, int(chosen.size()));
    for (uint32_t copy = 0; copy < copies; ++copy) {
        glm::dvec3 shift(0.0);
        uint32_t rest = copy; // the copy's grid cell, digit by digit in base `side`
        for (int a : chosen) {
            shift[a] = double(rest % side) * step[a];
            rest /= side;
        }
        const glm::dmat4 move = glm::translate(glm::dmat4(1.0), shift);
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
