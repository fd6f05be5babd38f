// procedural.cpp - seeded machine-like assemblies: a ladder frame with wheels, engine, gearbox,
// radiator, hoses and fasteners (car-like), or one gearbox module (small).
#include "scene/procedural/procedural.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

#include "scene/procedural/procedural_parts.h"
#include "scene/procedural/shapes.h"

namespace scene {

namespace {

using namespace procedural;

struct Materials {
    uint32_t steel, blackSteel, framePaint, enginePaint, aluminium, brass, rubber, copper;
};

Materials addMaterials(Scene& s, Rng& rng) {
    // The body colour is the seed's one visible signature at a glance.
    glm::vec4 paint{rng.uniform(0.1f, 0.8f), rng.uniform(0.1f, 0.5f), rng.uniform(0.2f, 0.7f), 1};
    return {addMaterial(s, "steel", {0.62f, 0.64f, 0.68f, 1}),
            addMaterial(s, "black oxide steel", {0.18f, 0.18f, 0.2f, 1}),
            addMaterial(s, "frame paint", paint),
            addMaterial(s, "engine red", {0.62f, 0.12f, 0.1f, 1}),
            addMaterial(s, "cast aluminium", {0.78f, 0.79f, 0.8f, 1}),
            addMaterial(s, "brass", {0.78f, 0.62f, 0.28f, 1}),
            addMaterial(s, "rubber", {0.08f, 0.08f, 0.09f, 1}),
            addMaterial(s, "copper", {0.72f, 0.42f, 0.24f, 1})};
}

glm::mat4 placeAt(glm::vec3 position) {
    return glm::translate(glm::mat4(1.0f), position);
}
// Places a geometry built along local z so that z runs along `axis`.
glm::mat4 placeAlong(glm::vec3 position, glm::vec3 axis, float spin = 0.0f) {
    Frame f = frameAlong(position, axis);
    glm::mat4 m(glm::vec4(f.ax, 0), glm::vec4(f.ay, 0), glm::vec4(f.az, 0), glm::vec4(position, 1));
    return glm::rotate(m, spin, {0, 0, 1});
}

// --- sub-assemblies ---
// Objects are named as a CAD user would call them: one of a kind by what it is and where
// ("frame rail left", "tyre front left"; x points to the front, y to the left), the rest by
// their geometry's name and a number per kind ("bolt M10 #12", "cross member #3"). Paths
// group them by sub-assembly: "car/chassis/angle bracket #2/bolt M6 #5".

const std::string kCar = "car", kChassis = "car/chassis";

struct Catalogue {
    uint32_t bolt, smallBolt, nut, smallNut, washer, hose, cluster;
};

// The fasteners both presets place everywhere (M10 and M6), made once per scene.
Catalogue makeFasteners(Scene& s) {
    Catalogue c{};
    c.bolt = makeBolt(s, 0.010f, 0.04f);
    c.smallBolt = makeBolt(s, 0.006f, 0.02f);
    c.nut = makeNut(s, 0.010f);
    c.smallNut = makeNut(s, 0.006f);
    c.washer = makeWasher(s, 0.010f);
    return c;
}

Catalogue makeCatalogue(Scene& s, Rng& rng) {
    Catalogue c = makeFasteners(s);
    c.hose = makeHose(s, rng, 3.2f, 320);
    c.cluster = makeGearCluster(s, rng.range(44, 52));
    return c;
}

// Bolted joint through a hole: the bolt head on one side, the nut `grip` below.
// The joint's bolt and nut go into `group`.
void addJoint(Scene& s, NameCounter& names, const Catalogue& c, const Materials& m, glm::vec3 at,
              glm::vec3 axis, float grip, bool small, const std::string& group) {
    names.add(s, small ? c.smallBolt : c.bolt, m.blackSteel, placeAlong(at, axis), group);
    names.add(s, small ? c.smallNut : c.nut, m.steel, placeAlong(at - axis * grip, -axis), group);
}

// "front left", "rear right", ...: where a point of the car is, seen from the driver's seat.
std::string corner(glm::vec3 at) {
    return std::string(at.x > 0 ? "front" : "rear") + (at.y > 0 ? " left" : " right");
}

void addWheel(Scene& s, NameCounter& names, const Catalogue& c, const Materials& m, glm::vec3 hub,
              float side, uint32_t tyre, uint32_t rim, uint32_t disc) {
    glm::vec3 out{0, side, 0};
    const std::string where = corner(hub), group = joinPath(kCar, "wheel " + where);
    addNamedObject(s, tyre, m.rubber, placeAlong(hub, out), group, "tyre " + where);
    addNamedObject(s, rim, m.aluminium, placeAlong(hub, out), group, "wheel rim " + where);
    addNamedObject(s, disc, m.steel, placeAlong(hub - out * 0.09f, out), group,
                   "brake disc and caliper " + where);
    for (int k = 0; k < 5; ++k) {
        float a = 2.0f * kPi * float(k) / 5.0f;
        glm::vec3 at = hub + glm::vec3(0.08f * std::cos(a), 0, 0.08f * std::sin(a)) + out * 0.05f;
        names.add(s, c.nut, m.steel, placeAlong(at, out), group);
    }
}

struct Chassis {
    float length, track, railHeight, wheelbase;
};

void addFrame(Scene& s, NameCounter& names, const Catalogue& c, const Materials& m,
              const Chassis& ch, Rng& rng) {
    const uint32_t rail = makeRail(s, ch.length, ch.railHeight);
    const uint32_t cross = makeTubeBar(s, ch.track * 0.6f, "cross member");
    const uint32_t bracket = makeBracket(s);
    const float y = ch.track * 0.3f, z = 0.35f;
    addNamedObject(s, rail, m.framePaint, placeAt({0, y, z}), kChassis, "frame rail left");
    addNamedObject(s, rail, m.framePaint, glm::rotate(placeAt({0, -y, z}), kPi, {0, 0, 1}),
                   kChassis, "frame rail right");
    const int members = rng.range(5, 7);
    for (int i = 0; i < members; ++i) {
        float x = -ch.length * 0.45f + ch.length * 0.9f * float(i) / float(members - 1);
        names.add(s, cross, m.framePaint, placeAlong({x, -y, z}, {0, 1, 0}), kChassis);
        for (float side : {-1.0f, 1.0f}) {
            glm::vec3 at{x, side * (y - 0.07f), z + 0.08f};
            const uint32_t b =
                names.add(s, bracket, m.steel,
                          glm::rotate(placeAt(at), side > 0 ? 0.0f : kPi, {0, 0, 1}), kChassis);
            const std::string group = s.objects[b].path; // a copy: adding objects moves it
            for (float dx : {-0.04f, 0.0f, 0.04f})
                addJoint(s, names, c, m, at + glm::vec3(dx, 0, 0.01f), {0, 0, 1}, 0.02f, true,
                         group);
        }
    }
    addNamedObject(s, makeFloorPan(s, {ch.length * 0.5f, ch.track * 0.6f}), m.framePaint,
                   placeAt({-ch.length * 0.12f, 0, z + ch.railHeight * 0.5f + 0.01f}), kChassis,
                   "floor pan");
}

void addRunningGear(Scene& s, NameCounter& names, const Catalogue& c, const Materials& m,
                    const Chassis& ch) {
    const uint32_t tyre = makeTyre(s), rim = makeRim(s), disc = makeDisc(s);
    const uint32_t axle = makeTubeBar(s, ch.track, "axle");
    const uint32_t diff = makeCasting(s, 0.3f, 0.14f, 96);
    for (float x : {-ch.wheelbase * 0.5f, ch.wheelbase * 0.5f}) {
        addNamedObject(s, axle, m.steel, placeAlong({x, -ch.track * 0.5f, 0.33f}, {0, 1, 0}), kCar,
                       x > 0 ? "axle front" : "axle rear");
        for (float side : {-1.0f, 1.0f})
            addWheel(s, names, c, m, {x, side * ch.track * 0.5f, 0.33f}, side, tyre, rim, disc);
    }
    addNamedObject(s, diff, m.aluminium,
                   placeAlong({-ch.wheelbase * 0.5f + 0.15f, 0, 0.33f}, {-1, 0, 0}), kCar,
                   "differential housing");
}

void addEngine(Scene& s, NameCounter& names, const Catalogue& c, const Materials& m,
               const Chassis& ch, Rng& rng) {
    const std::string engine = joinPath(kCar, "engine");
    const int cylinders = rng.range(4, 6);
    const glm::vec3 size{0.11f * float(cylinders), 0.3f, 0.35f};
    const glm::vec3 base{ch.wheelbase * 0.5f - 0.1f, 0, 0.3f};
    addNamedObject(s, makeEngineBlock(s, size), m.enginePaint, placeAt(base), engine,
                   "engine block");
    const uint32_t gearbox = makeCasting(s, 0.6f, 0.16f, 128);
    addNamedObject(s, gearbox, m.aluminium,
                   placeAlong(base + glm::vec3(-size.x * 0.5f, 0, 0.15f), {-1, 0, 0}), engine,
                   "gearbox housing");
    const uint32_t pulley = makePulley(s, 0.07f);
    for (int k = 0; k < 3; ++k)
        names.add(s, pulley, m.steel,
                  placeAlong(base + glm::vec3(size.x * 0.5f + 0.02f, 0.08f * float(k - 1),
                                              0.1f + 0.08f * float(k % 2)),
                             {1, 0, 0}),
                  engine);
    for (int i = 0; i < cylinders * 8; ++i) {
        float x = -size.x * 0.5f + size.x * (float(i / 2) + 0.5f) / float(cylinders * 4);
        glm::vec3 at = base + glm::vec3(x, (i % 2 ? 1.0f : -1.0f) * 0.13f, size.z + 0.005f);
        names.add(s, c.bolt, m.blackSteel, placeAlong(at, {0, 0, 1}), engine);
        names.add(s, c.washer, m.steel, placeAlong(at - glm::vec3(0, 0, 0.0015f), {0, 0, 1}),
                  engine);
    }
    const uint32_t fins = makeFinPack(s, 160, {0.6f, 0.4f});
    addNamedObject(s, fins, m.copper, placeAt({ch.length * 0.5f - 0.05f, 0, 0.6f}), kCar,
                   "radiator");
}

struct Site {
    glm::vec3 at, axis; // the bolt head sits at `at` and points along `axis`
};

// Fastener sites: the holes of both rail webs, then bolt rows on the rail flanges, each group
// in the order the seed shuffles it, so every seed fastens a different subset.
std::vector<Site> fastenerSites(const Chassis& ch, Rng& rng) {
    std::vector<Site> web, flange;
    const int columns = int(ch.length / 0.05f);
    const float cell = ch.length / float(columns);
    const float railY = ch.track * 0.3f;
    for (float side : {-1.0f, 1.0f})
        for (int col = 0; col < columns; ++col) {
            float x = -ch.length * 0.5f + cell * (float(col) + 0.5f);
            for (int row = 0; row < 3; ++row)
                web.push_back({{x, side * (railY + 0.004f),
                                0.35f + ch.railHeight * (float(row) - 1.0f) / 3.0f},
                               {0, side, 0}});
            for (float z : {-1.0f, 1.0f})
                flange.push_back(
                    {{x, side * (railY + 0.03f), 0.35f + z * (ch.railHeight * 0.5f + 0.003f)},
                     {0, 0, z}});
        }
    for (auto* group : {&web, &flange})
        for (size_t i = group->size(); i > 1; --i)
            std::swap((*group)[i - 1], (*group)[rng.next() % i]);
    web.insert(web.end(), flange.begin(), flange.end());
    return web;
}

struct Counts {
    double objects = 0, parts = 0, triangles = 0;
};

Counts countsOf(const Scene& s) {
    return {double(s.objects.size()), double(s.uniquePartCount()), double(s.drawnTriangleCount())};
}

Counts geometryCounts(const Scene& s, uint32_t g) {
    return {1, double(s.geometries[g].partCount), double(s.geometries[g].triangleCount)};
}

// How many fasteners, gear clusters and hoses close the gap to the target: a 3x3 linear
// system solved by Cramer's rule, then rounded (the rounding error is one item of each).
glm::ivec3 fillPlan(const Counts& gap, const Counts& a, const Counts& b, const Counts& c) {
    glm::dmat3 m(a.objects, a.parts, a.triangles, b.objects, b.parts, b.triangles, c.objects,
                 c.parts, c.triangles);
    glm::dvec3 n = glm::inverse(m) * glm::dvec3(gap.objects, gap.parts, gap.triangles);
    return glm::max(glm::ivec3(glm::round(n)), glm::ivec3(0));
}

void addFill(Scene& s, NameCounter& names, const Catalogue& c, const Materials& m,
             const Chassis& ch, Rng& rng, const Counts& target) {
    Counts now = countsOf(s);
    Counts gap{target.objects - now.objects, target.parts - now.parts,
               target.triangles - now.triangles};
    Counts joint = geometryCounts(s, c.bolt);
    joint.parts = (joint.parts + geometryCounts(s, c.nut).parts) * 0.5;
    joint.triangles = (joint.triangles + geometryCounts(s, c.nut).triangles) * 0.5;
    glm::ivec3 plan = fillPlan(gap, joint, geometryCounts(s, c.cluster), geometryCounts(s, c.hose));
    // Gear clusters stand in rows on the frame centre line, like a long transfer gearbox.
    for (int i = 0; i < plan.y; ++i) {
        int row = i % 6, col = i / 6;
        glm::vec3 at{-ch.length * 0.4f + 0.09f * float(col), -0.25f + 0.1f * float(row), 0.15f};
        names.add(s, c.cluster, i % 3 ? m.steel : m.brass,
                  placeAlong(at, {0, 0, 1}, rng.uniform(0.0f, kPi)),
                  joinPath(kCar, "transfer gearbox"));
    }
    for (int i = 0; i < plan.z; ++i) {
        float y = (i % 2 ? 1.0f : -1.0f) * (ch.track * 0.3f - 0.12f + 0.03f * float(i / 2 % 8));
        names.add(s, c.hose, i % 4 ? m.rubber : m.copper,
                  placeAt({-1.6f, y, 0.08f + 0.03f * float(i / 16)}), joinPath(kCar, "hoses"));
    }
    const std::vector<Site> sites = fastenerSites(ch, rng);
    for (int i = 0; i < plan.x; ++i) {
        Site site = sites[size_t(i / 2) % sites.size()];
        // Past the last site the rows repeat a little higher: a second row of clips.
        site.at.z += float(size_t(i / 2) / sites.size()) * 0.02f;
        const std::string rail =
            joinPath(kChassis, site.at.y > 0 ? "frame rail left" : "frame rail right");
        if (i % 2 == 0)
            names.add(s, c.bolt, m.blackSteel, placeAlong(site.at, site.axis), rail);
        else
            names.add(s, c.nut, m.steel, placeAlong(site.at - site.axis * 0.016f, -site.axis),
                      rail);
    }
}

Scene makeCarLike(uint64_t seed) {
    Scene s;
    Rng rng(seed);
    const Materials m = addMaterials(s, rng);
    const Catalogue c = makeCatalogue(s, rng);
    const Chassis ch{rng.uniform(4.0f, 4.4f), rng.uniform(1.45f, 1.6f), 0.16f,
                     rng.uniform(2.5f, 2.8f)};
    NameCounter names;
    addFrame(s, names, c, m, ch, rng);
    addRunningGear(s, names, c, m, ch);
    addEngine(s, names, c, m, ch, rng);
    addFill(s, names, c, m, ch, rng, {2260, 99000, 2350000});
    return s;
}

// One gearbox module on a holed base plate: every shape kind, a few thousand parts.
Scene makeSmall(uint64_t seed) {
    Scene s;
    Rng rng(seed);
    const Materials m = addMaterials(s, rng);
    Catalogue c = makeFasteners(s);
    c.cluster = makeGearCluster(s, rng.range(30, 40));
    NameCounter names;
    const std::string module = "gearbox module", plate = joinPath(module, "base plate");
    MeshBuilder mb;
    addPlateWithHoles(mb, {}, {{0.6f, 0.4f}, 0.01f, {12, 8}, 3, 0.5f, 16});
    addNamedObject(s, mb.finish(s, "base plate"), m.framePaint, placeAt({0, 0, 0}), module,
                   "base plate");
    const int clusters = rng.range(3, 5);
    for (int i = 0; i < clusters; ++i)
        names.add(s, c.cluster, m.steel,
                  placeAlong({-0.2f + 0.12f * float(i), -0.06f + 0.05f * float(i % 2), 0.005f},
                             {0, 0, 1}, rng.uniform(0.0f, kPi)),
                  module);
    const uint32_t bracket = makeBracket(s);
    for (int i = 0; i < 4; ++i) {
        glm::vec3 at{-0.24f + 0.16f * float(i), -0.15f, 0.008f};
        const uint32_t b = names.add(s, bracket, m.steel, placeAt(at), module);
        const std::string group = s.objects[b].path; // a copy: adding objects moves it
        for (float dx : {-0.04f, 0.0f, 0.04f})
            addJoint(s, names, c, m, at + glm::vec3(dx, 0, 0.01f), {0, 0, 1}, 0.02f, true, group);
    }
    // The back rows of plate holes (every third cell has one) carry bolts with washers.
    for (int cell = 5 * 12; cell < 8 * 12; cell += 3) {
        glm::vec3 at{-0.275f + 0.05f * float(cell % 12), -0.175f + 0.05f * float(cell / 12),
                     0.0065f};
        addJoint(s, names, c, m, at, {0, 0, 1}, 0.013f, false, plate);
        names.add(s, c.washer, m.steel, placeAlong(at - glm::vec3(0, 0, 0.0015f), {0, 0, 1}),
                  plate);
    }
    return s;
}

} // namespace

const std::vector<std::string>& proceduralPresets() {
    static const std::vector<std::string> names = {"small", "car-like"};
    return names;
}

Scene makeProcedural(const ProceduralOptions& options) {
    Scene scene;
    if (options.preset == "small")
        scene = makeSmall(options.seed);
    else if (options.preset == "car-like")
        scene = makeCarLike(options.seed);
    else
        throw std::invalid_argument("unknown procedural preset '" + options.preset + "'");
    validate(scene);
    return scene;
}

} // namespace scene
