// cpu_raster.h - a CPU rasterizer that follows the rules a compute rasterizer must share with
// the hardware (issue 46): vertices snapped to the device's subpixel grid (round to nearest),
// a sample covered where every edge function of the snapped triangle is above zero, or zero on
// a top or left edge (framebuffer y down: a left edge goes up, a top edge is level with the
// inside below it), the nearest surface kept (reversed depth: the greater), the first drawn
// kept where two tie. Exact integer edge functions, so its answers are the rules' own; what
// it cannot know (a driver's rounding of an unsnapped vertex) it can say: whether a sample
// lies within one subpixel step of an edge.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace testing_support {

struct RasterTriangle {
    glm::dvec2 corner[3]; // framebuffer pixels, y down
    double depth;         // reversed: nearer is greater
    uint32_t id;
};

struct RasterRules {
    uint32_t subpixelBits = 8;
    bool topLeft = true; // false: the bottom-right rule instead (a mutation the tests catch)
};

class CpuRaster {
  public:
    CpuRaster(const RasterTriangle& t, const RasterRules& rules) : rules_(rules) {
        const double scale = double(1u << rules.subpixelBits);
        for (int k = 0; k < 3; ++k) {
            x_[k] = std::llround(t.corner[k].x * scale);
            y_[k] = std::llround(t.corner[k].y * scale);
        }
        area_ = edge(0, 1, x_[2], y_[2]);
        if (area_ < 0) { // one orientation, so the inside is where every edge is positive
            std::swap(x_[1], x_[2]);
            std::swap(y_[1], y_[2]);
            area_ = -area_;
        }
    }

    // Zero-area triangles cover nothing.
    bool covers(glm::dvec2 sample) const {
        if (area_ == 0) return false;
        const auto [px, py] = onGrid(sample);
        for (int k = 0; k < 3; ++k) {
            const int n = (k + 1) % 3;
            const int64_t e = edge(k, n, px, py);
            if (e > 0) continue;
            if (e < 0 || !owns(x_[n] - x_[k], y_[n] - y_[k])) return false;
        }
        return true;
    }

    // Whether the sample lies within one subpixel step of an edge's line.
    bool nearEdge(glm::dvec2 sample) const {
        const auto [px, py] = onGrid(sample);
        for (int k = 0; k < 3; ++k) {
            const int n = (k + 1) % 3;
            const double length = std::hypot(double(x_[n] - x_[k]), double(y_[n] - y_[k]));
            if (length > 0 && std::abs(double(edge(k, n, px, py))) <= length) return true;
        }
        return false;
    }

    // Whether the sample lies exactly on an edge's line, where the top-left rule decides.
    bool onEdge(glm::dvec2 sample) const {
        const auto [px, py] = onGrid(sample);
        for (int k = 0; k < 3; ++k)
            if (edge(k, (k + 1) % 3, px, py) == 0) return true;
        return false;
    }

  private:
    std::pair<int64_t, int64_t> onGrid(glm::dvec2 sample) const {
        const double scale = double(1u << rules_.subpixelBits);
        return {std::llround(sample.x * scale), std::llround(sample.y * scale)};
    }
    int64_t edge(int a, int b, int64_t px, int64_t py) const {
        return (x_[b] - x_[a]) * (py - y_[a]) - (y_[b] - y_[a]) * (px - x_[a]);
    }
    // A sample on the edge: owned by a left edge (going up, y down) or a top one (level, the
    // inside below: going right); with the mutation, by right and bottom edges instead.
    bool owns(int64_t dx, int64_t dy) const {
        const bool topLeft = dy < 0 || (dy == 0 && dx > 0);
        return rules_.topLeft ? topLeft : !topLeft;
    }

    RasterRules rules_;
    int64_t x_[3], y_[3];
    int64_t area_ = 0;
};

// The ID each pixel's sample at `offset` (in the pixel) shows: the nearest covering triangle,
// the first of those that tie; `none` where no triangle covers it.
inline std::vector<uint32_t> rasterize(const std::vector<RasterTriangle>& triangles, uint32_t width,
                                       uint32_t height, glm::dvec2 offset, const RasterRules& rules,
                                       uint32_t none) {
    std::vector<uint32_t> ids(size_t(width) * height, none);
    std::vector<double> depth(ids.size(), 0.0);
    for (const RasterTriangle& t : triangles) {
        const CpuRaster raster(t, rules);
        for (uint32_t y = 0; y < height; ++y)
            for (uint32_t x = 0; x < width; ++x) {
                const size_t i = size_t(y) * width + x;
                if (t.depth > depth[i] && raster.covers(glm::dvec2(x, y) + offset)) {
                    depth[i] = t.depth;
                    ids[i] = t.id;
                }
            }
    }
    return ids;
}

} // namespace testing_support
