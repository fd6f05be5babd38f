// inspect_query.cpp - the Inspect report's slow part, worked out on the worker
// (inspect_query.h).
#include "app/viewer/state/inspect_query.h"

#include "scene/bounds.h"

namespace app {
namespace {

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

// The selection's fields of `report`; false once cancelled.
bool answerSelection(const scene::Scene& scene, const scene::PartSet& selected,
                     const std::atomic<bool>& cancelled, InspectReport& report) {
    report.selectedParts = selected.size();
    if (report.selectedParts == 0) return true;
    bool allWhole = false;
    const std::vector<uint32_t> objects = touchedObjects(scene, selected, allWhole);
    // Solids: CAD scenes alone, whose B-rep gives volumes that mean something.
    for (uint32_t object : objects) {
        if (!scene.brep) break;
        if (cancelled.load()) return false; // a solid is Open CASCADE's longest step
        if (report.solids.size() == Inspector::maxSolids) {
            ++report.solidsLeftOut;
            continue;
        }
        if (auto p = scene::objectProperties(scene, object)) report.solids.push_back(*p);
    }
    if (report.solids.size() >= 2) report.sum = scene::sumProperties(report.solids);
    // Whole solids: the union of their exact boxes; else the triangles' box.
    if (allWhole && !report.solids.empty() && !report.solidsLeftOut &&
        report.solids.size() == objects.size()) {
        report.bounds = report.sum ? report.sum->bbox : report.solids.front().bbox;
        report.exactBounds = true;
    } else if (const scene::Bounds b = scene::partsWorldBounds(scene, selected);
               !scene::isEmpty(b)) {
        report.bounds = b;
    }
    return !cancelled.load();
}

} // namespace

std::optional<InspectAnswer> answerInspect(const InspectQuery& query,
                                           const std::atomic<bool>& cancelled) {
    InspectAnswer answer;
    const scene::Scene& scene = *query.scene;
    if (query.selection) {
        if (!answerSelection(scene, query.selected, cancelled, answer.report)) return std::nullopt;
        answer.selection = true;
    }
    if (query.distance) {
        if (cancelled.load()) return std::nullopt;
        if (query.a && query.b) answer.measured = scene::measureDistance(scene, *query.a, *query.b);
        answer.distance = true;
    }
    if (cancelled.load()) return std::nullopt;
    return answer;
}

} // namespace app
