// explode.cpp - exploded-view offsets and the CPU reference of the GPU animation.
#include "scene/explode.h"

#include "scene/bounds.h"

#include <cmath>
#include <limits>

namespace scene {

std::vector<glm::vec4> explodeOffsets(const Scene& scene) {
    // One pass over every placed vertex gives the objects' bounds and, as their union, the
    // scene's: the same min/max Scene::bounds() finds, without transforming twice.
    std::vector<Bounds> objectBounds(scene.objects.size());
    Bounds all = emptyBounds();
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& object = scene.objects[i];
        const Geometry& g = scene.geometries[object.geometry];
        Bounds b = emptyBounds();
        for (uint32_t v = 0; v < g.vertexCount; ++v) {
            const glm::dvec3 p = placed(object.world, scene.vertices[g.firstVertex + v].position);
            b.min = glm::min(b.min, p);
            b.max = glm::max(b.max, p);
        }
        if (g.vertexCount == 0) { // nothing drawn: its origin stands in, outside the union
            b.min = b.max = glm::dvec3(object.world[3]);
        } else {
            all.min = glm::min(all.min, b.min);
            all.max = glm::max(all.max, b.max);
        }
        objectBounds[i] = b;
    }
    std::vector<glm::vec4> offsets;
    offsets.reserve(scene.objects.size());
    for (const Bounds& b : objectBounds) offsets.push_back(glm::vec4(b.center() - all.center(), 0));
    return offsets;
}

Scene explodedScene(const Scene& scene, float explode) {
    const std::vector<glm::vec4> offsets = explodeOffsets(scene);
    Scene moved = scene;
    for (size_t i = 0; i < moved.objects.size(); ++i) {
        glm::dmat4& world = moved.objects[i].world;
        // A float multiply, then a double add, per component: animate.comp marks the same
        // expression `precise`, which forbids fusing them into an fma.
        for (int c = 0; c < 3; ++c) {
            const float step = offsets[i][c] * explode;
            world[3][c] = world[3][c] + double(step);
        }
    }
    return moved;
}

float explodeLoop(float seconds, float periodSeconds) {
    const float pi = 3.14159265358979f;
    return 0.5f - 0.5f * std::cos(2.0f * pi * seconds / periodSeconds);
}

} // namespace scene
