// test_lod_policy.cpp - one level-of-detail policy for meshes and CAD files (scene/lod_policy.h):
// the levels each kind gets are what the chooser (lod_choice.h) picks among its candidates,
// with their triangles, bytes, sizes and objects counted here; a CAD geometry and the same
// geometry as a plain mesh, offered the same candidates, get the same levels; and the error
// measure (lod_error.h) finds distances known beforehand.
#include <gtest/gtest.h>

#include <cfloat>
#include <filesystem>

#include "scene/cad/cad_levels.h"
#include "scene/cad/cad_loader.h"
#include "scene/lod_choice.h"
#include "scene/lod_policy.h"
#include "scene/procedural/procedural.h"
#include "test_data.h"

namespace fs = std::filesystem;
using namespace scene;

namespace {

const fs::path kData = "/usr/share/opencascade/data";

// A level as the tests compare them: its triangles and its error.
using Level = std::pair<uint32_t, float>;

float boxDiagonal(const Scene& s, const Geometry& g) {
    glm::vec3 low(FLT_MAX), high(-FLT_MAX);
    for (uint32_t v = 0; v < g.vertexCount; ++v) {
        low = glm::min(low, s.vertices[g.firstVertex + v].position);
        high = glm::max(high, s.vertices[g.firstVertex + v].position);
    }
    return glm::length(high - low);
}

// What chooseLevels picks among `candidates` for `scene` (whose geometries have no levels
// yet), each geometry's levels by growing error, with everything the chooser weighs counted
// here rather than taken from the policy.
std::vector<std::vector<Level>> chooserPicks(const Scene& scene,
                                             std::vector<GeometryCandidates> candidates) {
    const LodOptions options;
    std::vector<uint32_t> instances(scene.geometries.size(), 0);
    for (const Object& o : scene.objects) ++instances[o.geometry];
    std::vector<CandidateSet> sets;
    std::vector<std::vector<LevelMesh>> useful;
    double fullBytes = 0.0;
    for (GeometryCandidates& c : candidates) {
        const Geometry& g = scene.geometries[c.geometry];
        fullBytes += double(g.vertexCount * sizeof(Vertex) + 12 * g.triangleCount +
                            g.partCount * sizeof(Part));
        CandidateSet& set = sets.emplace_back();
        set.triangles = g.triangleCount;
        set.size = boxDiagonal(scene, g);
        set.instances = std::max(instances[c.geometry], 1u);
        useful.push_back(usefulCandidates(scene, c));
        for (const LevelMesh& level : useful.back()) {
            size_t triangles = 0;
            for (const auto& part : level.parts) triangles += part.size() / 3;
            EXPECT_EQ(level.parts.size(), g.partCount);
            EXPECT_EQ(level.triangles, triangles);
            const uint64_t bytes = level.vertices.size() * sizeof(Vertex) + 12 * triangles +
                                   g.partCount * sizeof(Part);
            EXPECT_EQ(level.bytes, bytes);
            set.candidates.push_back({triangles, bytes, level.error});
        }
    }
    const auto chosen = chooseLevels(sets, options.levels - 1, options.keepAtMost,
                                     double(options.memory) * fullBytes);
    std::vector<std::vector<Level>> out(candidates.size());
    for (size_t i = 0; i < candidates.size(); ++i)
        for (uint32_t c : chosen[i])
            out[i].push_back({uint32_t(useful[i][c].triangles), useful[i][c].error});
    return out;
}

std::vector<Level> levelsOf(const Scene& s, uint32_t geometry) {
    std::vector<Level> out;
    for (uint32_t l : s.geometries[geometry].levels)
        out.push_back({s.geometries[l].triangleCount, s.geometries[l].lodError});
    return out;
}

// Expects `built` (the scene with levels) to hold for each geometry of `candidates` exactly
// the levels chooserPicks finds for `bare` (the same scene without).
void expectTheChoice(const Scene& bare, const Scene& built,
                     const std::vector<GeometryCandidates>& candidates, const std::string& what) {
    const auto picks = chooserPicks(bare, candidates);
    size_t levels = 0;
    for (size_t i = 0; i < candidates.size(); ++i) {
        EXPECT_EQ(levelsOf(built, candidates[i].geometry), picks[i])
            << what << ", geometry " << candidates[i].geometry;
        levels += picks[i].size();
    }
    EXPECT_GT(levels, candidates.size() / 2) << what << ": too few levels to say anything";
}

// A geometry of one part appended to `s`: the triangles `points` holds three by three.
uint32_t addPart(Scene& s, const std::vector<glm::vec3>& points) {
    Geometry& g = s.geometries.emplace_back();
    g.firstVertex = uint32_t(s.vertices.size());
    g.firstIndex = uint32_t(s.indices.size());
    g.firstPart = uint32_t(s.parts.size());
    for (const glm::vec3& p : points) {
        s.indices.push_back(g.vertexCount++);
        s.vertices.push_back({p, glm::vec3(0.0f, 0.0f, 1.0f)});
    }
    g.triangleCount = uint32_t(points.size() / 3);
    g.partCount = 1;
    s.parts.push_back({0, g.triangleCount});
    return uint32_t(s.geometries.size() - 1);
}

LevelMesh meshOf(const std::vector<glm::vec3>& points) {
    LevelMesh level;
    level.parts.emplace_back();
    for (const glm::vec3& p : points) {
        level.parts[0].push_back(uint32_t(level.vertices.size()));
        level.vertices.push_back({p, glm::vec3(0.0f, 0.0f, 1.0f)});
    }
    return level;
}

} // namespace

TEST(LodPolicy, CadLevelsAreTheChoiceAmongItsTessellations) {
    for (const char* name : {"occ/Motor-c.brep", "iges/bearing.iges"}) {
        const fs::path path = kData / name;
        REQUIRE_DATA(path);
        const CadLoadResult bare = loadCad(path.string(), {}, {}, 1);
        const CadLoadResult built = loadCad(path.string(), {}, {}, maxLevels);
        ASSERT_TRUE(bare.scene.brep);
        // No face of these files is left unmeshed, so the loader skipped none.
        const auto candidates = cadCandidates(bare.scene, decodedShapes(*bare.scene.brep),
                                              bare.deflection, CadOptions{}.angularDeflection, {});
        expectTheChoice(bare.scene, built.scene, candidates, name);
    }
}

TEST(LodPolicy, MeshLevelsAreTheChoiceAmongItsSimplifications) {
    const Scene bare = makeProcedural({"small", 3});
    Scene built = bare;
    buildLevels(built);
    expectTheChoice(bare, built, meshCandidates(bare, {}), "procedural small");
}

TEST(LodPolicy, ACadGeometryAndTheSameAsAMeshGetTheSameLevels) {
    const fs::path path = kData / "occ/Motor-c.brep";
    REQUIRE_DATA(path);
    CadLoadResult loaded = loadCad(path.string(), {}, {}, 1);
    Scene& s = loaded.scene;
    const std::vector<GeometryCandidates> candidates = cadCandidates(
        s, decodedShapes(*s.brep), loaded.deflection, CadOptions{}.angularDeflection, {});
    // The CAD geometry of the most triangles, and a copy of it as a mesh would come: no
    // faces, no surfaces, no shape; its own object.
    uint32_t cad = 0;
    for (uint32_t g = 0; g < s.geometries.size(); ++g)
        if (s.geometries[g].triangleCount > s.geometries[cad].triangleCount) cad = g;
    Geometry mesh = s.geometries[cad];
    mesh.name += " as a mesh";
    mesh.partFaces.clear();
    mesh.partSurfaces.clear();
    s.geometries.push_back(mesh);
    const uint32_t copy = uint32_t(s.geometries.size() - 1);
    addObject(s, copy, 0, glm::dmat4(1.0), "copy", "copy");
    GeometryCandidates cadOnes = candidates[cad], meshOnes = candidates[cad];
    ASSERT_EQ(cadOnes.geometry, cad);
    meshOnes.geometry = copy;
    std::vector<GeometryCandidates> both = {cadOnes, meshOnes};
    addChosenLevels(s, both, {});
    EXPECT_FALSE(levelsOf(s, cad).empty());
    EXPECT_EQ(levelsOf(s, cad), levelsOf(s, copy));
}

TEST(LodPolicy, TheErrorIsTheFarthestEitherWayPartByPart) {
    // A unit square at z = 0, and a pyramid over it whose apex is 0.25 above its centre.
    const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(0, 1, 0), apex(0.5f, 0.5f, 0.25f);
    const std::vector<glm::vec3> flat = {a, b, c, a, c, d};
    const std::vector<glm::vec3> pyramid = {a, b, apex, b, c, apex, c, d, apex, d, a, apex};
    Scene s;
    const uint32_t roof = addPart(s, pyramid), floor = addPart(s, flat);
    // The apex lies 0.25 from the square; the square's corners lie on the pyramid and its
    // centre, edge midpoints and triangle centres nearer than that.
    EXPECT_FLOAT_EQ(levelError(s, s.geometries[roof], meshOf(flat)), 0.25f);
    EXPECT_FLOAT_EQ(levelError(s, s.geometries[floor], meshOf(pyramid)), 0.25f);
    // The same square: nothing but the rounding of a float's last place on a unit square.
    EXPECT_NEAR(levelError(s, s.geometries[floor], meshOf(flat)), 0.0f, 1e-6f);
    // A part drawn nowhere (one triangle of zero area) counts its diagonal.
    EXPECT_FLOAT_EQ(levelError(s, s.geometries[roof], meshOf({a, a, a})),
                    glm::length(glm::vec3(1.0f, 1.0f, 0.25f)));
    // A square moved sideways along its own plane: its corners are 0.5 from the other's.
    const glm::vec3 slide(0.5f, 0.0f, 0.0f);
    EXPECT_FLOAT_EQ(
        levelError(s, s.geometries[floor],
                   meshOf({a + slide, b + slide, c + slide, a + slide, c + slide, d + slide})),
        0.5f);
    // Past the limit it stops, beyond the limit.
    EXPECT_GT(levelError(s, s.geometries[roof], meshOf(flat), 0.1f), 0.1f);
}
