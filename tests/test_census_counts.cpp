// test_census_counts.cpp - the census's CPU side: its views spread evenly and hold the scene,
// the summary's counts (never seen apart from hidden and empty parts), the exterior cut to
// the kept parts, the CSV's quoting and --census on the command line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "app/census.h"
#include "app/cli.h"
#include "census_scene.h"
#include "empty_parts_scene.h"
#include "scene/census.h"
#include "scene/exterior.h"

namespace {

// Each hemisphere of any axis holds half the directions (within one), the mean lies near
// the centre, and no two come closer than half the spacing of an even spread.
TEST(CensusViews, DirectionsSpreadEvenlyOverTheSphere) {
    for (uint32_t count : {12u, 42u, 162u, 642u}) {
        const std::vector<glm::dvec3> d = scene::censusDirections(count);
        ASSERT_EQ(d.size(), count);
        glm::dvec3 mean(0.0);
        for (const glm::dvec3& v : d) {
            EXPECT_NEAR(glm::length(v), 1.0, 1e-12);
            mean += v / double(count);
        }
        EXPECT_LT(glm::length(mean), 2.0 / count) << count;
        for (const glm::dvec3 axis :
             {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)}) {
            uint32_t above = 0;
            for (const glm::dvec3& v : d) above += glm::dot(v, axis) > 0.0;
            EXPECT_NEAR(double(above), count / 2.0, 0.03 * count + 1.0) << count;
        }
        const double spacing = std::sqrt(4.0 * std::numbers::pi / count);
        double closest = 10.0;
        for (size_t i = 0; i < d.size(); ++i)
            for (size_t j = i + 1; j < d.size(); ++j)
                closest = std::min(closest, std::acos(std::min(1.0, glm::dot(d[i], d[j]))));
        EXPECT_GT(closest, 0.5 * spacing) << count;
    }
}

// Every corner of the scene's box lies inside every view's square and depth range, and the
// bounding sphere just fits: the same scale in every view.
TEST(CensusViews, EveryViewHoldsTheWholeSceneAtOneScale) {
    const scene::Bounds bounds{{-16, -4, -4}, {17, 18, 4}};
    for (const glm::dvec3& d : scene::censusDirections(42)) {
        const scene::Camera camera = scene::censusCamera(bounds, d);
        EXPECT_TRUE(camera.ortho);
        EXPECT_NEAR(camera.orthoHeight(), 2.0 * bounds.radius() * 1.02, 1e-9);
        const glm::dmat4 viewProj = camera.viewProjection(1.0);
        for (int c = 0; c < 8; ++c) {
            const glm::dvec3 corner(c & 1 ? bounds.max.x : bounds.min.x,
                                    c & 2 ? bounds.max.y : bounds.min.y,
                                    c & 4 ? bounds.max.z : bounds.min.z);
            const glm::dvec4 clip = viewProj * glm::dvec4(corner, 1.0);
            EXPECT_LE(std::abs(clip.x / clip.w), 1.0);
            EXPECT_LE(std::abs(clip.y / clip.w), 1.0);
            EXPECT_GT(clip.z / clip.w, 0.0);
            EXPECT_LT(clip.z / clip.w, 1.0);
        }
    }
}

// A census by hand over a scene with empty parts: hidden and empty parts are counted apart
// from the never-seen ones, and an object counts as never seen only with no part seen.
TEST(CensusSummary, CountsNeverSeenApartFromHiddenAndEmpty) {
    const testing_support::WithEmptyParts made =
        testing_support::withEmptyParts(testing_support::fourObjectScene());
    ASSERT_EQ(made.emptyObject, 1u);
    const scene::Scene& s = made.scene;
    const uint32_t parts = s.uniquePartCount();
    scene::Census census;
    census.views = 2;
    census.width = census.height = 10;
    census.parts.resize(parts);
    scene::PartSet hidden(parts);
    // Object 0: every drawable part seen but one; object 1 (all empty) nothing; object 2:
    // nothing seen, one part hidden; the rest seen.
    const auto partsOf = [&](uint32_t o) {
        const scene::Object& object = s.objects[o];
        std::vector<uint32_t> ids;
        for (uint32_t p = 0; p < s.geometries[object.geometry].partCount; ++p)
            ids.push_back(object.uniquePartOffset + p);
        return ids;
    };
    uint32_t expectNever = 0, expectEmpty = 0;
    uint64_t expectTriangles = 0, objectTriangles = 0;
    for (uint32_t o = 0; o < s.objects.size(); ++o) {
        bool first = true, firstDrawable = true;
        for (uint32_t id : partsOf(o)) {
            const auto ref = *s.locate(id);
            const uint32_t triangles = s.part(s.objects[o], ref.localPart).triangleCount;
            if (triangles == 0) {
                ++expectEmpty;
                continue;
            }
            const bool skip = (o == 0 && firstDrawable) || o == 2;
            if (o == 2 && first) {
                hidden.insert(id);
                first = false;
            } else if (skip) {
                ++expectNever;
                expectTriangles += triangles;
                if (o == 2) objectTriangles += triangles;
            } else {
                census.parts[id] = {uint64_t(id + 1), 1, id + 1};
            }
            firstDrawable = false;
        }
    }
    const scene::CensusSummary sum = scene::summarize(s, census, hidden);
    EXPECT_EQ(sum.parts, parts);
    EXPECT_EQ(sum.partsEmpty, expectEmpty);
    EXPECT_EQ(sum.partsHidden, 1u);
    EXPECT_EQ(sum.partsNeverSeen, expectNever);
    EXPECT_EQ(sum.partsSeen, parts - expectEmpty - 1 - expectNever);
    EXPECT_EQ(sum.trianglesNeverSeen, expectTriangles);
    EXPECT_EQ(sum.objectsNeverSeen, 1u); // object 2; object 1 has nothing to see
    EXPECT_EQ(sum.objectTrianglesNeverSeen, objectTriangles);
    EXPECT_EQ(sum.triangles, s.drawnTriangleCount());
    EXPECT_EQ(scene::neverSeenParts(s, census, hidden).size(), expectNever);
    EXPECT_EQ(scene::seenParts(census).size(), sum.partsSeen);
}

// The cut scene keeps exactly the kept parts' triangles, in order, and objects of one
// geometry keeping the same parts share the geometry made for them.
TEST(CensusExterior, KeptPartsHoldTheirTrianglesAndShareGeometries) {
    const testing_support::CensusScene made = testing_support::makeCensusScene();
    scene::Scene s = made.scene;
    scene::addObject(s, s.objects[0].geometry, 0, glm::dmat4(1.0), "shell again", "shell again");
    scene::PartSet keep(s.uniquePartCount());
    for (uint32_t id = 0; id < s.uniquePartCount(); ++id)
        if (!made.neverSeen.contains(id) && s.locate(id)->localPart % 2 == 0) keep.insert(id);
    const scene::Scene cut = scene::keptParts(s, keep);
    scene::validate(cut);
    EXPECT_EQ(cut.uniquePartCount(), keep.size());
    uint32_t next = 0;
    for (uint32_t id : keep.ids()) {
        const auto from = *s.locate(id);
        const auto to = *cut.locate(next++);
        const scene::Part& a = s.part(s.objects[from.object], from.localPart);
        const scene::Part& b = cut.part(cut.objects[to.object], to.localPart);
        ASSERT_EQ(a.triangleCount, b.triangleCount);
        const uint32_t ia = s.geometries[s.objects[from.object].geometry].firstIndex;
        const uint32_t ib = cut.geometries[cut.objects[to.object].geometry].firstIndex;
        for (uint32_t k = 0; k < 3 * a.triangleCount; ++k)
            EXPECT_EQ(s.indices[ia + 3 * a.firstTriangle + k],
                      cut.indices[ib + 3 * b.firstTriangle + k]);
        EXPECT_EQ(s.objects[from.object].name, cut.objects[to.object].name);
    }
    // The shell and its copy keep the same parts: one geometry between them.
    EXPECT_EQ(cut.objects.front().geometry, cut.objects.back().geometry);
    EXPECT_EQ(cut.objects.back().name, "shell again");
}

TEST(CensusCsv, QuotesNamesWithCommasAndQuotes) {
    scene::Scene s = testing_support::fourObjectScene();
    s.objects[0].name = "bolt, \"M10\"";
    s.objects[0].path = "rig/bolt, \"M10\"";
    scene::Census census;
    census.views = 1;
    census.width = census.height = 4;
    census.parts.resize(s.uniquePartCount());
    census.parts[0] = {4, 1, 4};
    const auto path = std::filesystem::temp_directory_path() / "idview-census-quotes.csv";
    app::writeCensusCsv(path.string(), s, census);
    std::ifstream in(path);
    std::string header, first;
    std::getline(in, header);
    std::getline(in, first);
    EXPECT_EQ(header, "part,object,name,path,pixels,views,largest_share");
    EXPECT_EQ(first, "0,0,\"bolt, \"\"M10\"\"\",\"rig/bolt, \"\"M10\"\"\",4,1,0.25");
    std::filesystem::remove(path);
}

TEST(CensusCli, TakesViewsAndSizeAndImpliesHeadless) {
    const app::Options o = app::parseArgs({"--census", "162x1024"});
    EXPECT_EQ(o.census, (scene::CensusSpec{162, 1024}));
    EXPECT_TRUE(o.headless);
    const app::Options e = app::parseArgs({"--census", "12x64", "--census-export", "a.stp"});
    EXPECT_EQ(e.censusExport, "a.stp");
    for (const std::vector<std::string>& bad : {std::vector<std::string>{"--census", "162"},
                                                {"--census", "0x64"},
                                                {"--census", "12x8"},
                                                {"--census", "12x9000"},
                                                {"--census", "x64"},
                                                {"--census-csv", "a.csv"},
                                                {"--census", "4x32", "--census-export", "a.obj"}})
        EXPECT_THROW(app::parseArgs(bad), app::UsageError) << bad.back();
}

} // namespace
