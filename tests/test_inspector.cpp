// test_inspector.cpp - the Inspect panel's report worked out on its worker (inspect_report.h,
// inspect_query.h), on Motor-c.brep's solids: the frame's update() asks and returns at once
// (an inspect_computing record, the rows "... computing..."), a newer selection supersedes the one
// before (only its records and rows come, with the values Open CASCADE gives for its solid), A's
// and B's distance lands as scene::measureDistance gives it, and an Inspector destroyed while
// its question is held ends cleanly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "app/viewer/state/inspect_report.h"
#include "app/viewer/state/things.h"
#include "scene/cad/cad_loader.h"
#include "scene/units.h"

namespace {

const scene::Scene& motor() {
    static const scene::Scene scene =
        scene::loadCadInProcess("/usr/share/opencascade/data/occ/Motor-c.brep").scene;
    return scene;
}

scene::PartSet partsOf(const scene::Scene& s, uint32_t object) {
    scene::PartSet parts(s.uniquePartCount());
    const scene::Object& o = s.objects[object];
    for (uint32_t i = 0; i < s.geometries[o.geometry].partCount; ++i)
        parts.insert(o.uniquePartOffset + i);
    return parts;
}

bool starts(const std::string& line, const std::string& with) {
    return line.rfind(with, 0) == 0;
}

// The event records one update() says, a line each.
std::vector<std::string> update(app::Inspector& inspector, const scene::Scene& s,
                                const scene::PartSet& selected, const app::Things& things) {
    std::FILE* file = std::tmpfile();
    inspector.update(s, {}, selected, things, app::Events(true, file));
    std::rewind(file);
    std::vector<std::string> lines;
    char line[4096];
    while (std::fgets(line, sizeof line, file)) lines.emplace_back(line, std::strlen(line) - 1);
    std::fclose(file);
    return lines;
}

const std::string computing = R"({"event":"inspect_computing"})";
const std::string solidsStart = R"({"event":"inspect_solids","solids":1,"volume":)";
const std::string distanceStart = R"({"event":"inspect_distance","distance":)";

// The volume an inspect_solids record of one solid says.
double saidVolume(const std::vector<std::string>& lines) {
    for (const std::string& line : lines)
        if (starts(line, solidsStart)) return std::stod(line.substr(solidsStart.size()));
    return -1.0;
}

// Two solids of different volume (the motor's are).
std::pair<uint32_t, uint32_t> twoSolids(const scene::Scene& s) {
    const double v0 = scene::objectProperties(s, 0)->volume;
    for (uint32_t o = 1; o < s.objects.size(); ++o)
        if (std::abs(scene::objectProperties(s, o)->volume - v0) > 1e-3 * v0) return {0, o};
    return {0, 0};
}

TEST(Inspector, NewerSelectionSupersedesTheOneBeingWorkedOut) {
    const scene::Scene& s = motor();
    ASSERT_GE(s.objects.size(), 2u);
    const auto [first, second] = twoSolids(s);
    ASSERT_NE(first, second);
    app::Inspector inspector;
    app::Things things;
    inspector.hold(true); // the worker takes no question until released
    EXPECT_EQ(update(inspector, s, partsOf(s, first), things), std::vector<std::string>{computing});
    EXPECT_TRUE(inspector.computing());
    const auto& rows = inspector.report().rows;
    ASSERT_EQ(rows.size(), 4u); // the unit's heading, then the box's three rows, each waiting
    EXPECT_EQ(rows[0].text, scene::unitHeading(s.unit));
    for (size_t i = 1; i < rows.size(); ++i)
        EXPECT_NE(rows[i].text.find("computing..."), std::string::npos) << rows[i].text;
    EXPECT_FALSE(inspector.due(partsOf(s, first), things)); // asked: nothing to do per frame
    EXPECT_TRUE(update(inspector, s, partsOf(s, first), things).empty());

    EXPECT_EQ(update(inspector, s, partsOf(s, second), things),
              std::vector<std::string>{computing});
    inspector.hold(false);
    inspector.wait();
    EXPECT_TRUE(inspector.due(partsOf(s, second), things)); // landed: a frame takes it in
    const std::vector<std::string> lines = update(inspector, s, partsOf(s, second), things);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_TRUE(starts(lines[0], R"({"event":"inspect_size","size":[)")) << lines[0];
    const double want = scene::objectProperties(s, second)->volume;
    EXPECT_NEAR(saidVolume(lines), want, 1e-6 * want);
    EXPECT_FALSE(inspector.computing());
    ASSERT_EQ(inspector.report().solids.size(), 1u);
    EXPECT_EQ(inspector.report().solids[0].object, second);
    for (const app::InspectRow& row : inspector.report().rows)
        EXPECT_EQ(row.text.find("computing"), std::string::npos) << row.text;
    EXPECT_FALSE(inspector.due(partsOf(s, second), things));
}

TEST(Inspector, DistanceOfAAndBLandsAsMeasureDistanceGivesIt) {
    const scene::Scene& s = motor();
    const auto [first, second] = twoSolids(s);
    app::Inspector inspector;
    app::Things things;
    things.click(scene::Thing{partsOf(s, first).ids(), {}, "first"});
    things.add(scene::Thing{partsOf(s, second).ids(), {}, "second"});
    const scene::PartSet none(s.uniquePartCount());
    const auto asked = update(inspector, s, none, things);
    EXPECT_EQ(asked, (std::vector<std::string>{
                         R"({"event":"inspect_things","a":"first","b":"second"})", computing}));
    EXPECT_TRUE(inspector.report().computingDistance);
    inspector.wait();
    const auto lines = update(inspector, s, none, things);
    ASSERT_EQ(lines.size(), 1u);
    ASSERT_TRUE(starts(lines[0], distanceStart)) << lines[0];
    const double want = scene::measureDistance(s, *things.a(), *things.b())->distance;
    EXPECT_NEAR(std::stod(lines[0].substr(distanceStart.size())), want, 1e-9 + 1e-6 * want);
    ASSERT_TRUE(inspector.report().distance);
    EXPECT_TRUE(inspector.report().distance->fromBrep);
}

TEST(Inspector, DestroyedWhileItsQuestionIsHeldEndsCleanly) {
    const scene::Scene& s = motor();
    app::Things things;
    {
        app::Inspector inspector;
        inspector.hold(true);
        update(inspector, s, partsOf(s, 0), things);
        EXPECT_TRUE(inspector.computing());
    }
    // And an empty selection asks nothing: no "computing".
    app::Inspector inspector;
    EXPECT_TRUE(update(inspector, s, scene::PartSet(s.uniquePartCount()), things).empty());
    EXPECT_FALSE(inspector.computing());
}

} // namespace
