// raycast.cpp - Moller-Trumbore in each object's own space. An affine transform keeps the
// ray parameter t, so hits of different objects compare without going back to world space.
#include "scene/raycast.h"

namespace scene {

static bool intersect(glm::vec3 origin, glm::vec3 dir, glm::vec3 a, glm::vec3 b, glm::vec3 c,
                      float& t) {
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 p = glm::cross(dir, e2);
    const float det = glm::dot(e1, p);
    if (det == 0.0f) return false; // two-sided: both windings hit, as the renderer draws them
    const float inv = 1.0f / det;
    const glm::vec3 s = origin - a;
    const float u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f) return false;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(dir, q) * inv;
    if (v < 0.0f || u + v > 1.0f) return false;
    t = glm::dot(e2, q) * inv;
    return t >= 0.0f;
}

std::optional<Hit> raycast(const Scene& scene, const Ray& ray) {
    std::optional<Hit> best;
    for (uint32_t oi = 0; oi < scene.objects.size(); ++oi) {
        const Object& object = scene.objects[oi];
        const Geometry& g = scene.geometries[object.geometry];
        const glm::mat4 toLocal = glm::inverse(object.world);
        const glm::vec3 origin = glm::vec3(toLocal * glm::vec4(ray.origin, 1.0f));
        const glm::vec3 dir = glm::vec3(toLocal * glm::vec4(ray.direction, 0.0f));
        for (uint32_t p = 0; p < g.partCount; ++p) {
            const Part& part = scene.parts[g.firstPart + p];
            for (uint32_t tri = part.firstTriangle; tri < part.firstTriangle + part.triangleCount;
                 ++tri) {
                const uint32_t* idx = &scene.indices[g.firstIndex + 3 * tri];
                const Vertex* v = &scene.vertices[g.firstVertex];
                float t;
                if (!intersect(origin, dir, v[idx[0]].position, v[idx[1]].position,
                               v[idx[2]].position, t))
                    continue;
                if (t > 1.0f || (best && t >= best->t)) continue; // beyond far plane, or behind
                best = Hit{object.uniquePartOffset + p, oi, p, t};
            }
        }
    }
    return best;
}

} // namespace scene
