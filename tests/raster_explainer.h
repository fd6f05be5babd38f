// raster_explainer.h - why two ID images of one scene may differ where one was drawn by the
// compute rasterizer (visbuffer-compute) and one by the hardware: a CPU rasterizer with the
// same rules (cpu_raster.h) over the triangles of the two parts a pixel shows says whether
// its sample lies within one subpixel step of an edge of one of them but not on it (there the
// top-left rule decides, which both follow), so that a vertex projected a rounding apart could
// move the edge across it, or whether the two surfaces lie within 2 ulps of depth there. Any
// other difference is a bug. test_compute_raster.cpp and the registry sweeps use it.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "cpu_raster.h"
#include "render/technique.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "shared.h"

namespace testing_support {

inline glm::dvec2 sampleZero(uint32_t msaa) {
    return msaa == 4 ? glm::dvec2(0.375, 0.125) : glm::dvec2(0.5);
}

// A scene triangle as the framebuffer sees it: corners in pixels (y down) and their depths.
struct Projected {
    RasterTriangle corners;
    glm::dvec3 xyz[3];
};

// The depth of the plane through the projected corners at `p`.
inline double depthAt(const Projected& t, glm::dvec2 p) {
    const glm::dvec3 a = t.xyz[0], b = t.xyz[1], c = t.xyz[2];
    const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (area == 0.0) return a.z;
    const double wb = ((p.x - a.x) * (c.y - a.y) - (p.y - a.y) * (c.x - a.x)) / area;
    const double wc = ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / area;
    return a.z + wb * (b.z - a.z) + wc * (c.z - a.z);
}

// Explains the pixels where two ID images differ, from the triangles of the parts shown.
class Explainer {
  public:
    Explainer(const scene::Scene& scene, const scene::Camera& camera, glm::uvec2 extent,
              uint32_t msaa, const RasterRules& rules = {})
        : scene_(scene), extent_(extent),
          viewProj_(camera.viewProjection(double(extent.x) / double(extent.y))),
          sample_(sampleZero(msaa)), rules_(rules) {}

    enum class Why { Unexplained, NearEdge, Depth };

    Why explain(uint32_t x, uint32_t y, uint32_t a, uint32_t b) const {
        const glm::dvec2 p = glm::dvec2(x, y) + sample_;
        std::optional<double> depthA, depthB;
        for (uint32_t id : {a, b}) {
            if (id == gpu::BACKGROUND_ID) continue;
            for (const Projected& t : trianglesOf(id)) {
                const CpuRaster raster(t.corners, rules_);
                if (raster.nearEdge(p) && !raster.onEdge(p)) return Why::NearEdge;
                if (!raster.covers(p)) continue;
                std::optional<double>& d = id == a ? depthA : depthB;
                d = std::max(d.value_or(0.0), depthAt(t, p));
            }
        }
        if (depthA && depthB && ulpsApart(float(*depthA), float(*depthB)) <= 2) return Why::Depth;
        return Why::Unexplained;
    }

  private:
    static int64_t ulpsApart(float a, float b) {
        int32_t ia, ib;
        std::memcpy(&ia, &a, 4);
        std::memcpy(&ib, &b, 4);
        return std::llabs(int64_t(ia) - int64_t(ib));
    }

    // Every level's triangles of the unique part `id`, projected.
    std::vector<Projected> trianglesOf(uint32_t id) const {
        std::vector<Projected> out;
        const std::optional<scene::PartRef> ref = scene_.locate(id);
        if (!ref) return out;
        const scene::Object& object = scene_.objects[ref->object];
        std::vector<uint32_t> geometries = {object.geometry};
        for (uint32_t level : scene_.geometries[object.geometry].levels)
            geometries.push_back(level);
        const glm::dmat4 toClip = viewProj_ * object.world;
        for (uint32_t g : geometries) {
            const scene::Geometry& geometry = scene_.geometries[g];
            const scene::Part& part = scene_.parts[geometry.firstPart + ref->localPart];
            for (uint32_t t = part.firstTriangle; t < part.firstTriangle + part.triangleCount;
                 ++t) {
                Projected p{};
                for (int k = 0; k < 3; ++k) {
                    const uint32_t v = geometry.firstVertex +
                                       scene_.indices[geometry.firstIndex + 3 * t + uint32_t(k)];
                    const glm::dvec4 clip =
                        toClip * glm::dvec4(glm::dvec3(scene_.vertices[v].position), 1.0);
                    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
                    p.xyz[k] = {(ndc.x * 0.5 + 0.5) * extent_.x, (ndc.y * 0.5 + 0.5) * extent_.y,
                                ndc.z};
                    p.corners.corner[k] = glm::dvec2(p.xyz[k]);
                }
                out.push_back(p);
            }
        }
        return out;
    }

    const scene::Scene& scene_;
    glm::dvec2 extent_;
    glm::dmat4 viewProj_;
    glm::dvec2 sample_;
    RasterRules rules_;
};

// The pixels where `got` (the compute rasterizer's) differs from `expected` (the hardware's),
// by what explains them.
struct Explained {
    size_t differ = 0, nearEdge = 0, depth = 0, unexplained = 0;
    // One pixel that differs, for the reason `why`.
    void add(Explainer::Why why) {
        ++differ;
        ++(why == Explainer::Why::NearEdge ? nearEdge
           : why == Explainer::Why::Depth  ? depth
                                           : unexplained);
    }
};
inline Explained explainDifferences(const scene::Scene& scene, const scene::Camera& camera,
                                    glm::uvec2 extent, uint32_t msaa,
                                    const std::vector<uint32_t>& expected,
                                    const std::vector<uint32_t>& got) {
    Explained e;
    if (expected.size() != got.size()) {
        e.differ = e.unexplained = std::max(expected.size(), got.size());
        return e;
    }
    const Explainer explainer(scene, camera, extent, msaa);
    for (size_t i = 0; i < got.size(); ++i)
        if (got[i] != expected[i])
            e.add(explainer.explain(uint32_t(i % extent.x), uint32_t(i / extent.x), expected[i],
                                    got[i]));
    return e;
}

// For a registry sweep: `got`, drawn by `technique`, is `expected` byte for byte; drawn by a
// compute rasterizer, it differs at most where explainDifferences explains.
inline ::testing::AssertionResult sameIdsAs(const render::Technique& technique,
                                            const std::vector<uint32_t>& got,
                                            const std::vector<uint32_t>& expected,
                                            const scene::Scene& scene, const scene::Camera& camera,
                                            glm::uvec2 extent, uint32_t msaa) {
    if (!technique.computeRaster) {
        if (got == expected) return ::testing::AssertionSuccess();
        size_t differ = got.size() == expected.size() ? 0 : std::max(got.size(), expected.size());
        for (size_t i = 0; i < std::min(got.size(), expected.size()); ++i)
            differ += got[i] != expected[i];
        return ::testing::AssertionFailure() << differ << " pixels of the ID images differ";
    }
    const Explained e = explainDifferences(scene, camera, extent, msaa, expected, got);
    if (e.unexplained == 0) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << e.differ << " pixels differ, " << e.unexplained << " of them unexplained";
}

} // namespace testing_support
