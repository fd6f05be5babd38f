// raycast.cpp - Moller-Trumbore in each object's own space, in double: the reference the GPU
// is checked against must not share its rounding, wherever the model sits. An affine
// transform keeps the ray parameter t, so hits of different objects compare without going
// back to world space.
#include "scene/raycast.h"

#include <algorithm>
#include <limits>

#include "scene/bounds.h"

namespace scene {

static bool intersect(glm::dvec3 origin, glm::dvec3 dir, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c,
                      double& t, glm::dvec2& uv) {
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const glm::dvec3 p = glm::cross(dir, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0) return false; // two-sided: both windings hit, as the renderer draws them
    const double inv = 1.0 / det;
    const glm::dvec3 s = origin - a;
    const double u = glm::dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) return false;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(dir, q) * inv;
    if (v < 0.0 || u + v > 1.0) return false;
    t = glm::dot(e2, q) * inv;
    uv = {u, v};
    return t >= 0.0;
}

// Slab test of the segment origin + t * direction, t in [0, ray.end], against a box.
static bool hitsBox(const Ray& ray, const Bounds& box) {
    if (isEmpty(box)) return false;
    double t0 = 0.0, t1 = ray.end;
    for (int axis = 0; axis < 3; ++axis) {
        const double inv = 1.0 / ray.direction[axis]; // +-inf for axis-parallel rays is fine
        double a = (box.min[axis] - ray.origin[axis]) * inv;
        double b = (box.max[axis] - ray.origin[axis]) * inv;
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
        local[g] = emptyBounds();
        for (uint32_t v = 0; v < geo.vertexCount; ++v) {
            const glm::dvec3 position(scene.vertices[geo.firstVertex + v].position);
            local[g].min = glm::min(local[g].min, position);
            local[g].max = glm::max(local[g].max, position);
        }
    }
    // The in-plane tolerance: float vertices are rounded at their magnitude, the rest is double.
    double reach = 0.0;
    for (const Bounds& b : local)
        if (!isEmpty(b)) reach = std::max(reach, glm::length(glm::max(-b.min, b.max)));
    inPlane_ = inPlaneTolerance(reach);
    for (const Object& object : scene.objects) {
        const Bounds& b = local[object.geometry];
        if (isEmpty(b)) { // no triangles: no ray meets it
            objects_.push_back({glm::dmat4(1.0), emptyBounds()});
            continue;
        }
        Bounds world = emptyBounds();
        for (int corner = 0; corner < 8; ++corner) {
            glm::dvec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                         (corner & 4) ? b.max.z : b.min.z);
            p = glm::dvec3(object.world * glm::dvec4(p, 1.0));
            world.min = glm::min(world.min, p);
            world.max = glm::max(world.max, p);
        }
        // Widen a little so rounding in the transform never rejects a grazing hit.
        const glm::dvec3 margin = (world.max - world.min) * 1e-9 + 1e-9;
        objects_.push_back({glm::inverse(object.world), {world.min - margin, world.max + margin}});
    }
}

// The vertex normals of triangle `idx` of the object interpolated at `uv`, in world space.
static glm::dvec3 normalAt(const Scene& scene, const Object& object, const uint32_t* idx,
                           glm::dvec2 uv) {
    const Vertex* v = &scene.vertices[scene.geometries[object.geometry].firstVertex];
    const glm::dvec3 local = (1.0 - uv.x - uv.y) * glm::dvec3(v[idx[0]].normal) +
                             uv.x * glm::dvec3(v[idx[1]].normal) +
                             uv.y * glm::dvec3(v[idx[2]].normal);
    return glm::transpose(glm::inverse(glm::dmat3(object.world))) * local;
}

// Whether the ray meets triangle `idx` of the object from behind, decided as the fragment
// shader decides it (shaders/scene.frag, backFacing): in world space, the triangle's normal
// turned towards the normal interpolated at the hit.
static bool fromBehind(const Scene& scene, const Object& object, const uint32_t* idx, glm::dvec2 uv,
                       const Ray& ray) {
    const Vertex* v = &scene.vertices[scene.geometries[object.geometry].firstVertex];
    glm::dvec3 p[3];
    for (int i = 0; i < 3; ++i) p[i] = placed(object.world, v[idx[i]].position);
    glm::dvec3 faceNormal = glm::cross(p[1] - p[0], p[2] - p[0]);
    if (glm::dot(faceNormal, normalAt(scene, object, idx, uv)) < 0.0) faceNormal = -faceNormal;
    return glm::dot(faceNormal, ray.direction) > 0.0;
}

std::optional<Hit> RayCaster::cast(const Ray& ray, const PartSet* hidden,
                                   const Section* section) const {
    std::optional<Hit> best;
    const uint32_t* bestTriangle = nullptr;
    glm::dvec2 bestUv{};
    for (uint32_t oi = 0; oi < scene_.objects.size(); ++oi) {
        if (!hitsBox(ray, objects_[oi].worldBounds)) continue;
        const Object& object = scene_.objects[oi];
        const Geometry& g = scene_.geometries[object.geometry];
        const glm::dmat4& toLocal = objects_[oi].toLocal;
        const glm::dvec3 origin = glm::dvec3(toLocal * glm::dvec4(ray.origin, 1.0));
        const glm::dvec3 dir = glm::dvec3(toLocal * glm::dvec4(ray.direction, 0.0));
        const Vertex* v = &scene_.vertices[g.firstVertex];
        for (uint32_t p = 0; p < g.partCount; ++p) {
            if (hidden && hidden->contains(object.uniquePartOffset + p)) continue;
            const Part& part = scene_.parts[g.firstPart + p];
            for (uint32_t tri = part.firstTriangle; tri < part.firstTriangle + part.triangleCount;
                 ++tri) {
                const uint32_t* idx = &scene_.indices[g.firstIndex + 3 * tri];
                double t;
                glm::dvec2 uv;
                if (!intersect(origin, dir, glm::dvec3(v[idx[0]].position),
                               glm::dvec3(v[idx[1]].position), glm::dvec3(v[idx[2]].position), t,
                               uv))
                    continue;
                if (t > ray.end || (best && t >= best->t))
                    continue; // beyond the far plane, or behind
                if (section && !section->keeps(ray.origin + t * ray.direction,
                                               normalAt(scene_, object, idx, uv), inPlane_))
                    continue;
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
