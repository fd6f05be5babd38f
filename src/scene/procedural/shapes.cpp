// shapes.cpp - tessellation of turned profiles, hex prisms, gears, holed plates and tubes.
// Triangles take their winding from the vertex normals, so no shape has to get it right by hand.
#include "scene/procedural/shapes.h"

#include <cmath>
#include <vector>

namespace scene {

namespace {

constexpr float kTwoPi = 6.28318530717958647692f;

// Adds vertices of one part and orients every triangle to face along its vertex normals.
class Writer {
  public:
    explicit Writer(MeshBuilder& mb) : mb_(mb) {}
    uint32_t vertex(glm::vec3 p, glm::vec3 n) {
        uint32_t index = mb_.addVertex(p, n);
        if (positions_.empty()) first_ = index;
        positions_.push_back(p);
        normals_.push_back(n);
        return index;
    }
    void triangle(uint32_t a, uint32_t b, uint32_t c) {
        glm::vec3 pa = positions_[a - first_], pb = positions_[b - first_];
        glm::vec3 pc = positions_[c - first_];
        glm::vec3 n = normals_[a - first_] + normals_[b - first_] + normals_[c - first_];
        if (glm::dot(glm::cross(pb - pa, pc - pa), n) < 0.0f) std::swap(b, c);
        mb_.addTriangle(a, b, c);
    }
    void quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
        triangle(a, b, c);
        triangle(a, c, d);
    }

  private:
    MeshBuilder& mb_;
    uint32_t first_ = 0;
    std::vector<glm::vec3> positions_, normals_;
};

glm::vec2 unitAt(float angle) {
    return {std::cos(angle), std::sin(angle)};
}

// One flat part: the strip between two closed outlines sampled at matching angles, or a fan
// from the centre when `inner` is empty (the outline must be star-shaped around it).
void flatRing(MeshBuilder& mb, const Frame& f, std::span<const glm::vec2> outer,
              std::span<const glm::vec2> inner, float z, float up) {
    mb.beginPart();
    Writer w(mb);
    const glm::vec3 n = f.dir({0, 0, up});
    const uint32_t count = static_cast<uint32_t>(outer.size());
    const uint32_t o = w.vertex(f.point({outer[0], z}), n);
    for (uint32_t i = 1; i < count; ++i) w.vertex(f.point({outer[i], z}), n);
    if (inner.empty()) {
        glm::vec2 c(0.0f);
        for (auto p : outer) c += p;
        const uint32_t center = w.vertex(f.point({c / float(count), z}), n);
        for (uint32_t i = 0; i < count; ++i) w.triangle(center, o + i, o + (i + 1) % count);
        return;
    }
    const uint32_t in = w.vertex(f.point({inner[0], z}), n);
    for (uint32_t i = 1; i < count; ++i) w.vertex(f.point({inner[i], z}), n);
    for (uint32_t i = 0; i < count; ++i) {
        uint32_t j = (i + 1) % count;
        w.quad(o + i, o + j, in + j, in + i);
    }
}

// One smooth part: a band between z0 and z1 through the given outline, normals radial.
void mantle(MeshBuilder& mb, const Frame& f, std::span<const glm::vec2> outline, float z0, float z1,
            float outward) {
    mb.beginPart();
    Writer ring(mb);
    const uint32_t count = static_cast<uint32_t>(outline.size());
    std::vector<glm::vec3> normals(count);
    for (uint32_t i = 0; i < count; ++i) normals[i] = f.dir({glm::normalize(outline[i]), 0});
    const uint32_t bottom = ring.vertex(f.point({outline[0], z0}), normals[0] * outward);
    for (uint32_t i = 1; i < count; ++i)
        ring.vertex(f.point({outline[i], z0}), normals[i] * outward);
    const uint32_t top = ring.vertex(f.point({outline[0], z1}), normals[0] * outward);
    for (uint32_t i = 1; i < count; ++i)
        ring.vertex(f.point({outline[i], z1}), normals[i] * outward);
    for (uint32_t i = 0; i < count; ++i) {
        uint32_t j = (i + 1) % count;
        ring.quad(bottom + i, bottom + j, top + j, top + i);
    }
}

// One flat part from four corners; the normal faces along `outside`.
void flatQuad(MeshBuilder& mb, const glm::vec3 (&p)[4], glm::vec3 outside) {
    glm::vec3 n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    if (glm::dot(n, outside) < 0.0f) n = -n;
    mb.beginPart();
    Writer w(mb);
    uint32_t a = w.vertex(p[0], n), b = w.vertex(p[1], n);
    uint32_t c = w.vertex(p[2], n), d = w.vertex(p[3], n);
    w.quad(a, b, c, d);
}

// Side faces of a prism whose cross-section is `outline`: one flat part per outline edge.
void prismSides(MeshBuilder& mb, const Frame& f, std::span<const glm::vec2> outline, float z0,
                float z1) {
    for (size_t i = 0; i < outline.size(); ++i) {
        glm::vec2 a = outline[i], b = outline[(i + 1) % outline.size()];
        const glm::vec3 p[4] = {f.point({a, z0}), f.point({b, z0}), f.point({b, z1}),
                                f.point({a, z1})};
        flatQuad(mb, p, f.dir({b.y - a.y, a.x - b.x, 0})); // outlines run counter-clockwise
    }
}

std::vector<glm::vec2> circleAt(std::span<const glm::vec2> directions, float radius) {
    std::vector<glm::vec2> points;
    for (auto d : directions) points.push_back(glm::normalize(d) * radius);
    return points;
}

} // namespace

Frame frameAlong(glm::vec3 origin, glm::vec3 axis) {
    Frame f;
    f.origin = origin;
    f.az = glm::normalize(axis);
    glm::vec3 helper = std::abs(f.az.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    f.ax = glm::normalize(glm::cross(helper, f.az));
    f.ay = glm::cross(f.az, f.ax);
    return f;
}

void addLathe(MeshBuilder& mb, const Frame& f, std::span<const glm::vec2> profile, int segments,
              bool onePart) {
    const size_t count = profile.size();
    std::vector<glm::vec2> segNormal(count - 1), pointNormal(count);
    for (size_t k = 0; k + 1 < count; ++k) {
        glm::vec2 t = profile[k + 1] - profile[k];
        segNormal[k] = glm::normalize(glm::vec2(t.y, -t.x));
    }
    for (size_t k = 0; k < count; ++k) {
        glm::vec2 n = (k > 0 ? segNormal[k - 1] : glm::vec2(0)) +
                      (k + 1 < count ? segNormal[k] : glm::vec2(0));
        pointNormal[k] = glm::normalize(n);
    }
    std::vector<glm::vec2> dirs(segments);
    for (int i = 0; i < segments; ++i) dirs[i] = unitAt(kTwoPi * float(i) / float(segments));
    if (onePart) mb.beginPart();
    for (size_t k = 0; k + 1 < count; ++k) {
        glm::vec2 p0 = profile[k], p1 = profile[k + 1];
        if (!onePart) mb.beginPart();
        Writer w(mb);
        glm::vec2 n0 = onePart ? pointNormal[k] : segNormal[k];
        glm::vec2 n1 = onePart ? pointNormal[k + 1] : segNormal[k];
        auto ring = [&](glm::vec2 p, glm::vec2 n) {
            uint32_t first = 0;
            for (int i = 0; i < segments; ++i) {
                uint32_t v = w.vertex(f.point({dirs[i] * p.x, p.y}), f.dir({dirs[i] * n.x, n.y}));
                if (i == 0) first = v;
            }
            return first;
        };
        uint32_t a = ring(p0, n0), b = ring(p1, n1);
        for (int i = 0; i < segments; ++i) {
            uint32_t j = uint32_t((i + 1) % segments);
            if (p0.x > 0.0f) w.triangle(a + i, a + j, b + j);
            if (p1.x > 0.0f) w.triangle(a + i, b + j, b + i);
        }
    }
}

void addHexPrism(MeshBuilder& mb, const Frame& f, float acrossCorners, float z0, float z1,
                 float boreRadius, int boreSegments) {
    const float r = acrossCorners * 0.5f;
    std::vector<glm::vec2> corners(6);
    for (int k = 0; k < 6; ++k) corners[k] = unitAt(kTwoPi * float(k) / 6.0f) * r;
    prismSides(mb, f, corners, z0, z1);
    if (boreRadius <= 0.0f) {
        flatRing(mb, f, corners, {}, z1, 1.0f);
        flatRing(mb, f, corners, {}, z0, -1.0f);
        return;
    }
    // The hexagon is sampled at the bore's angles (a multiple of 6 includes the corners).
    const float apothem = r * std::cos(kTwoPi / 12.0f);
    std::vector<glm::vec2> outer, dirs;
    for (int i = 0; i < boreSegments; ++i) {
        float a = kTwoPi * float(i) / float(boreSegments);
        float sector = std::floor(a / (kTwoPi / 6.0f));
        float flankCenter = (sector + 0.5f) * (kTwoPi / 6.0f);
        dirs.push_back(unitAt(a));
        outer.push_back(dirs.back() * (apothem / std::cos(a - flankCenter)));
    }
    std::vector<glm::vec2> bore = circleAt(dirs, boreRadius);
    flatRing(mb, f, outer, bore, z1, 1.0f);
    flatRing(mb, f, outer, bore, z0, -1.0f);
    mantle(mb, f, bore, z0, z1, -1.0f);
}

void addGear(MeshBuilder& mb, const Frame& f, int teeth, float rootRadius, float tipRadius,
             float z0, float z1, float boreRadius) {
    const float pitch = kTwoPi / float(teeth);
    std::vector<glm::vec2> outline;
    for (int t = 0; t < teeth; ++t) {
        float a = pitch * float(t);
        outline.push_back(unitAt(a) * rootRadius);
        outline.push_back(unitAt(a + 0.15f * pitch) * tipRadius);
        outline.push_back(unitAt(a + 0.45f * pitch) * tipRadius);
        outline.push_back(unitAt(a + 0.6f * pitch) * rootRadius);
    }
    prismSides(mb, f, outline, z0, z1);
    std::vector<glm::vec2> bore = circleAt(outline, boreRadius);
    flatRing(mb, f, outline, bore, z1, 1.0f);
    flatRing(mb, f, outline, bore, z0, -1.0f);
    mantle(mb, f, bore, z0, z1, -1.0f);
}

// The boundary of a cell centred at the origin, corners included, walked counter-clockwise
// from the middle of its right side. Equal spacing makes neighbouring cells share points.
static std::vector<glm::vec2> cellOutline(glm::vec2 half, int segments) {
    const int perHalfSide = segments / 8;
    std::vector<glm::vec2> points;
    const glm::vec2 corners[4] = {
        {half.x, half.y}, {-half.x, half.y}, {-half.x, -half.y}, {half.x, -half.y}};
    glm::vec2 start(half.x, 0.0f);
    for (int c = 0; c < 4; ++c) {
        glm::vec2 corner = corners[c], next = corners[(c + 1) % 4];
        glm::vec2 end = (corner + next) * 0.5f;
        for (int i = 0; i < perHalfSide; ++i)
            points.push_back(glm::mix(start, corner, float(i) / float(perHalfSide)));
        for (int i = 0; i < perHalfSide; ++i)
            points.push_back(glm::mix(corner, end, float(i) / float(perHalfSide)));
        start = end;
    }
    return points;
}

static void plateFace(MeshBuilder& mb, const Frame& f, const PlateSpec& s, float z, float up) {
    mb.beginPart();
    Writer w(mb);
    const glm::vec3 n = f.dir({0, 0, up});
    const glm::vec2 cell = s.size / glm::vec2(s.cells);
    const std::vector<glm::vec2> outline = cellOutline(cell * 0.5f, s.holeSegments);
    const std::vector<glm::vec2> hole =
        circleAt(outline, 0.5f * s.holeFraction * std::min(cell.x, cell.y));
    const uint32_t count = static_cast<uint32_t>(outline.size());
    for (int iy = 0; iy < s.cells.y; ++iy)
        for (int ix = 0; ix < s.cells.x; ++ix) {
            glm::vec2 c = -s.size * 0.5f + cell * (glm::vec2(ix, iy) + 0.5f);
            bool holed = (iy * s.cells.x + ix) % s.holeEvery == 0;
            uint32_t o = w.vertex(f.point({c + outline[0], z}), n);
            for (uint32_t i = 1; i < count; ++i) w.vertex(f.point({c + outline[i], z}), n);
            if (!holed) {
                uint32_t mid = w.vertex(f.point({c, z}), n);
                for (uint32_t i = 0; i < count; ++i) w.triangle(mid, o + i, o + (i + 1) % count);
                continue;
            }
            uint32_t in = w.vertex(f.point({c + hole[0], z}), n);
            for (uint32_t i = 1; i < count; ++i) w.vertex(f.point({c + hole[i], z}), n);
            for (uint32_t i = 0; i < count; ++i)
                w.quad(o + i, o + (i + 1) % count, in + (i + 1) % count, in + i);
        }
}

void addPlateWithHoles(MeshBuilder& mb, const Frame& f, const PlateSpec& s) {
    const float h = s.thickness * 0.5f;
    plateFace(mb, f, s, h, 1.0f);
    plateFace(mb, f, s, -h, -1.0f);
    const glm::vec2 cell = s.size / glm::vec2(s.cells);
    const std::vector<glm::vec2> outline = cellOutline(cell * 0.5f, s.holeSegments);
    const std::vector<glm::vec2> hole =
        circleAt(outline, 0.5f * s.holeFraction * std::min(cell.x, cell.y));
    for (int iy = 0; iy < s.cells.y; ++iy)
        for (int ix = 0; ix < s.cells.x; ++ix) {
            if ((iy * s.cells.x + ix) % s.holeEvery != 0) continue;
            Frame at = f;
            at.origin = f.point({-s.size * 0.5f + cell * (glm::vec2(ix, iy) + 0.5f), 0});
            mantle(mb, at, hole, -h, h, -1.0f);
        }
    const glm::vec2 e = s.size * 0.5f;
    const std::vector<glm::vec2> rim = {{e.x, -e.y}, {e.x, e.y}, {-e.x, e.y}, {-e.x, -e.y}};
    prismSides(mb, f, rim, -h, h);
}

void addTube(MeshBuilder& mb, std::span<const glm::vec3> path, float radius, int segments) {
    mb.beginPart();
    Writer w(mb);
    const size_t count = path.size();
    glm::vec3 normal = frameAlong(path[0], path[1] - path[0]).ax;
    uint32_t previous = 0;
    for (size_t k = 0; k < count; ++k) {
        glm::vec3 in = k > 0 ? glm::normalize(path[k] - path[k - 1]) : glm::vec3(0);
        glm::vec3 out = k + 1 < count ? glm::normalize(path[k + 1] - path[k]) : glm::vec3(0);
        glm::vec3 tangent = glm::normalize(in + out);
        // Parallel transport keeps the rings from twisting along the path.
        normal = glm::normalize(normal - glm::dot(normal, tangent) * tangent);
        glm::vec3 binormal = glm::cross(tangent, normal);
        uint32_t first = 0;
        for (int i = 0; i < segments; ++i) {
            glm::vec2 d = unitAt(kTwoPi * float(i) / float(segments));
            glm::vec3 radial = d.x * normal + d.y * binormal;
            uint32_t v = w.vertex(path[k] + radial * radius, radial);
            if (i == 0) first = v;
        }
        if (k > 0)
            for (int i = 0; i < segments; ++i) {
                uint32_t j = uint32_t((i + 1) % segments);
                w.quad(previous + i, previous + j, first + j, first + i);
            }
        previous = first;
    }
}

} // namespace scene
