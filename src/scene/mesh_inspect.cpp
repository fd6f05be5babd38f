// mesh_inspect.cpp - distances and properties from triangles (mesh_inspect.h). The closest
// points of two triangles follow the Voronoi-region construction of Ericson's "Real-Time
// Collision Detection" (point to triangle, segment to segment), written here anew.
#include "scene/mesh_inspect.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "scene/bounds.h"
#include "scene/closest_point.h"

namespace scene {

namespace {

glm::dvec3 closestOnTriangle(const glm::dvec3& p, const Triangle& t) {
    return scene::closestOnTriangle<glm::dvec3>(p, t[0], t[1], t[2]);
}

// The closest points of segments p0-p1 and q0-q1.
std::pair<glm::dvec3, glm::dvec3> closestOnSegments(const glm::dvec3& p0, const glm::dvec3& p1,
                                                    const glm::dvec3& q0, const glm::dvec3& q1) {
    const glm::dvec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
    double s = 0, t = 0;
    if (a <= 0 && e <= 0) return {p0, q0};
    if (a <= 0) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = glm::dot(d1, r);
        if (e <= 0) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = glm::dot(d1, d2), denom = a * e - b * b;
            // Parallel segments: any s, so 0, and t follows.
            s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0) {
                t = 0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1) {
                t = 1;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    return {p0 + d1 * s, q0 + d2 * t};
}

// Where segment p-q crosses triangle t, if it does (a segment in the triangle's plane is
// found by the segment-to-segment tests instead).
std::optional<glm::dvec3> segmentCrossing(const glm::dvec3& p, const glm::dvec3& q,
                                          const Triangle& t) {
    const glm::dvec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
    const double dp = glm::dot(n, p - t[0]), dq = glm::dot(n, q - t[0]);
    if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0) || dp == dq) return std::nullopt;
    const glm::dvec3 x = p + (q - p) * (dp / (dp - dq));
    for (int k = 0; k < 3; ++k)
        if (glm::dot(glm::cross(t[(k + 1) % 3] - t[k], x - t[k]), n) < 0) return std::nullopt;
    return x;
}

} // namespace

ClosestPoints triangleDistance(const Triangle& a, const Triangle& b) {
    ClosestPoints best{std::numeric_limits<double>::infinity(), a[0], b[0]};
    auto consider = [&](const glm::dvec3& p, const glm::dvec3& q) {
        const double d = glm::distance(p, q);
        if (d < best.distance) best = {d, p, q};
    };
    for (int i = 0; i < 3; ++i) {
        consider(a[i], closestOnTriangle(a[i], b));
        consider(closestOnTriangle(b[i], a), b[i]);
        for (int j = 0; j < 3; ++j) {
            const auto [p, q] = closestOnSegments(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3]);
            consider(p, q);
        }
    }
    // Crossing triangles touch inside both, where no vertex or edge pair is closest.
    for (int i = 0; i < 3 && best.distance > 0; ++i) {
        if (const auto x = segmentCrossing(a[i], a[(i + 1) % 3], b))
            best = {0.0, *x, *x};
        else if (const auto y = segmentCrossing(b[i], b[(i + 1) % 3], a))
            best = {0.0, *y, *y};
    }
    return best;
}

namespace {

struct BoxedTriangle {
    Triangle corners;
    Bounds box;
};

// A side's triangles in world coordinates.
struct Side {
    std::vector<BoxedTriangle> triangles;
    Bounds box = emptyBounds();
};

Triangle worldTriangle(const Scene& scene, const Object& object, uint32_t t) {
    const Geometry& g = scene.geometries[object.geometry];
    Triangle c;
    for (int k = 0; k < 3; ++k) {
        const uint32_t v = scene.indices[g.firstIndex + 3 * t + uint32_t(k)];
        c[size_t(k)] = placed(object.world, scene.vertices[g.firstVertex + v].position);
    }
    return c;
}

Bounds boxOf(const Triangle& t) {
    return {glm::min(t[0], glm::min(t[1], t[2])), glm::max(t[0], glm::max(t[1], t[2]))};
}

double boxGap(const Bounds& a, const Bounds& b) {
    const glm::dvec3 gap = glm::max(glm::dvec3(0.0), glm::max(a.min - b.max, b.min - a.max));
    return glm::length(gap);
}

std::optional<Side> gather(const Scene& scene, const Thing& thing) {
    if (thing.edge || thing.parts.empty()) return std::nullopt;
    Side side;
    for (uint32_t id : thing.parts) {
        const auto ref = scene.locate(id);
        if (!ref) return std::nullopt;
        const Object& object = scene.objects[ref->object];
        const Part& part = scene.part(object, ref->localPart);
        for (uint32_t t = part.firstTriangle; t < part.firstTriangle + part.triangleCount; ++t) {
            const Triangle c = worldTriangle(scene, object, t);
            side.triangles.push_back({c, boxOf(c)});
            side.box = unite(side.box, side.triangles.back().box);
        }
    }
    if (side.triangles.empty()) return std::nullopt;
    return side;
}

// A bounding volume hierarchy over one side's triangles: each node's box holds its triangles,
// a leaf's few in order, an inner node's split in two at the median of its longest axis.
class TriangleTree {
  public:
    explicit TriangleTree(std::vector<BoxedTriangle> triangles) : triangles_(std::move(triangles)) {
        nodes_.emplace_back();
        build(0, 0, uint32_t(triangles_.size()));
    }

    // Lowers `best` to the distance of `t` to the nearest triangle, where that is less.
    void closest(const BoxedTriangle& t, ClosestPoints& best) const {
        std::vector<uint32_t> stack{0};
        while (!stack.empty()) {
            const Node& node = nodes_[stack.back()];
            stack.pop_back();
            if (boxGap(t.box, node.box) >= best.distance) continue;
            if (node.count > 0) {
                for (uint32_t i = node.first; i < node.first + node.count; ++i) {
                    if (boxGap(t.box, triangles_[i].box) >= best.distance) continue;
                    const ClosestPoints c = triangleDistance(t.corners, triangles_[i].corners);
                    if (c.distance < best.distance) best = c;
                }
                continue;
            }
            // The nearer child on top: taken first, it lowers `best` for the other.
            const uint32_t near = node.first, far = node.first + 1;
            const bool swap = boxGap(t.box, nodes_[far].box) < boxGap(t.box, nodes_[near].box);
            stack.push_back(swap ? near : far);
            stack.push_back(swap ? far : near);
        }
    }

  private:
    static constexpr uint32_t kLeafSize = 4;
    struct Node {
        Bounds box;
        uint32_t first = 0; // a leaf's first triangle, an inner node's first child
        uint32_t count = 0; // a leaf's triangles; 0 for an inner node
    };

    void build(uint32_t node, uint32_t begin, uint32_t end) {
        Bounds box = emptyBounds();
        for (uint32_t i = begin; i < end; ++i) box = unite(box, triangles_[i].box);
        nodes_[node].box = box;
        if (end - begin <= kLeafSize) {
            nodes_[node].first = begin;
            nodes_[node].count = end - begin;
            return;
        }
        const glm::dvec3 size = box.max - box.min;
        const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
        const uint32_t middle = begin + (end - begin) / 2;
        std::nth_element(triangles_.begin() + begin, triangles_.begin() + middle,
                         triangles_.begin() + end,
                         [axis](const BoxedTriangle& a, const BoxedTriangle& b) {
                             return a.box.center()[axis] < b.box.center()[axis];
                         });
        // The two children side by side, so that a node names them by the first.
        const uint32_t children = uint32_t(nodes_.size());
        nodes_.resize(nodes_.size() + 2);
        nodes_[node].first = children;
        build(children, begin, middle);
        build(children + 1, middle, end);
    }

    std::vector<BoxedTriangle> triangles_;
    std::vector<Node> nodes_;
};

} // namespace

std::optional<DistanceReport> meshDistance(const Scene& scene, const Thing& a, const Thing& b) {
    const auto sa = gather(scene, a), sb = gather(scene, b);
    if (!sa || !sb) return std::nullopt;
    // The tree over b; each of a's triangles descends it, skipping what lies farther than the
    // best distance so far.
    const TriangleTree tree(sb->triangles);
    ClosestPoints best{std::numeric_limits<double>::infinity(), {}, {}};
    for (const BoxedTriangle& t : sa->triangles) {
        if (boxGap(t.box, sb->box) >= best.distance) continue;
        tree.closest(t, best);
        if (best.distance == 0) break;
    }
    DistanceReport report;
    report.distance = best.distance;
    report.p0 = best.p0;
    report.p1 = best.p1;
    report.fromBrep = false;
    report.unit = scene.unit;
    return report;
}

std::optional<SolidProperties> meshProperties(const Scene& scene, uint32_t object) {
    if (object >= scene.objects.size()) return std::nullopt;
    const Object& o = scene.objects[object];
    const Geometry& g = scene.geometries[o.geometry];
    SolidProperties p;
    p.object = object;
    p.unit = scene.unit;
    p.bbox = emptyBounds();
    std::vector<Triangle> triangles;
    for (uint32_t t = 0; t < g.triangleCount; ++t) {
        triangles.push_back(worldTriangle(scene, o, t));
        p.bbox = unite(p.bbox, boxOf(triangles.back()));
    }
    if (triangles.empty()) return p;
    // Parts have vertices of their own: edges are matched by their corners' positions, each
    // edge of a closed surface used once in each direction.
    std::map<std::pair<std::array<double, 3>, std::array<double, 3>>, int> edges;
    auto key = [](const glm::dvec3& v) { return std::array<double, 3>{v.x, v.y, v.z}; };
    // Volumes and centres relative to the box centre: digits kept far from the origin.
    const glm::dvec3 origin = p.bbox.center();
    double volume = 0.0;
    glm::dvec3 volumeMoment(0.0), areaMoment(0.0);
    for (const Triangle& t : triangles) {
        for (int k = 0; k < 3; ++k) {
            const auto from = key(t[size_t(k)]), to = key(t[size_t(k + 1) % 3]);
            edges[from < to ? std::pair(from, to) : std::pair(to, from)] += from < to ? 1 : 16;
        }
        const glm::dvec3 a = t[0] - origin, b = t[1] - origin, c = t[2] - origin;
        const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
        p.area += area;
        areaMoment += area * (a + b + c) / 3.0;
        // The divergence theorem: the tetrahedron of the triangle and the origin, signed.
        const double tetra = glm::dot(a, glm::cross(b, c)) / 6.0;
        volume += tetra;
        volumeMoment += tetra * (a + b + c) / 4.0;
    }
    // Once each way: 1 + 16.
    p.closed =
        std::all_of(edges.begin(), edges.end(), [](const auto& e) { return e.second == 17; });
    if (p.closed && volume != 0.0) {
        p.volume = std::abs(volume);
        p.center = origin + volumeMoment / volume;
    } else if (p.area > 0.0) {
        p.center = origin + areaMoment / p.area;
    }
    return p;
}

} // namespace scene
