// shapes.h - machine-part shapes built on MeshBuilder: turned profiles, hex prisms, gears,
// plates with holes and swept tubes, each CAD face its own part, placed by a local frame.
#pragma once

#include <span>

#include "scene/mesh_builder.h"

namespace scene {

// An orthonormal placement: local (x, y, z) maps to origin + x * ax + y * ay + z * az.
struct Frame {
    glm::vec3 origin{0.0f};
    glm::vec3 ax{1, 0, 0}, ay{0, 1, 0}, az{0, 0, 1};
    glm::vec3 point(glm::vec3 p) const { return origin + p.x * ax + p.y * ay + p.z * az; }
    glm::vec3 dir(glm::vec3 d) const { return d.x * ax + d.y * ay + d.z * az; }
};
// A frame at `origin` whose local z runs along `axis`.
Frame frameAlong(glm::vec3 origin, glm::vec3 axis);

// Surface of revolution around local z. `profile` holds (radius, z) points walked so that the
// solid lies on the left; each profile segment becomes one part (flat annulus, cylinder or
// cone), or with onePart the whole profile is one smooth part (tyres, castings).
void addLathe(MeshBuilder& mb, const Frame& f, std::span<const glm::vec2> profile, int segments,
              bool onePart = false);

// Hexagon prism along z (bolt heads, nuts): six flank parts, and a top and bottom part that
// are rings around a hole of `boreRadius` (or full hexagons when it is 0).
void addHexPrism(MeshBuilder& mb, const Frame& f, float acrossCorners, float z0, float z1,
                 float boreRadius, int boreSegments);

// Spur gear along z: every tooth flank, tip and root land is its own flat part; the two
// faces and the bore are one part each.
void addGear(MeshBuilder& mb, const Frame& f, int teeth, float rootRadius, float tipRadius,
             float z0, float z1, float boreRadius);

struct PlateSpec {
    glm::vec2 size{1.0f};
    float thickness = 0.01f;
    glm::ivec2 cells{4, 4};    // the faces are tessellated cell by cell
    int holeEvery = 1;         // every n-th cell (row-major) has a hole
    float holeFraction = 0.6f; // hole diameter relative to the cell's smaller side
    int holeSegments = 16;     // a multiple of 8
};
// Slab centred on the frame's origin in its xy plane: a top and bottom part holding every
// cell (thousands of triangles on large plates), one part per hole bore and four side parts.
void addPlateWithHoles(MeshBuilder& mb, const Frame& f, const PlateSpec& spec);

// Round tube swept along a polyline: one smooth part (hoses, exhaust pipes, frame tubes).
void addTube(MeshBuilder& mb, std::span<const glm::vec3> path, float radius, int segments);

} // namespace scene
