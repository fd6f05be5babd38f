// lod_error.h - how far a candidate level of detail lies from full detail: the one error every
// level carries, whatever made it (meshoptimizer for meshes, lod.cpp; Open CASCADE's mesher
// for CAD, cad/cad_levels.cpp), and the grid of triangles the measure searches.
#pragma once

#include <array>
#include <cfloat>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "scene/scene.h"

namespace scene {

// A candidate level of one full-detail geometry before it becomes one: vertices of its own
// and, for each of full detail's parts in order, the triangles drawn for that part (three
// indices into `vertices` each), so that every triangle belongs to one part. A part whose
// triangles all have their corners at one point is drawn nowhere; a part empty at full detail
// (Part::empty) has no triangles here either. No parts at all: the maker failed (lod_policy.h
// ends the candidate's chain there).
struct LevelMesh {
    std::vector<Vertex> vertices;
    std::vector<std::vector<uint32_t>> parts;
    size_t triangles = 0;
    uint64_t bytes = 0; // geometryBytes (lod.h), as the memory rules count them
    float error = 0.0f; // levelError, model units
};

// A level's error in model units: the farthest, over the parts, that a corner, edge midpoint
// or centre of a part's triangles at either level lies from the same part's triangles at the
// other; a part drawn nowhere counts its diagonal, one empty at full detail nothing. Measured
// both ways, so that a part that shrank counts as much as one that bulged, and part by part,
// so that a part's outline moving along the surface counts too. Every kind of level takes this and
// nothing else: what its maker says of it (meshoptimizer's error, the deflection asked of Open
// CASCADE's mesher) is no bound on it, and full detail's own distance from an exact surface is no
// part of it, full detail being what level 0 draws. Past `limit` it stops measuring and returns a
// distance beyond it.
float levelError(const Scene& scene, const Geometry& full, const LevelMesh& level,
                 float limit = FLT_MAX);

using Triangle = std::array<glm::vec3, 3>;

// Triangles sorted into a grid of cubes, each listed in every cube its box touches, for the
// nearest of them to a point.
class TriangleGrid {
  public:
    explicit TriangleGrid(const std::vector<Triangle>& triangles);

    // The nearest triangle to `p`: its distance and index; or, once one within `enough` is
    // found (the caller wants no nearer), that one; or, where none lies within `farEnough`
    // (the caller needs no more), a distance above it that no triangle is nearer than.
    struct Hit {
        float distance = FLT_MAX;
        uint32_t index = 0;
    };
    Hit nearest(glm::vec3 p, float enough = 0.0f, float farEnough = FLT_MAX) const;

  private:
    glm::ivec3 cellOf(glm::vec3 p) const { return glm::ivec3(glm::floor((p - low_) / cell_)); }
    static uint64_t key(glm::ivec3 c) {
        return (uint64_t(uint32_t(c.x) & 0x1FFFFF) << 42) |
               (uint64_t(uint32_t(c.y) & 0x1FFFFF) << 21) | uint64_t(uint32_t(c.z) & 0x1FFFFF);
    }

    const std::vector<Triangle>& triangles_;
    glm::vec3 low_{0.0f};
    float cell_ = 1.0f;
    std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

} // namespace scene
