// test_inspector.cpp - the Inspect panel's report worked out on its worker (inspect_report.h,
// inspect_query.h), on Motor-c.brep's solids: the frame's update() asks and returns at once
// ("inspect: computing", the rows "... computing..."), a newer selection supersedes the one
// before (only its lines and rows come, with the values Open CASCADE gives for its solid), A's
// and B's distance lands as scene::measureDistance gives it, and an Inspector destroyed while
// its question is held ends cleanly.
#include <gtest/gtest.h>

#include <algorithm>

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

// The volume an "inspect solids N volume V area A mm" line says.
double saidVolume(const std::vector<std::string>& lines) {
    for (const std::string& line : lines)
        if (starts(line, "inspect solids 1 volume "))
            return std::stod(line.substr(std::string("inspect solids 1 volume ").size()));
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
    EXPECT_EQ(inspector.update(s, {}, partsOf(s, first), things),
              std::vector<std::string>{"inspect: computing"});
    EXPECT_TRUE(inspector.computing());
    const auto& rows = inspector.report().rows;
    ASSERT_EQ(rows.size(), 4u); // the unit's heading, then the box's three rows, each waiting
    EXPECT_EQ(rows[0].text, scene::unitHeading(s.unit));
    for (size_t i = 1; i < rows.size(); ++i)
        EXPECT_NE(rows[i].text.find("computing..."), std::string::npos) << rows[i].text;
    EXPECT_FALSE(inspector.due(partsOf(s, first), things)); // asked: nothing to do per frame
    EXPECT_TRUE(inspector.update(s, {}, partsOf(s, first), things).empty());

    EXPECT_EQ(inspector.update(s, {}, partsOf(s, second), things),
              std::vector<std::string>{"inspect: computing"});
    inspector.hold(false);
    inspector.wait();
    EXPECT_TRUE(inspector.due(partsOf(s, second), things)); // landed: a frame takes it in
    const std::vector<std::string> lines = inspector.update(s, {}, partsOf(s, second), things);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_TRUE(starts(lines[0], "inspect size ")) << lines[0];
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
    const auto asked = inspector.update(s, {}, none, things);
    EXPECT_EQ(asked,
              (std::vector<std::string>{"inspect things first|second", "inspect: computing"}));
    EXPECT_TRUE(inspector.report().computingDistance);
    inspector.wait();
    const auto lines = inspector.update(s, {}, none, things);
    ASSERT_EQ(lines.size(), 1u);
    ASSERT_TRUE(starts(lines[0], "inspect distance ")) << lines[0];
    const double want = scene::measureDistance(s, *things.a(), *things.b())->distance;
    EXPECT_NEAR(std::stod(lines[0].substr(17)), want, 1e-9 + 1e-6 * want);
    ASSERT_TRUE(inspector.report().distance);
    EXPECT_TRUE(inspector.report().distance->fromBrep);
}

TEST(Inspector, DestroyedWhileItsQuestionIsHeldEndsCleanly) {
    const scene::Scene& s = motor();
    app::Things things;
    {
        app::Inspector inspector;
        inspector.hold(true);
        inspector.update(s, {}, partsOf(s, 0), things);
        EXPECT_TRUE(inspector.computing());
    }
    // And an empty selection asks nothing: no "computing".
    app::Inspector inspector;
    EXPECT_TRUE(inspector.update(s, {}, scene::PartSet(s.uniquePartCount()), things).empty());
    EXPECT_FALSE(inspector.computing());
}

} // namespace
