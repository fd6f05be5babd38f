// raycast.h - the CPU reference for "which part is at this pixel": a ray cast against every
// triangle of the scene, used by tests to check what the GPU wrote.
#pragma once

#include <optional>
#include <vector>

#include "scene/camera.h"
#include "scene/part_set.h"
#include "scene/scene.h"
#include "scene/section.h"

namespace scene {

struct Hit {
    uint32_t uniquePartId = 0;
    uint32_t object = 0;
    uint32_t localPart = 0;
    double t = 0.0; // along Ray::direction, 0 at the origin
    // The ray meets the back of the surface (its triangle's normal, turned to the side the
    // vertex normals give at the hit, faces away): with section planes, a cap of the part.
    bool cap = false;
};

// Prepares per-object inverse matrices and world bounds once, so rays skip the objects
// whose box they miss (and those without triangles); every remaining triangle is tested
// exactly (no approximation). An empty part has no triangle to hit.
class RayCaster {
  public:
    explicit RayCaster(const Scene& scene);
    // The nearest hit of a part not in `hidden` (rays go through hidden parts) at a point
    // `section` keeps (rays go through what its planes cut away), by the in-plane rule as the
    // renderer applies it (Section::keeps with the hit's normal).
    std::optional<Hit> cast(const Ray& ray, const PartSet* hidden = nullptr,
                            const Section* section = nullptr) const;

  private:
    struct Prepared {
        glm::dmat4 toLocal;
        Bounds worldBounds;
    };
    const Scene& scene_;
    std::vector<Prepared> objects_;
    double inPlane_ = 0.0; // the in-plane rule's tolerance at this scene's scale
};

// One ray; for many rays over the same scene use RayCaster.
std::optional<Hit> raycast(const Scene& scene, const Ray& ray);

} // namespace scene
