// procedural_parts.cpp - the geometries of the procedural scenes' parts catalogue.
#include "scene/procedural/procedural_parts.h"

#include <algorithm>
#include <cmath>

#include "scene/procedural/shapes.h"

namespace scene::procedural {

namespace {

// The metric thread size of diameter `d` metres: "M10".
std::string thread(float d) {
    std::string name = "M"; // appended, as "M" + ... trips GCC 12's -Wrestrict
    return name += std::to_string(std::lround(d * 1000.0f));
}

} // namespace

uint32_t makeBolt(Scene& s, float d, float length) {
    MeshBuilder mb;
    addHexPrism(mb, {}, 1.8f * d, 0.0f, 0.65f * d, 0.0f, 0);
    const float r = 0.5f * d, c = 0.1f * d;
    const glm::vec2 shank[] = {{0, -length}, {r - c, -length}, {r, -length + c}, {r, 0}};
    addLathe(mb, {}, shank, 12);
    return mb.finish(s, "bolt " + thread(d));
}

uint32_t makeNut(Scene& s, float d) {
    MeshBuilder mb;
    addHexPrism(mb, {}, 1.8f * d, 0.0f, 0.8f * d, 0.5f * d, 12);
    return mb.finish(s, "nut " + thread(d));
}

uint32_t makeWasher(Scene& s, float d) {
    MeshBuilder mb;
    const float ri = 0.55f * d, ro = 1.0f * d, t = 0.15f * d;
    const glm::vec2 ring[] = {{ri, 0}, {ro, 0}, {ro, t}, {ri, t}, {ri, 0}};
    addLathe(mb, {}, ring, 16);
    return mb.finish(s, "washer " + thread(d));
}

// Three gears and their shaft in one geometry: a lay-shaft cluster of many tiny flank parts.
uint32_t makeGearCluster(Scene& s, int teeth) {
    MeshBuilder mb;
    float z = 0.0f;
    for (int g = 0; g < 3; ++g) {
        int n = teeth - 8 * g;
        float r = 0.0008f * float(n);
        addGear(mb, frameAlong({0, 0, z}, {0, 0, 1}), n, r, r + 0.003f, 0, 0.02f, 0.01f);
        z += 0.03f;
    }
    const glm::vec2 shaft[] = {{0, -0.03f}, {0.01f, -0.03f}, {0.01f, z + 0.02f}, {0, z + 0.02f}};
    addLathe(mb, {}, shaft, 24);
    return mb.finish(s, "gear cluster " + std::to_string(teeth));
}

uint32_t makeHose(Scene& s, Rng& rng, float length, int rings) {
    MeshBuilder mb;
    std::vector<glm::vec3> path;
    const float wave = rng.uniform(0.01f, 0.04f), turns = rng.uniform(2.0f, 5.0f);
    for (int k = 0; k <= rings; ++k) {
        float t = float(k) / float(rings);
        float a = 2.0f * kPi * turns * t;
        path.push_back({length * t, wave * std::sin(a), wave * 0.5f * std::cos(a)});
    }
    addTube(mb, path, 0.012f, 32);
    return mb.finish(s, "hose");
}

uint32_t makeRail(Scene& s, float length, float height) {
    MeshBuilder mb;
    PlateSpec web{{length, height}, 0.006f, {int(length / 0.05f), 3}, 1, 0.45f, 16};
    Frame f = frameAlong({0, 0, 0}, {0, 1, 0});
    f.ax = {1, 0, 0};
    f.ay = {0, 0, 1};
    f.az = {0, -1, 0};
    addPlateWithHoles(mb, f, web);
    mb.addBox({0, 0.03f, height * 0.5f}, {length, 0.06f, 0.006f});
    mb.addBox({0, 0.03f, -height * 0.5f}, {length, 0.06f, 0.006f});
    return mb.finish(s, "frame rail");
}

uint32_t makeFloorPan(Scene& s, glm::vec2 size) {
    MeshBuilder mb;
    addPlateWithHoles(mb, {}, {size, 0.003f, {48, 24}, 5, 0.5f, 16});
    return mb.finish(s, "floor pan");
}

uint32_t makeTubeBar(Scene& s, float length, std::string name) {
    MeshBuilder mb;
    const float ro = 0.035f, ri = 0.03f;
    const glm::vec2 tube[] = {{ri, 0}, {ro, 0}, {ro, length}, {ri, length}, {ri, 0}};
    addLathe(mb, {}, tube, 32);
    return mb.finish(s, std::move(name));
}

uint32_t makeBracket(Scene& s) {
    MeshBuilder mb;
    addPlateWithHoles(mb, {}, {{0.12f, 0.08f}, 0.006f, {3, 2}, 1, 0.5f, 16});
    Frame up = frameAlong({0, -0.04f, 0.04f}, {0, 1, 0});
    addPlateWithHoles(mb, up, {{0.12f, 0.08f}, 0.006f, {3, 2}, 2, 0.5f, 16});
    return mb.finish(s, "angle bracket");
}

uint32_t makeTyre(Scene& s) {
    MeshBuilder mb;
    std::vector<glm::vec2> profile;
    // A rounded tread section, walked from the inner bead over the tread and back.
    for (int k = 0; k <= 40; ++k) {
        float a = -kPi * 0.5f + kPi * float(k) / 40.0f;
        profile.push_back({0.25f + 0.08f * std::cos(a), 0.1f * std::sin(a) * -1.0f});
    }
    std::reverse(profile.begin(), profile.end());
    addLathe(mb, {}, profile, 128, true);
    return mb.finish(s, "tyre");
}

uint32_t makeRim(Scene& s) {
    MeshBuilder mb;
    const glm::vec2 rim[] = {{0.26f, -0.1f}, {0.26f, 0.1f},  {0.24f, 0.1f},   {0.24f, 0.04f},
                             {0.2f, 0.03f},  {0.12f, 0.05f}, {0.06f, 0.05f},  {0.06f, 0.03f},
                             {0.1f, 0.02f},  {0.2f, 0.0f},   {0.23f, -0.05f}, {0.23f, -0.1f},
                             {0.26f, -0.1f}};
    addLathe(mb, {}, rim, 64);
    return mb.finish(s, "wheel rim");
}

uint32_t makeDisc(Scene& s) {
    MeshBuilder mb;
    const glm::vec2 disc[] = {{0.06f, 0}, {0.16f, 0}, {0.16f, 0.025f}, {0.06f, 0.025f}, {0.06f, 0}};
    addLathe(mb, {}, disc, 64);
    mb.addBox({0.16f, 0, 0.0125f}, {0.06f, 0.12f, 0.05f});
    return mb.finish(s, "brake disc and caliper");
}

uint32_t makeCasting(Scene& s, float length, float radius, int segments) {
    MeshBuilder mb;
    std::vector<glm::vec2> profile{{0, 0}};
    for (int k = 0; k <= 24; ++k) {
        float t = float(k) / 24.0f;
        profile.push_back({radius * (0.6f + 0.4f * std::sin(kPi * t)), length * t});
    }
    profile.push_back({0, length});
    addLathe(mb, {}, profile, segments, true);
    const glm::vec2 flange[] = {
        {radius * 0.5f, 0}, {radius * 1.15f, 0}, {radius * 1.15f, 0.012f}, {radius * 0.5f, 0.012f}};
    addLathe(mb, frameAlong({0, 0, -0.012f}, {0, 0, 1}), flange, 48);
    return mb.finish(s, "cast housing");
}

uint32_t makeEngineBlock(Scene& s, glm::vec3 size) {
    MeshBuilder mb;
    addPlateWithHoles(mb, frameAlong({0, 0, size.z}, {0, 0, 1}),
                      {{size.x, size.y}, 0.01f, {4, 1}, 1, 0.8f, 32});
    mb.addBox({0, 0, size.z * 0.5f - 0.005f}, {size.x, size.y, size.z - 0.01f});
    return mb.finish(s, "engine block");
}

uint32_t makeFinPack(Scene& s, int fins, glm::vec2 size) {
    MeshBuilder mb;
    for (int i = 0; i < fins; ++i)
        mb.addBox({0.0f, -size.x * 0.5f + size.x * (float(i) + 0.5f) / float(fins), 0.0f},
                  {0.03f, 0.0015f, size.y});
    return mb.finish(s, "radiator fins");
}

uint32_t makePulley(Scene& s, float r) {
    MeshBuilder mb;
    std::vector<glm::vec2> profile{{0.01f, 0}, {r, 0}};
    for (int g = 0; g < 6; ++g) {
        float z = 0.006f * float(g);
        profile.push_back({r - 0.004f, z + 0.003f});
        profile.push_back({r, z + 0.006f});
    }
    profile.push_back({0.01f, 0.036f});
    profile.push_back({0.01f, 0.0f});
    addLathe(mb, {}, profile, 48);
    return mb.finish(s, "pulley");
}

} // namespace scene::procedural
