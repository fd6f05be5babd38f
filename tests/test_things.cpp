// test_things.cpp - the Inspect panel's things A and B (app/viewer/state/things.h): a click makes A,
// Ctrl+click B, a third Ctrl+click replaces B, a plain click starts again, Esc and a new
// scene forget them; their names from the assembly; and the Inspect panel's rows
// (inspect_report.h): the sum of several solids (volumes and areas added, the centre
// weighted by volume), every row naming its component, every value with its unit.
#include <gtest/gtest.h>

#include "app/viewer/state/inspect_report.h"
#include "app/viewer/state/things.h"
#include "scene/bounds.h"

namespace {

scene::Thing thing(std::vector<uint32_t> parts, std::string label) {
    scene::Thing t;
    t.parts = std::move(parts);
    t.label = std::move(label);
    return t;
}

TEST(Things, ClickMakesACtrlClickMakesBAndReplacesIt) {
    app::Things things;
    EXPECT_EQ(app::thingsLine(things), "none|none");
    const uint64_t start = things.version();
    things.click(thing({3}, "plate · face 2"));
    ASSERT_TRUE(things.a());
    EXPECT_FALSE(things.b());
    things.add(thing({7, 8}, "bolt"));
    EXPECT_EQ(app::thingsLine(things), "plate · face 2|bolt");
    things.add(thing({9}, "nut · face 1")); // a third replaces B, A stays
    EXPECT_EQ(app::thingsLine(things), "plate · face 2|nut · face 1");
    EXPECT_EQ(things.parts(16).ids(), (std::vector<uint32_t>{3, 9}));
    EXPECT_EQ(things.version(), start + 3);
    things.click(thing({5}, "base")); // a plain click starts again
    EXPECT_EQ(app::thingsLine(things), "base|none");
    things.click(std::nullopt); // empty space: neither
    EXPECT_EQ(app::thingsLine(things), "none|none");
}

TEST(Things, CtrlClickFirstIsAForgetClearsBoth) {
    app::Things things;
    things.add(thing({1}, "first")); // nothing to compare with yet: it is A
    EXPECT_EQ(app::thingsLine(things), "first|none");
    things.add(thing({2}, "second"));
    EXPECT_EQ(app::thingsLine(things), "first|second");
    const uint64_t before = things.version();
    EXPECT_TRUE(things.forget());
    EXPECT_EQ(app::thingsLine(things), "none|none");
    EXPECT_GT(things.version(), before); // what was worked out from them goes too
    EXPECT_FALSE(things.forget());
    EXPECT_EQ(things.parts(4).size(), 0u);
}

TEST(Things, AnEdgeThingSelectsItsFace) {
    app::Things things;
    scene::Thing edge;
    edge.edge = scene::EdgeRef{6, 4};
    edge.label = "plate · edge 4";
    things.click(edge);
    EXPECT_EQ(things.parts(8).ids(), (std::vector<uint32_t>{6}));
}

// Two objects of two parts each, under "box/left" and "box/right": a face is named by its
// object's path and its part, both objects by their node, one object by its path.
TEST(Things, NamedByTheAssembly) {
    scene::Scene s;
    s.geometries.push_back({});
    s.geometries[0].partCount = 2;
    s.parts.resize(2);
    scene::addObject(s, 0, 0, glm::dmat4(1.0), "left", "box/left");
    scene::addObject(s, 0, 0, glm::dmat4(1.0), "right", "box/right");
    scene::AssemblyNode root = scene::assemblyTree(s, "scene");
    const auto rows = scene::treeRows(root);
    scene::PartSet face(4), object(4), both(4);
    face.insert(3);
    object.insert(2);
    object.insert(3);
    for (uint32_t p = 0; p < 4; ++p) both.insert(p);
    EXPECT_EQ(app::makeThing(s, rows, face, 3).label, "box/right \u00b7 part 1");
    EXPECT_EQ(app::makeThing(s, rows, face, 3).parts, (std::vector<uint32_t>{3}));
    EXPECT_EQ(app::makeThing(s, rows, object, 2).label, "box/right");
    EXPECT_EQ(app::makeThing(s, rows, both, 0).label, "box");
    // An object whose node holds another: its path, not its node's (which holds both).
    scene::Scene nested = s;
    nested.objects[1].path = "box/left/right";
    const auto nestedRows = scene::treeRows(scene::assemblyTree(nested, "scene"));
    scene::PartSet left(4);
    left.insert(0);
    left.insert(1);
    EXPECT_EQ(app::makeThing(nested, nestedRows, left, 1).label, "box/left");
    EXPECT_EQ(app::makeThing(nested, nestedRows, both, 1).label, "box/left");
    const scene::Thing edge = app::makeThing(s, rows, face, 3, scene::EdgeRef{3, 5});
    EXPECT_EQ(edge.label, "box/right \u00b7 edge 5");
    EXPECT_TRUE(edge.parts.empty());
}

scene::SolidProperties solid(double volume, double area, glm::dvec3 center, bool closed = true) {
    scene::SolidProperties p;
    p.volume = volume;
    p.area = area;
    p.center = center;
    p.closed = closed;
    p.bbox = {center - 1.0, center + 1.0};
    return p;
}

// The rows of a selection's sum: a 1000 mm³ cube at the origin and a 3000 mm³ one at
// x = 40: volumes and areas added, the centre of mass at x = 30 (weighted by volume).
TEST(InspectSum, RowsSumVolumesAndAreasCentreWeighsByVolume) {
    scene::Scene s;
    s.unit = {"mm", "test"};
    app::InspectReport report;
    report.sum = scene::sumProperties({solid(1000, 600, {0, 0, 0}), solid(3000, 1400, {40, 0, 8})});
    const auto rows = app::inspectRows(s, report);
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_EQ(rows[0].component, ""); // the unit's heading
    EXPECT_EQ(rows[0].text, "lengths in mm");
    for (size_t i = 1; i < rows.size(); ++i) EXPECT_EQ(rows[i].component, "sum of 2 solids");
    EXPECT_EQ(rows[1].text, "volume 4000 mm\u00b3");
    EXPECT_EQ(rows[2].text, "surface area 2000 mm\u00b2");
    EXPECT_EQ(rows[3].text, "centre of mass (30, 0, 6)");
}

// Open shells have no volume to weigh by: the centre is the surfaces', and says so.
TEST(InspectSum, OpenShellsWeighByArea) {
    scene::Scene s;
    s.unit = {"mm", "test"};
    app::InspectReport report;
    report.sum =
        scene::sumProperties({solid(0, 100, {0, 0, 0}, false), solid(0, 300, {4, 0, 0}, false)});
    const auto rows = app::inspectRows(s, report);
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_EQ(rows[1].text, "volume 0 mm\u00b3 (some are open shells)");
    EXPECT_EQ(rows[3].text, "centre of the surfaces (3, 0, 0)");
}

// The panel's rows: the unit once, as their heading; then each names its component, lengths
// and points bare, areas and volumes with their unit.
TEST(InspectRows, EveryRowNamesItsComponentAndUnit) {
    scene::Scene s;
    s.unit = {"mm", "test"};
    s.geometries.push_back({});
    s.geometries[0].partCount = 1;
    s.parts.resize(1);
    scene::addObject(s, 0, 0, glm::dmat4(1.0), "nut", "box/nut");
    app::InspectReport report;
    report.selectionName = "box/nut";
    report.bounds = scene::Bounds{{0, 0, 0}, {2, 3, 4}};
    report.solids.push_back(solid(24, 52, {1, 1.5, 2}));
    report.a = thing({0}, "box/nut \u00b7 face 1");
    report.b = thing({0}, "box/nut \u00b7 face 3");
    scene::DistanceReport d;
    d.distance = 2.5;
    d.p1 = {0, 0, 2.5};
    d.centreDistance = 7.0;
    report.distance = d;
    const auto rows = app::inspectRows(s, report);
    auto has = [&](const std::string& component, const std::string& text) {
        for (const auto& row : rows)
            if (row.component == component && row.text == text) return true;
        return false;
    };
    ASSERT_FALSE(rows.empty());
    EXPECT_TRUE(rows[0].component.empty());
    EXPECT_EQ(rows[0].text, "lengths in mm");
    EXPECT_TRUE(has("box/nut", "size dX dY dZ (2, 3, 4) (triangles)"));
    EXPECT_TRUE(has("box/nut", "volume 24 mm\u00b3"));
    EXPECT_TRUE(has("box/nut", "surface area 52 mm\u00b2"));
    EXPECT_TRUE(has("box/nut", "centre of mass (1, 1.5, 2)"));
    const std::string both = "A (box/nut \u00b7 face 1) to B (box/nut \u00b7 face 3)";
    EXPECT_TRUE(has(both, "minimum distance 2.5 (triangles)"));
    EXPECT_TRUE(has(both, "closest point on B (0, 0, 2.5)"));
    EXPECT_TRUE(has(both, "centre to centre 7"));
    for (size_t i = 1; i < rows.size(); ++i) {
        EXPECT_FALSE(rows[i].component.empty()) << rows[i].text;
        // One unit per line at most: the heading says the length's.
        EXPECT_EQ(rows[i].text.find(" mm "), std::string::npos) << rows[i].text;
    }
}

} // namespace
