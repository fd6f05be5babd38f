// inspect_report.cpp - the Inspect panel's report and rows, worked out on change
// (inspect_report.h).
#include "app/viewer/inspect_report.h"

#include <cstdio>

#include "scene/bounds.h"

namespace app {
namespace {

std::string number(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

std::string objectPath(const scene::Scene& scene, uint32_t object) {
    const scene::Object& o = scene.objects[object];
    return !o.path.empty() ? o.path : !o.name.empty() ? o.name : "object " + std::to_string(object);
}

// Every object with a part in `selected`, in scene order.
std::vector<uint32_t> touchedObjects(const scene::Scene& scene, const scene::PartSet& selected,
                                     bool& allWhole) {
    std::vector<uint32_t> objects;
    allWhole = true;
    for (uint32_t i = 0; i < scene.objects.size(); ++i) {
        const scene::Object& o = scene.objects[i];
        const uint32_t count = scene.geometries[o.geometry].partCount;
        const uint32_t in = selected.countIn(o.uniquePartOffset, count);
        if (in == 0) continue;
        objects.push_back(i);
        allWhole = allWhole && in == count;
    }
    return objects;
}

// The event lines' numbers: enough digits to compare with the headless JSON.
std::string precise(double value) {
    return number("%.9g", value);
}
std::string unitWord(const scene::LengthUnit& unit) {
    return unit.symbol.empty() ? "none" : unit.symbol;
}

// Named as the clicks named it (A, or A and B), else by its tree node, else by its count.
std::string selectionName(const std::vector<scene::TreeRow>& tree, const scene::PartSet& selected,
                          const Things& things) {
    if (things.a() && things.parts(selected.partCount()) == selected)
        return things.b() ? "A and B" : things.a()->label;
    if (const auto row = scene::rowOfParts(tree, selected); row && !tree[*row].path.empty())
        return tree[*row].path;
    const uint32_t n = selected.size();
    return "selection of " + std::to_string(n) + (n == 1 ? " part" : " parts");
}

void addDistanceRows(const scene::Scene& scene, const InspectReport& report,
                     std::vector<InspectRow>& rows) {
    const scene::DistanceReport& d = *report.distance;
    const scene::Precision& p = scene.precision;
    const std::string both = "A (" + report.a->label + ") to B (" + report.b->label + ")";
    rows.push_back({both, "minimum distance " + scene::lengthText(d.distance, p) +
                              (d.fromBrep ? " (B-rep)" : " (triangles)")});
    rows.push_back({both, "closest point on A " + scene::pointText(d.p0, p)});
    rows.push_back({both, "closest point on B " + scene::pointText(d.p1, p)});
    if (d.centreDistance)
        rows.push_back({both, "centre to centre " + scene::lengthText(*d.centreDistance, p)});
    if (d.axisAngleDegrees)
        rows.push_back({both, "axes at " + scene::angleText(*d.axisAngleDegrees) + " degrees"});
    if (d.axisDistance)
        rows.push_back({both, "axis to axis " + scene::lengthText(*d.axisDistance, p)});
    if (d.pointToPlane)
        rows.push_back({both, "point to plane " + scene::lengthText(*d.pointToPlane, p)});
}

} // namespace

// Lengths and points bare under the unit's heading (the first row, no component); areas and
// volumes with their unit, which the heading does not name.
std::vector<InspectRow> inspectRows(const scene::Scene& scene, const InspectReport& report) {
    std::vector<InspectRow> rows;
    const scene::LengthUnit& unit = scene.unit;
    const scene::Precision& p = scene.precision;
    if (report.bounds) {
        const scene::Bounds& b = *report.bounds;
        const std::string from = report.exactBounds ? " (B-rep)" : " (triangles)";
        rows.push_back(
            {report.selectionName, "size dX dY dZ " + scene::pointText(b.max - b.min, p) + from});
        rows.push_back({report.selectionName, "box min " + scene::pointText(b.min, p)});
        rows.push_back({report.selectionName, "box max " + scene::pointText(b.max, p)});
    }
    for (const scene::SolidProperties& s : report.solids) {
        const std::string name = objectPath(scene, s.object);
        rows.push_back({name, s.closed ? "volume " + scene::formatVolume(s.volume, unit, p)
                                       : "open shell: no volume"});
        rows.push_back({name, "surface area " + scene::formatArea(s.area, unit, p)});
        rows.push_back({name, "centre of mass " + scene::pointText(s.center, p)});
    }
    if (report.solidsLeftOut)
        rows.push_back(
            {"selection", std::to_string(report.solidsLeftOut) + " more solids left out (at most " +
                              std::to_string(Inspector::maxSolids) + " are worked out)"});
    if (const auto& sum = report.sum) {
        const std::string name = "sum of " + std::to_string(sum->object) + " solids";
        // An open shell's volume means nothing: the centre is then the surfaces' (inspect.h).
        const bool byVolume = sum->closed && sum->volume > 0.0;
        rows.push_back({name, "volume " + scene::formatVolume(sum->volume, unit, p) +
                                  (sum->closed ? "" : " (some are open shells)")});
        rows.push_back({name, "surface area " + scene::formatArea(sum->area, unit, p)});
        rows.push_back({name, (byVolume ? "centre of mass " : "centre of the surfaces ") +
                                  scene::pointText(sum->center, p)});
    }
    if (report.a) rows.push_back({"A", report.a->label});
    if (report.b) rows.push_back({"B", report.b->label});
    if (report.distance) addDistanceRows(scene, report, rows);
    if (!rows.empty()) rows.insert(rows.begin(), {"", scene::unitHeading(unit)});
    return rows;
}

std::vector<std::string> Inspector::update(const scene::Scene& scene,
                                           const std::vector<scene::TreeRow>& tree,
                                           const scene::PartSet& selected, const Things& things) {
    if (!stale(selected, things)) return {};
    const bool selectionChanged = !valid_ || selected != selection_;
    const bool thingsChanged = !valid_ || things.version() != version_;
    valid_ = true;
    selection_ = selected;
    version_ = things.version();
    std::vector<std::string> said;
    const std::string unit = unitWord(scene.unit);

    if (selectionChanged) {
        InspectReport next;
        next.selectedParts = selected.size();
        if (next.selectedParts > 0) {
            bool allWhole = false;
            const std::vector<uint32_t> objects = touchedObjects(scene, selected, allWhole);
            // Solids: CAD scenes alone, whose B-rep gives volumes that mean something.
            for (uint32_t object : objects) {
                if (!scene.brep) break;
                if (next.solids.size() == maxSolids) {
                    ++next.solidsLeftOut;
                    continue;
                }
                if (auto p = scene::objectProperties(scene, object)) next.solids.push_back(*p);
            }
            if (next.solids.size() >= 2) next.sum = scene::sumProperties(next.solids);
            // Whole solids: the union of their exact boxes; else the triangles' box.
            if (allWhole && !next.solids.empty() && !next.solidsLeftOut &&
                next.solids.size() == objects.size()) {
                next.bounds = next.sum ? next.sum->bbox : next.solids.front().bbox;
                next.exactBounds = true;
            } else if (const scene::Bounds b = scene::partsWorldBounds(scene, selected);
                       !scene::isEmpty(b)) {
                next.bounds = b;
            }
            if (next.bounds) {
                const glm::dvec3 size = next.bounds->max - next.bounds->min;
                said.push_back("inspect size " + precise(size.x) + " " + precise(size.y) + " " +
                               precise(size.z) + " " + unit);
            }
            if (!next.solids.empty()) {
                const scene::SolidProperties sum =
                    next.sum ? *next.sum : scene::sumProperties(next.solids);
                said.push_back("inspect solids " + std::to_string(sum.object) + " volume " +
                               precise(sum.volume) + " area " + precise(sum.area) + " " + unit);
            }
        }
        next.a = report_.a;
        next.b = report_.b;
        next.distance = report_.distance;
        report_ = std::move(next);
    }
    if (thingsChanged) {
        report_.a = things.a();
        report_.b = things.b();
        report_.distance.reset();
        if (report_.a && report_.b)
            report_.distance = scene::measureDistance(scene, *report_.a, *report_.b);
        const std::string line = thingsLine(things);
        if (line != saidThings_) said.push_back("inspect things " + line);
        saidThings_ = line;
        if (report_.distance)
            said.push_back("inspect distance " + precise(report_.distance->distance) + " " + unit);
    }
    if (report_.selectedParts) report_.selectionName = selectionName(tree, selected, things);
    report_.rows = inspectRows(scene, report_);
    return said;
}

} // namespace app
