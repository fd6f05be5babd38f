// inspect_query.h - the Inspect panel's slow work as a question for a worker thread
// (util::LatestWorker, owned by Inspector): the selection's box, each selected CAD solid's
// volume, area and centre of mass (BRepGProp, BRepBndLib), and A's and B's distance
// (BRepExtrema_DistShapeShape) take Open CASCADE milliseconds to seconds, which the frame must
// not wait for. The question holds everything it reads (a copy of the scene, the parts, the
// things), so the viewer may change or replace its scene while the answer is worked out.
#pragma once

#include <atomic>
#include <memory>
#include <optional>

#include "app/viewer/state/inspect_report.h"

namespace app {

struct InspectQuery {
    // A copy of the scene as the selection was made: it shares the triangles' arrays and the
    // B-rep (scene/shared_array.h, BrepShapes), copying the objects alone.
    std::shared_ptr<const scene::Scene> scene;
    bool selection = false; // work out the selection's part of the report
    scene::PartSet selected;
    bool distance = false; // work out A's and B's distance
    std::optional<scene::Thing> a, b;
};

// On the worker. Thread safety: the scene copy is only read; its arrays are read-only while
// shared (copy on write); BrepShapes decodes a shape under its own lock and hands out const
// shapes; Open CASCADE's BRepGProp, BRepBndLib and BRepExtrema only read the shared TopoDS
// shapes (placed copies are new handles, their reference counts atomic), as the UI thread's
// edge and face reports do. nullopt once `cancelled` is seen (checked between solids).
std::optional<InspectAnswer> answerInspect(const InspectQuery& query,
                                           const std::atomic<bool>& cancelled);

} // namespace app
