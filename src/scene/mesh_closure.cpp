// mesh_closure.cpp - closed, consistently oriented tessellations (mesh_closure.h).
#include "scene/mesh_closure.h"

#include <algorithm>
#include <array>
#include <vector>

namespace scene {

bool closedAndOriented(const Scene& scene, const Geometry& g) {
    using Edge = std::array<float, 6>; // from x, y, z; to x, y, z
    std::vector<Edge> forward, backward;
    forward.reserve(3 * size_t(g.triangleCount));
    backward.reserve(3 * size_t(g.triangleCount));
    auto at = [&](uint32_t corner) {
        return scene.vertices[g.firstVertex + scene.indices[g.firstIndex + corner]].position;
    };
    for (uint32_t t = 0; t < g.triangleCount; ++t)
        for (uint32_t k = 0; k < 3; ++k) {
            const glm::vec3 a = at(3 * t + k), b = at(3 * t + (k + 1) % 3);
            if (a == b) continue;
            forward.push_back({a.x, a.y, a.z, b.x, b.y, b.z});
            backward.push_back({b.x, b.y, b.z, a.x, a.y, a.z});
        }
    // Closed and oriented: the edges, turned round, are the same edges.
    std::sort(forward.begin(), forward.end());
    std::sort(backward.begin(), backward.end());
    return forward == backward;
}

} // namespace scene
