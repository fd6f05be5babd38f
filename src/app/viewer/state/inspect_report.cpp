// inspect_report.cpp - the Inspect panel's report and rows, worked out on change
// (inspect_report.h), the slow part on the Inspector's worker (inspect_query.h).
#include "app/viewer/state/inspect_report.h"

#include <cstdio>
#include <memory>

#include "app/viewer/state/inspect_query.h"

namespace app {
namespace {

std::string objectPath(const scene::Scene& scene, uint32_t object) {
    const scene::Object& o = scene.objects[object];
    return !o.path.empty() ? o.path : !o.name.empty() ? o.name : "object " + std::to_string(object);
}

// The event records' numbers: enough digits to compare with the headless JSON.
util::Significant precise(double value) {
    return util::Significant{value, 9};
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

std::string bothName(const InspectReport& report) {
    return "A (" + report.a->label + ") to B (" + report.b->label + ")";
}

// The rows an answer will fill, while the worker works it out: the panel keeps its height.
void addComputingRows(const std::string& component, std::initializer_list<const char*> what,
                      std::vector<InspectRow>& rows) {
    for (const char* row : what) rows.push_back({component, std::string(row) + " computing..."});
}

void addDistanceRows(const scene::Scene& scene, const InspectReport& report,
                     std::vector<InspectRow>& rows) {
    const scene::DistanceReport& d = *report.distance;
    const scene::Precision& p = scene.precision;
    const std::string both = bothName(report);
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
    if (report.computingSelection)
        addComputingRows(report.selectionName, {"size dX dY dZ", "box min", "box max"}, rows);
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
    if (report.computingDistance)
        addComputingRows(bothName(report),
                         {"minimum distance", "closest point on A", "closest point on B"}, rows);
    if (report.distance) addDistanceRows(scene, report, rows);
    if (!rows.empty()) rows.insert(rows.begin(), {"", scene::unitHeading(unit)});
    return rows;
}

Inspector::Inspector(std::function<void()> landed) : worker_(std::move(landed)) {}

Inspector::~Inspector() = default;

void Inspector::forget() {
    valid_ = false;
    worker_.cancel(); // its answer is of the scene before
}

void Inspector::update(const scene::Scene& scene, const std::vector<scene::TreeRow>& tree,
                       const scene::PartSet& selected, const Things& things, const Events& events) {
    const bool changed = !valid_ || selected != selection_ || things.version() != version_;
    if (changed) ask(scene, selected, things, events);
    // Only the newest question's answer lands: an older one's never shows.
    std::optional<InspectAnswer> answer = worker_.take();
    if (answer) takeIn(scene, std::move(*answer), events);
    if (!changed && !answer) return;
    if (report_.selectedParts) report_.selectionName = selectionName(tree, selected, things);
    report_.rows = inspectRows(scene, report_);
}

// What changed loses its answer at once (it no longer holds); what is still owed, the
// selection's part, A's and B's distance or both, is asked anew, superseding the question
// before, whose answer would not be taken.
void Inspector::ask(const scene::Scene& scene, const scene::PartSet& selected, const Things& things,
                    const Events& events) {
    const bool selectionChanged = !valid_ || selected != selection_;
    const bool thingsChanged = !valid_ || things.version() != version_;
    valid_ = true;
    selection_ = selected;
    version_ = things.version();
    if (selectionChanged) {
        InspectReport next;
        next.selectedParts = selected.size();
        next.computingSelection = next.selectedParts > 0;
        next.a = report_.a;
        next.b = report_.b;
        next.distance = report_.distance;
        next.computingDistance = report_.computingDistance;
        report_ = std::move(next);
    }
    if (thingsChanged) {
        report_.a = things.a();
        report_.b = things.b();
        report_.distance.reset();
        report_.computingDistance = report_.a && report_.b;
        const std::string line = thingsLine(things);
        if (line != saidThings_)
            events.say("inspect_things", [&](util::JsonWriter& j) {
                j.member("a", report_.a ? std::optional(report_.a->label) : std::nullopt);
                j.member("b", report_.b ? std::optional(report_.b->label) : std::nullopt);
            });
        saidThings_ = line;
    }
    if (!computing()) return worker_.cancel();
    InspectQuery query;
    // The worker reads a copy: the viewer's scene changes and is replaced meanwhile.
    query.scene = std::make_shared<const scene::Scene>(scene);
    query.selection = report_.computingSelection;
    query.selected = selected;
    query.distance = report_.computingDistance;
    query.a = report_.a;
    query.b = report_.b;
    worker_.submit([query = std::move(query)](const std::atomic<bool>& cancelled) {
        return answerInspect(query, cancelled);
    });
    events.say("inspect_computing");
}

void Inspector::takeIn(const scene::Scene& scene, InspectAnswer answer, const Events& events) {
    if (answer.selection) {
        InspectReport& got = answer.report;
        report_.selectedParts = got.selectedParts;
        report_.bounds = got.bounds;
        report_.exactBounds = got.exactBounds;
        report_.solids = std::move(got.solids);
        report_.solidsLeftOut = got.solidsLeftOut;
        report_.sum = got.sum;
        report_.computingSelection = false;
        if (report_.bounds) {
            const glm::dvec3 size = report_.bounds->max - report_.bounds->min;
            events.say("inspect_size", [&](util::JsonWriter& j) {
                j.beginArray("size");
                for (int i = 0; i < 3; ++i) j.value(precise(size[i]));
                scene::unitMember(j.endArray(), scene.unit);
            });
        }
        if (!report_.solids.empty()) {
            const scene::SolidProperties sum =
                report_.sum ? *report_.sum : scene::sumProperties(report_.solids);
            events.say("inspect_solids", [&](util::JsonWriter& j) {
                j.member("solids", sum.object).member("volume", precise(sum.volume));
                scene::unitMember(j.member("area", precise(sum.area)), scene.unit);
            });
        }
    }
    if (answer.distance) {
        report_.distance = answer.measured;
        report_.computingDistance = false;
        if (report_.distance)
            events.say("inspect_distance", [&](util::JsonWriter& j) {
                j.member("distance", precise(report_.distance->distance));
                scene::unitMember(j, scene.unit);
            });
    }
}

} // namespace app
