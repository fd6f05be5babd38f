// raycast.cpp - Moller-Trumbore in each object's own space. An affine transform keeps the
// ray parameter t, so hits of different objects compare without going back to world space.
#include "scene/raycast.h"

#include <algorithm>
#include <limits>

namespace scene {

static bool intersect(glm::vec3 origin, glm::vec3 dir, glm::vec3 a, glm::vec3 b, glm::vec3 c,
                      float& t, glm::vec2& uv) {
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
    uv = {u, v};
    return t >= 0.0f;
}

// Slab test of the segment origin + t * direction, t in [0, ray.end], against a box.
static bool hitsBox(const Ray& ray, const Bounds& box) {
    float t0 = 0.0f, t1 = ray.end;
    for (int axis = 0; axis < 3; ++axis) {
        const float inv = 1.0f / ray.direction[axis]; // +-inf for axis-parallel rays is fine
        float a = (box.min[axis] - ray.origin[axis]) * inv;
        float b = (box.max[axis] - ray.origin[axis]) * inv;
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        if (t0 > t1) return false;
    }
    return true;
}

RayCaster::RayCaster(const Scene& scene) : scene_(scene) {
    std::vector<Bounds> local(scene.geometries.size());
    for (size_t g = 0; g < scene.geometries.size(); ++g) {
        const Geometry& geo = scene.geometries[g];
        local[g].min = glm::vec3(std::numeric_limits<float>::max());
        local[g].max = glm::vec3(std::numeric_limits<float>::lowest());
        for (uint32_t v = 0; v < geo.vertexCount; ++v) {
            local[g].min = glm::min(local[g].min, scene.vertices[geo.firstVertex + v].position);
            local[g].max = glm::max(local[g].max, scene.vertices[geo.firstVertex + v].position);
        }
    }
    for (const Object& object : scene.objects) {
        const Bounds& b = local[object.geometry];
        Bounds world{glm::vec3(std::numeric_limits<float>::max()),
                     glm::vec3(std::numeric_limits<float>::lowest())};
        for (int corner = 0; corner < 8; ++corner) {
            glm::vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                        (corner & 4) ? b.max.z : b.min.z);
            p = glm::vec3(object.world * glm::vec4(p, 1.0f));
            world.min = glm::min(world.min, p);
            world.max = glm::max(world.max, p);
        }
        // Widen a little so rounding in the transform never rejects a grazing hit.
        const glm::vec3 margin = (world.max - world.min) * 1e-4f + 1e-6f;
        objects_.push_back({glm::inverse(object.world), {world.min - margin, world.max + margin}});
    }
}

// Whether the ray meets triangle `idx` of the object from behind, decided as the fragment
// shader decides it (shaders/scene.frag, backFacing): in world space, the triangle's normal
// turned towards the normal interpolated at the hit.
static bool fromBehind(const Scene& scene, const Object& object, const uint32_t* idx, glm::vec2 uv,
                       const Ray& ray) {
    const Vertex* v = &scene.vertices[scene.geometries[object.geometry].firstVertex];
    glm::vec3 p[3];
    for (int i = 0; i < 3; ++i) p[i] = glm::vec3(object.world * glm::vec4(v[idx[i]].position, 1));
    glm::vec3 faceNormal = glm::cross(p[1] - p[0], p[2] - p[0]);
    const glm::vec3 local =
        (1.0f - uv.x - uv.y) * v[idx[0]].normal + uv.x * v[idx[1]].normal + uv.y * v[idx[2]].normal;
    const glm::vec3 normal = glm::transpose(glm::inverse(glm::mat3(object.world))) * local;
    if (glm::dot(faceNormal, normal) < 0.0f) faceNormal = -faceNormal;
    return glm::dot(faceNormal, ray.direction) > 0.0f;
}

std::optional<Hit> RayCaster::cast(const Ray& ray, const PartSet* hidden,
                                   const Section* section) const {
    std::optional<Hit> best;
    const uint32_t* bestTriangle = nullptr;
    glm::vec2 bestUv{};
    for (uint32_t oi = 0; oi < scene_.objects.size(); ++oi) {
        if (!hitsBox(ray, objects_[oi].worldBounds)) continue;
        const Object& object = scene_.objects[oi];
        const Geometry& g = scene_.geometries[object.geometry];
        const glm::mat4& toLocal = objects_[oi].toLocal;
        const glm::vec3 origin = glm::vec3(toLocal * glm::vec4(ray.origin, 1.0f));
        const glm::vec3 dir = glm::vec3(toLocal * glm::vec4(ray.direction, 0.0f));
        const Vertex* v = &scene_.vertices[g.firstVertex];
        for (uint32_t p = 0; p < g.partCount; ++p) {
            if (hidden && hidden->contains(object.uniquePartOffset + p)) continue;
            const Part& part = scene_.parts[g.firstPart + p];
            for (uint32_t tri = part.firstTriangle; tri < part.firstTriangle + part.triangleCount;
                 ++tri) {
                const uint32_t* idx = &scene_.indices[g.firstIndex + 3 * tri];
                float t;
                glm::vec2 uv;
                if (!intersect(origin, dir, v[idx[0]].position, v[idx[1]].position,
                               v[idx[2]].position, t, uv))
                    continue;
                if (t > ray.end || (best && t >= best->t)) continue; // beyond far plane, or behind
                if (section && !section->keeps(ray.origin + t * ray.direction)) continue;
                best = Hit{object.uniquePartOffset + p, oi, p, t};
                bestTriangle = idx;
                bestUv = uv;
            }
        }
    }
    if (best)
        best->cap = fromBehind(scene_, scene_.objects[best->object], bestTriangle, bestUv, ray);
    return best;
}

std::optional<Hit> raycast(const Scene& scene, const Ray& ray) {
    return RayCaster(scene).cast(ray);
}

} // namespace scene
