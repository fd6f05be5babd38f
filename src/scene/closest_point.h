// closest_point.h - the point of a triangle nearest a given point, by the triangle's Voronoi
// regions (its corners, then its edges, then its inside), in float (the error of levels of
// detail, lod_error.cpp) or double (distances between meshes, mesh_inspect.cpp).
#pragma once

#include <glm/glm.hpp>

namespace scene {

template <typename Vec>
Vec closestOnTriangle(const Vec& p, const Vec& a, const Vec& b, const Vec& c) {
    using Real = typename Vec::value_type;
    const Vec ab = b - a, ac = c - a, ap = p - a;
    const Real d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Vec bp = p - b;
    const Real d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const Real vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    const Vec cp = p - c;
    const Real d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const Real vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    const Real va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const Real sum = va + vb + vc;
    // A degenerate triangle has no inside: its corners and edges (tested above) hold the answer.
    if (!(sum > 0)) return a;
    return a + ab * (vb / sum) + ac * (vc / sum);
}

} // namespace scene
