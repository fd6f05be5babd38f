// test_procedural.cpp - the procedural generator: preset statistics, determinism, validity,
// hard-edged parts with their own vertices, instancing and the long-tailed part sizes.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <set>
#include <stdexcept>

#include "scene/procedural/procedural.h"

namespace {

using scene::Scene;

Scene make(const std::string& preset, uint64_t seed) {
    return scene::makeProcedural({preset, seed});
}

// Triangle counts of every unique part (instanced parts counted once per object).
std::vector<uint32_t> uniquePartSizes(const Scene& s) {
    std::vector<uint32_t> sizes;
    for (const auto& o : s.objects)
        for (uint32_t p = 0; p < s.geometries[o.geometry].partCount; ++p)
            sizes.push_back(s.part(o, p).triangleCount);
    std::sort(sizes.begin(), sizes.end());
    return sizes;
}

template <typename T>
bool sameBytes(const scene::SharedArray<T>& a, const scene::SharedArray<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

bool sameObjects(const Scene& a, const Scene& b) {
    if (a.objects.size() != b.objects.size()) return false;
    for (size_t i = 0; i < a.objects.size(); ++i) {
        const scene::Object &x = a.objects[i], &y = b.objects[i];
        if (x.geometry != y.geometry || x.material != y.material || x.world != y.world ||
            x.uniquePartOffset != y.uniquePartOffset || x.name != y.name || x.path != y.path)
            return false;
    }
    return true;
}

void expectIdentical(const Scene& a, const Scene& b) {
    EXPECT_TRUE(sameBytes(a.vertices, b.vertices));
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_TRUE(sameBytes(a.parts, b.parts));
    ASSERT_EQ(a.geometries.size(), b.geometries.size());
    for (size_t g = 0; g < a.geometries.size(); ++g) {
        EXPECT_EQ(a.geometries[g].name, b.geometries[g].name);
        const scene::Geometry &x = a.geometries[g], &y = b.geometries[g];
        EXPECT_EQ(x.firstVertex, y.firstVertex);
        EXPECT_EQ(x.vertexCount, y.vertexCount);
        EXPECT_EQ(x.firstIndex, y.firstIndex);
        EXPECT_EQ(x.triangleCount, y.triangleCount);
        EXPECT_EQ(x.firstPart, y.firstPart);
        EXPECT_EQ(x.partCount, y.partCount);
    }
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (size_t m = 0; m < a.materials.size(); ++m) {
        EXPECT_EQ(a.materials[m].name, b.materials[m].name);
        EXPECT_EQ(a.materials[m].color, b.materials[m].color);
    }
    EXPECT_TRUE(sameObjects(a, b));
}

// Names of the objects whose geometry is called `geometry`, in scene order.
std::vector<std::string> namesOf(const Scene& s, const std::string& geometry) {
    std::vector<std::string> names;
    for (const auto& o : s.objects)
        if (s.geometries[o.geometry].name == geometry) names.push_back(o.name);
    return names;
}

} // namespace

TEST(Procedural, CarLikeMatchesReferenceStatistics) {
    for (uint64_t seed : {1ull, 2ull, 99ull}) {
        Scene s = make("car-like", seed);
        SCOPED_TRACE("seed " + std::to_string(seed));
        EXPECT_GE(s.objects.size(), 2192u);
        EXPECT_LE(s.objects.size(), 2328u);
        EXPECT_GE(s.uniquePartCount(), 96030u);
        EXPECT_LE(s.uniquePartCount(), 101970u);
        EXPECT_GE(s.drawnTriangleCount(), 2'300'000u);
        EXPECT_LE(s.drawnTriangleCount(), 2'400'000u);
        double perPart = double(s.drawnTriangleCount()) / double(s.uniquePartCount());
        EXPECT_GT(perPart, 22.0);
        EXPECT_LT(perPart, 26.0);
    }
}

// The small preset's budget is its size, which bounds the work of every test that uses it;
// how long it takes to make is printed, never compared with a number (the machine may be slow
// or busy).
TEST(Procedural, SmallPresetStaysInItsBudget) {
    double fastestMs = 1e9;
    for (int run = 0; run < 3; ++run) {
        auto start = std::chrono::steady_clock::now();
        Scene s = make("small", 7 + run);
        auto end = std::chrono::steady_clock::now();
        fastestMs =
            std::min(fastestMs, std::chrono::duration<double, std::milli>(end - start).count());
        EXPECT_GE(s.objects.size(), 50u);
        EXPECT_LE(s.objects.size(), 200u);
        EXPECT_GE(s.uniquePartCount(), 1000u);
        EXPECT_LE(s.uniquePartCount(), 4000u);
        EXPECT_LT(s.drawnTriangleCount(), 60'000u);
    }
    std::printf("[ small    ] made in %.1f ms at best of 3\n", fastestMs);
}

TEST(Procedural, SameSeedGivesTheSameSceneBitForBit) {
    for (const char* preset : {"small", "car-like"}) {
        SCOPED_TRACE(preset);
        expectIdentical(make(preset, 5), make(preset, 5));
    }
}

TEST(Procedural, DifferentSeedsGiveDifferentScenes) {
    for (const char* preset : {"small", "car-like"}) {
        Scene a = make(preset, 5), b = make(preset, 6);
        bool same = sameBytes(a.vertices, b.vertices) && sameObjects(a, b);
        EXPECT_FALSE(same) << preset;
    }
}

TEST(Procedural, ScenesValidateForSeveralSeeds) {
    for (const auto& preset : scene::proceduralPresets())
        for (uint64_t seed : {0ull, 1ull, 3ull, 1234567ull, ~0ull}) {
            Scene s = make(preset, seed);
            EXPECT_NO_THROW(scene::validate(s)) << preset << " seed " << seed;
            EXPECT_GT(s.objects.size(), 0u);
        }
}

TEST(Procedural, EveryPartUsesOnlyItsOwnVertices) {
    for (const char* preset : {"small", "car-like"}) {
        Scene s = make(preset, 11);
        for (const auto& g : s.geometries) {
            std::vector<int64_t> owner(g.vertexCount, -1);
            for (uint32_t p = 0; p < g.partCount; ++p) {
                const scene::Part& part = s.parts[g.firstPart + p];
                for (uint32_t i = 0; i < 3 * part.triangleCount; ++i) {
                    uint32_t v = s.indices[g.firstIndex + 3 * part.firstTriangle + i];
                    if (owner[v] == -1) owner[v] = p;
                    ASSERT_EQ(owner[v], int64_t(p))
                        << preset << " geometry '" << g.name << "' vertex " << v;
                }
            }
        }
    }
}

// Flat parts carry the face normal at every vertex, and every triangle of every part winds
// counter-clockwise seen from the side its vertex normals point to.
TEST(Procedural, FlatPartsHaveFaceNormalsAndWindingFollowsNormals) {
    Scene s = make("car-like", 3);
    size_t flatParts = 0, curvedParts = 0;
    for (const auto& g : s.geometries)
        for (uint32_t p = 0; p < g.partCount; ++p) {
            const scene::Part& part = s.parts[g.firstPart + p];
            std::vector<glm::vec3> faceNormals;
            std::vector<uint32_t> used;
            for (uint32_t t = 0; t < part.triangleCount; ++t) {
                const uint32_t* tri = &s.indices[g.firstIndex + 3 * (part.firstTriangle + t)];
                const scene::Vertex* v[3];
                for (int k = 0; k < 3; ++k) {
                    v[k] = &s.vertices[g.firstVertex + tri[k]];
                    used.push_back(tri[k]);
                }
                glm::vec3 c =
                    glm::cross(v[1]->position - v[0]->position, v[2]->position - v[0]->position);
                ASSERT_GT(glm::length(c), 0.0f) << "degenerate triangle in " << g.name;
                glm::vec3 n = glm::normalize(c);
                EXPECT_GT(glm::dot(n, v[0]->normal + v[1]->normal + v[2]->normal), 0.0f)
                    << g.name << " part " << p << " winds against its normals";
                faceNormals.push_back(n);
            }
            bool flat = std::all_of(faceNormals.begin(), faceNormals.end(), [&](glm::vec3 n) {
                return glm::dot(n, faceNormals[0]) > 0.99999f;
            });
            if (!flat) {
                ++curvedParts;
                continue;
            }
            ++flatParts;
            for (uint32_t v : used)
                ASSERT_GT(glm::dot(s.vertices[g.firstVertex + v].normal, faceNormals[0]), 0.9999f)
                    << g.name << " part " << p << " is flat but its normals are not";
        }
    EXPECT_GT(flatParts, 100u);
    EXPECT_GT(curvedParts, 10u);
}

TEST(Procedural, CarLikeInstancesGeometriesAndHasALongTail) {
    Scene s = make("car-like", 1);
    std::map<uint32_t, int> uses;
    for (const auto& o : s.objects) uses[o.geometry]++;
    int most = 0;
    for (auto [g, n] : uses) most = std::max(most, n);
    EXPECT_GE(most, 50);
    EXPECT_LT(s.vertices.size(), size_t(s.drawnTriangleCount() / 4)); // instancing saves memory
    std::vector<uint32_t> sizes = uniquePartSizes(s);
    EXPECT_LE(sizes[sizes.size() / 2], 8u);
    EXPECT_GE(sizes.back(), 1000u);
}

TEST(Procedural, CarLikeLooksLikeAVehicleWithUniformScale) {
    Scene s = make("car-like", 1);
    scene::Bounds b = s.bounds();
    glm::vec3 extent = b.max - b.min;
    EXPECT_GT(extent.x, 3.5f); // a frame a few metres long, narrower than long, low
    EXPECT_LT(extent.x, 5.0f);
    EXPECT_LT(extent.y, extent.x * 0.6f);
    EXPECT_LT(extent.z, extent.y);
    EXPECT_GE(s.materials.size(), 5u);
    for (const auto& o : s.objects)
        for (int axis = 0; axis < 3; ++axis)
            ASSERT_NEAR(glm::length(glm::vec3(o.world[axis])), 1.0f, 1e-5f);
}

TEST(Procedural, PresetsAreListedAndUnknownOnesThrow) {
    const auto& presets = scene::proceduralPresets();
    ASSERT_EQ(presets.size(), 2u);
    EXPECT_EQ(presets[0], "small");
    EXPECT_EQ(presets[1], "car-like");
    EXPECT_THROW(make("truck", 1), std::invalid_argument);
    EXPECT_THROW(make("", 1), std::invalid_argument);
}

TEST(Procedural, ObjectsHaveUniqueNamesAndPathsEndingInTheirNames) {
    for (const auto& preset : scene::proceduralPresets())
        for (uint64_t seed : {1ull, 7ull}) {
            SCOPED_TRACE(preset + " seed " + std::to_string(seed));
            const Scene s = make(preset, seed);
            std::set<std::string> names, paths;
            for (const auto& o : s.objects) {
                EXPECT_TRUE(names.insert(o.name).second) << "name used twice: " << o.name;
                EXPECT_TRUE(paths.insert(o.path).second) << "path used twice: " << o.path;
                ASSERT_GT(o.path.size(), o.name.size() + 1) << o.path;
                EXPECT_EQ(o.path.substr(o.path.size() - o.name.size() - 1), "/" + o.name);
            }
        }
}

TEST(Procedural, FastenersAreNumberedPerKindInSceneOrder) {
    const Scene s = make("car-like", 1);
    for (const char* kind : {"bolt M10", "bolt M6", "nut M10", "nut M6", "washer M10"}) {
        const std::vector<std::string> names = namesOf(s, kind);
        ASSERT_GT(names.size(), 10u) << kind;
        for (size_t i = 0; i < names.size(); ++i)
            ASSERT_EQ(names[i], std::string(kind) + " #" + std::to_string(i + 1));
    }
}

TEST(Procedural, CarLikeNamesAndPathsFollowItsAssemblies) {
    const Scene s = make("car-like", 1);
    std::map<std::string, std::string> pathOf;
    for (const auto& o : s.objects) pathOf[o.name] = o.path;
    // The frame comes first: rails, then a cross member and its two brackets with M6 joints.
    ASSERT_GE(s.objects.size(), 6u);
    EXPECT_EQ(s.objects[0].name, "frame rail left");
    EXPECT_EQ(s.objects[0].path, "car/chassis/frame rail left");
    EXPECT_GT(s.objects[0].world[3].y, 0.0f); // left is +y with x to the front
    EXPECT_EQ(s.objects[1].path, "car/chassis/frame rail right");
    EXPECT_EQ(s.objects[2].path, "car/chassis/cross member #1");
    EXPECT_EQ(s.objects[3].path, "car/chassis/angle bracket #1");
    EXPECT_EQ(s.objects[4].path, "car/chassis/angle bracket #1/bolt M6 #1");
    EXPECT_EQ(s.objects[5].path, "car/chassis/angle bracket #1/nut M6 #1");
    EXPECT_EQ(pathOf["floor pan"], "car/chassis/floor pan");
    EXPECT_EQ(pathOf["tyre front left"], "car/wheel front left/tyre front left");
    EXPECT_EQ(pathOf["wheel rim rear right"], "car/wheel rear right/wheel rim rear right");
    EXPECT_EQ(pathOf["brake disc and caliper front right"],
              "car/wheel front right/brake disc and caliper front right");
    EXPECT_EQ(pathOf["axle front"], "car/axle front");
    EXPECT_EQ(pathOf["differential housing"], "car/differential housing");
    EXPECT_EQ(pathOf["engine block"], "car/engine/engine block");
    EXPECT_EQ(pathOf["gearbox housing"], "car/engine/gearbox housing");
    EXPECT_EQ(pathOf["pulley #3"], "car/engine/pulley #3");
    EXPECT_EQ(pathOf["radiator"], "car/radiator");
    EXPECT_EQ(pathOf["hose #1"], "car/hoses/hose #1");
    // The front-left tyre sits at +x, +y.
    for (const auto& o : s.objects)
        if (o.name == "tyre front left") {
            EXPECT_GT(o.world[3].x, 0.0f);
            EXPECT_GT(o.world[3].y, 0.0f);
        }
    // Wheel nuts and the fill's rail fasteners share the per-kind numbers.
    EXPECT_EQ(pathOf["nut M10 #1"], "car/wheel rear right/nut M10 #1");
    const std::string& lastBolt =
        pathOf["bolt M10 #" + std::to_string(namesOf(s, "bolt M10").size())];
    EXPECT_TRUE(lastBolt.starts_with("car/chassis/frame rail ")) << lastBolt;
}

TEST(Procedural, SmallNamesAndPaths) {
    const Scene s = make("small", 1);
    ASSERT_GE(s.objects.size(), 2u);
    EXPECT_EQ(s.objects[0].name, "base plate");
    EXPECT_EQ(s.objects[0].path, "gearbox module/base plate");
    const std::string cluster = s.geometries[s.objects[1].geometry].name;
    EXPECT_TRUE(cluster.starts_with("gear cluster ")) << cluster;
    EXPECT_EQ(s.objects[1].path, "gearbox module/" + cluster + " #1");
    std::map<std::string, std::string> pathOf;
    for (const auto& o : s.objects) pathOf[o.name] = o.path;
    EXPECT_EQ(pathOf["bolt M6 #3"], "gearbox module/angle bracket #1/bolt M6 #3");
    EXPECT_EQ(pathOf["bolt M6 #4"], "gearbox module/angle bracket #2/bolt M6 #4");
    EXPECT_EQ(pathOf["washer M10 #1"], "gearbox module/base plate/washer M10 #1");
}
