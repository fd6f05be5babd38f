// cad_levels.cpp - CAD shapes tessellated again at coarser deflections, as candidate levels of
// detail (cad_levels.h).
#include "scene/cad/cad_levels.h"

#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>

#include "scene/cad/cad_mesh.h"

namespace scene {
namespace {

// The faces of `shape` in the order full detail's parts number them, at their current
// triangulation; no parts where a face that full detail draws has no triangles: the hole it
// left would show, where the mesh path's welded surface still covers a part it drops. A face
// full detail has no triangles for stays empty here too.
LevelMesh tessellated(const Scene& scene, const Geometry& full, const BrepShapes::Shape& shape) {
    Scene scratch;
    scratch.geometries.emplace_back();
    SharedPoints shared;
    for (uint32_t p = 0; p < full.partCount; ++p) {
        if (appendFace(scratch, shape.faces[full.partFaces[p]], 0, &shared)) continue;
        if (scene.parts[full.firstPart + p].triangleCount > 0) return {};
        appendEmptyPart(scratch);
    }
    LevelMesh level;
    level.vertices = scratch.vertices.take();
    for (const Part& part : scratch.parts) {
        const auto first = scratch.indices.begin() + 3 * ptrdiff_t(part.firstTriangle);
        level.parts.emplace_back(first, first + 3 * ptrdiff_t(part.triangleCount));
    }
    return level;
}

// Meshes `shapes` anew at `deflection` (what they had is dropped first, or the mesher would
// keep it).
void tessellate(const std::vector<TopoDS_Shape>& shapes, double deflection, double angle,
                const std::set<const void*>& skipped) {
    TopoDS_Compound all;
    BRep_Builder builder;
    builder.MakeCompound(all);
    for (const TopoDS_Shape& shape : shapes) builder.Add(all, shape);
    BRepTools::Clean(all);
    IMeshTools_Parameters parameters;
    parameters.Deflection = deflection;
    parameters.Angle = angle;
    parameters.Relative = false;
    parameters.InParallel = true;
    MeshBudget unlimited;
    unlimited.maxTriangles = std::numeric_limits<uint64_t>::max();
    unlimited.skipped = skipped;
    meshCounted(all, parameters, unlimited, {});
}

} // namespace

std::vector<GeometryCandidates> cadCandidates(const Scene& scene,
                                              const std::vector<BrepShapes::Shape>& shapes,
                                              double deflection, double angularDeflection,
                                              const std::set<const void*>& skipped,
                                              const std::function<void(double)>& progress) {
    std::vector<GeometryCandidates> out;
    std::vector<float> sizes;
    for (uint32_t g = 0; g < scene.geometries.size() && g < shapes.size(); ++g)
        if (scene.geometries[g].level == 0 && scene.geometries[g].levels.empty() &&
            !shapes[g].shape.IsNull()) {
            out.push_back({g, {{}}});
            sizes.push_back(geometrySize(scene, scene.geometries[g]));
        }
    // The tessellations take the first half of the progress, the measures the second.
    constexpr size_t passes = std::size(kCandidateDeflections);
    std::vector<std::pair<size_t, size_t>> measures; // (shape, candidate)
    for (size_t k = 0; k < passes; ++k) {
        if (progress) progress(0.5 * double(k) / double(passes));
        const double asked = deflection * kCandidateDeflections[k];
        std::vector<size_t> going;
        std::vector<TopoDS_Shape> meshed;
        for (size_t i = 0; i < out.size(); ++i) {
            const std::vector<LevelMesh>& chain = out[i].chains[0];
            if ((chain.empty() || !chain.back().parts.empty()) &&
                asked <= double(kUsefulErrorShare) * double(sizes[i])) {
                going.push_back(i);
                meshed.push_back(shapes[out[i].geometry].shape);
            }
        }
        if (going.empty()) break;
        tessellate(
            meshed, asked,
            std::min(angularDeflection * std::sqrt(kCandidateDeflections[k]), std::numbers::pi / 2),
            skipped);
        for (size_t i : going) {
            out[i].chains[0].push_back(
                tessellated(scene, scene.geometries[out[i].geometry], shapes[out[i].geometry]));
            measures.emplace_back(i, out[i].chains[0].size() - 1);
        }
    }
    for (const BrepShapes::Shape& shape : shapes)
        if (!shape.shape.IsNull()) BRepTools::Clean(shape.shape);
    // Measured as every kind of level is: the deflection asked is no bound (the mesher keeps it
    // only where it samples, and on a plane it is no distance at all), nor is full detail's own
    // deflection added, full detail being what level 0 draws (lod_error.h).
    forEachTask(
        measures.size(),
        [&](size_t t) {
            const auto [i, k] = measures[t];
            measureCandidate(scene, scene.geometries[out[i].geometry], out[i].chains[0][k],
                             sizes[i]);
        },
        [&](double fraction) {
            if (progress) progress(0.5 + 0.5 * fraction);
        });
    if (progress) progress(1.0);
    return out;
}

} // namespace scene
