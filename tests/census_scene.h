// census_scene.h - a scene whose hidden parts are known by construction, for the visibility
// census's tests: a closed box with a cube inside; an open cup with a cube standing in it a
// little above the floor (its underside hidden, its sides seen only from above the rim); a
// block with a square shaft that a pin fills (only the pin's top shows, and only to views
// that look down the shaft). Every wall is a single two-sided face, as the renderer draws
// them, so nothing is seen through from behind.
#pragma once

#include <array>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/mesh_builder.h"
#include "scene/scene.h"

namespace testing_support {

struct CensusScene {
    scene::Scene scene;
    std::set<uint32_t> neverSeen;  // the unique parts no view from outside can show
    uint32_t pinTop = 0;           // seen only by views within 45 degrees of +z
    uint32_t shell = 0, inner = 0; // the closed box and the cube inside it (objects)
};

namespace census_detail {

using Quad = std::array<glm::vec3, 4>;

inline void quad(scene::MeshBuilder& b, glm::vec3 a, glm::vec3 c1, glm::vec3 c2, glm::vec3 d) {
    const Quad q = {a, c1, c2, d};
    b.addFlatFace(q);
}

// An open-topped box: the floor (part 0) and four walls, x and y from -h to h, z from z0 to z1.
inline void addCup(scene::MeshBuilder& b, float h, float z0, float z1) {
    quad(b, {-h, -h, z0}, {-h, h, z0}, {h, h, z0}, {h, -h, z0});
    quad(b, {h, -h, z0}, {h, h, z0}, {h, h, z1}, {h, -h, z1});
    quad(b, {-h, h, z0}, {-h, -h, z0}, {-h, -h, z1}, {-h, h, z1});
    quad(b, {h, h, z0}, {-h, h, z0}, {-h, h, z1}, {h, h, z1});
    quad(b, {-h, -h, z0}, {h, -h, z0}, {h, -h, z1}, {-h, -h, z1});
}

// A block from -4 to 4 in x and y, -3 to 3 in z, with a 2 x 2 shaft from its top down to
// z = -1: outer sides and bottom (parts 0-4), the top's frame around the opening (5-8), the
// shaft's walls (9-12) and floor (13).
inline void addShaftBlock(scene::MeshBuilder& b) {
    const float H = 4, s = 1, top = 3, bottom = -3, floor = -1;
    quad(b, {H, -H, bottom}, {H, H, bottom}, {H, H, top}, {H, -H, top});
    quad(b, {-H, H, bottom}, {-H, -H, bottom}, {-H, -H, top}, {-H, H, top});
    quad(b, {H, H, bottom}, {-H, H, bottom}, {-H, H, top}, {H, H, top});
    quad(b, {-H, -H, bottom}, {H, -H, bottom}, {H, -H, top}, {-H, -H, top});
    quad(b, {-H, H, bottom}, {H, H, bottom}, {H, -H, bottom}, {-H, -H, bottom});
    quad(b, {-H, -H, top}, {H, -H, top}, {H, -s, top}, {-H, -s, top});
    quad(b, {-H, s, top}, {H, s, top}, {H, H, top}, {-H, H, top});
    quad(b, {-H, -s, top}, {-s, -s, top}, {-s, s, top}, {-H, s, top});
    quad(b, {s, -s, top}, {H, -s, top}, {H, s, top}, {s, s, top});
    quad(b, {s, -s, floor}, {s, s, floor}, {s, s, top}, {s, -s, top});
    quad(b, {-s, s, floor}, {-s, -s, floor}, {-s, -s, top}, {-s, s, top});
    quad(b, {s, s, floor}, {-s, s, floor}, {-s, s, top}, {s, s, top});
    quad(b, {-s, -s, floor}, {s, -s, floor}, {s, -s, top}, {-s, -s, top});
    quad(b, {-s, -s, floor}, {-s, s, floor}, {s, s, floor}, {s, -s, floor});
}

} // namespace census_detail

// Box parts (MeshBuilder::addBox): +x, -x, +y, -y, +z (top), -z (bottom).
inline CensusScene makeCensusScene() {
    using namespace census_detail;
    CensusScene c;
    scene::Scene& s = c.scene;
    const uint32_t grey = scene::addMaterial(s, "grey", glm::vec4(0.7f, 0.7f, 0.7f, 1.0f));
    const auto add = [&](scene::MeshBuilder& b, const char* name, glm::dvec3 at) {
        const uint32_t geometry = b.finish(s, name);
        const glm::dmat4 world = glm::translate(glm::dmat4(1.0), at);
        const uint32_t object = scene::addObject(s, geometry, grey, world, name, name);
        return s.objects[object].uniquePartOffset;
    };
    scene::MeshBuilder b;
    b.addBox({0, 0, 0}, {8, 8, 8});
    c.shell = uint32_t(s.objects.size());
    add(b, "shell", {-12, 0, 0});
    b.addBox({0, 0, 0}, {2, 2, 2});
    c.inner = uint32_t(s.objects.size());
    const uint32_t inner = add(b, "inner cube", {-12, 0, 0});
    for (uint32_t p = 0; p < 6; ++p) c.neverSeen.insert(inner + p);
    addCup(b, 5, -1, 1);
    add(b, "cup", {12, 0, 0});
    b.addBox({0, 0, 0.6f}, {2, 2, 3}); // from z = -0.9 to 2.1, above the rim
    c.neverSeen.insert(add(b, "cube in the cup", {12, 0, 0}) + 5);
    addShaftBlock(b);
    c.neverSeen.insert(add(b, "block", {0, 14, 0}) + 13);
    b.addBox({0, 0, 0.05f}, {2, 2, 1.9f}); // fills the shaft from z = -0.9 to 1
    const uint32_t pin = add(b, "pin", {0, 14, 0});
    for (uint32_t p : {0u, 1u, 2u, 3u, 5u}) c.neverSeen.insert(pin + p);
    c.pinTop = pin + 4;
    scene::validate(s);
    return c;
}

} // namespace testing_support
