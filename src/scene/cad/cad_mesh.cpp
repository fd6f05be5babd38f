// cad_mesh.cpp - Open CASCADE triangulations into scene geometry, at full detail and coarser.
#include "scene/cad/cad_mesh.h"

#include "scene/closest_point.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include <BRepMesh_Context.hxx>
#include <BRepMesh_FaceDiscret.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepMesh_MeshAlgoFactory.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <IMeshData_Face.hxx>
#include <Poly.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

namespace scene {

bool appendFace(Scene& scene, const TopoDS_Face& face, uint32_t geometryFirstVertex,
                SharedPoints* shared) {
    TopLoc_Location location;
    const Handle(Poly_Triangulation)& triangulation = BRep_Tool::Triangulation(face, location);
    if (triangulation.IsNull() || triangulation->NbTriangles() == 0) return false;
    if (!triangulation->HasNormals()) Poly::ComputeNormals(triangulation);
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    const gp_Trsf& trsf = location.Transformation();
    const bool moved = !location.IsIdentity();
    const Standard_Integer nodes = triangulation->NbNodes();
    const uint32_t base = uint32_t(scene.vertices.size()) - geometryFirstVertex;
    const size_t firstIndex = scene.indices.size();
    for (Standard_Integer t = 1; t <= triangulation->NbTriangles(); ++t) {
        Standard_Integer a = 0, b = 0, c = 0;
        triangulation->Triangle(t).Get(a, b, c);
        if (std::min({a, b, c}) < 1 || std::max({a, b, c}) > nodes) continue;
        if (reversed) std::swap(b, c);
        for (Standard_Integer n : {a, b, c}) scene.indices.push_back(base + uint32_t(n - 1));
    }
    if (scene.indices.size() == firstIndex) return false;
    for (Standard_Integer n = 1; n <= nodes; ++n) {
        gp_Pnt p = triangulation->Node(n);
        gp_Dir d = triangulation->Normal(n);
        if (moved) {
            p.Transform(trsf);
            d.Transform(trsf);
        }
        if (reversed) d.Reverse();
        scene.vertices.push_back({glm::vec3(float(p.X()), float(p.Y()), float(p.Z())),
                                  glm::vec3(float(d.X()), float(d.Y()), float(d.Z()))});
    }
    if (shared)
        shared->share(face, triangulation, location,
                      &scene.vertices[scene.vertices.size() - size_t(nodes)]);
    const uint32_t triangles = uint32_t(scene.indices.size() - firstIndex) / 3;
    const Geometry& g = scene.geometries.back();
    scene.parts.push_back({g.triangleCount, triangles});
    scene.geometries.back().triangleCount += triangles;
    return true;
}

namespace {

uint64_t trianglesOf(const TopoDS_Face& face) {
    TopLoc_Location location;
    const Handle(Poly_Triangulation)& t = BRep_Tool::Triangulation(face, location);
    return t.IsNull() ? 0 : uint64_t(t->NbTriangles());
}

// Open CASCADE's own meshing of a face, then its triangles counted; skipped once the budget
// is spent. Faces are meshed on the mesher's threads, so the budget is atomic.
class CountingAlgo : public IMeshTools_MeshAlgo {
  public:
    CountingAlgo(const Handle(IMeshTools_MeshAlgo) & inner, MeshBudget& budget)
        : inner_(inner), budget_(budget) {}
    void Perform(const IMeshData::IFaceHandle& face, const IMeshTools_Parameters& parameters,
                 const Message_ProgressRange& range) override {
        if (budget_.stop() || inner_.IsNull() ||
            budget_.skipped.count(face->GetFace().TShape().get()))
            return;
        // A triangulation the face had (read from a BREP file) was counted before meshing
        // began, and this one replaces it.
        const uint64_t before = trianglesOf(face->GetFace());
        inner_->Perform(face, parameters, range);
        const uint64_t after = trianglesOf(face->GetFace());
        const uint64_t total = budget_.triangles.fetch_add(after - before) + (after - before);
        if (total > budget_.maxTriangles) budget_.over = true;
        if (before == 0) ++budget_.facesMeshed;
    }

  private:
    Handle(IMeshTools_MeshAlgo) inner_;
    MeshBudget& budget_;
};

class CountingFactory : public IMeshTools_MeshAlgoFactory {
  public:
    explicit CountingFactory(MeshBudget& budget) : budget_(budget) {}
    Handle(IMeshTools_MeshAlgo) GetAlgo(const GeomAbs_SurfaceType type,
                                        const IMeshTools_Parameters& parameters) const override {
        return new CountingAlgo(inner_->GetAlgo(type, parameters), budget_);
    }

  private:
    Handle(IMeshTools_MeshAlgoFactory) inner_ = new BRepMesh_MeshAlgoFactory;
    MeshBudget& budget_;
};

// How far full detail's vertices (which lie on the surface) are from `level`'s triangles of
// the same face, the largest over the faces: the mesher bounds its deflection only where it
// samples, and coarse levels of unsewn faces (IGES) stray further. Faces too large to compare
// every vertex with every triangle compare every n-th vertex.
float measuredDistance(const Scene& scene, const Geometry& full, const Geometry& level) {
    constexpr uint64_t budget = uint64_t(1) << 22; // distance tests per face
    float worst = 0.0f;
    for (uint32_t p = 0; p < full.partCount; ++p) {
        const Part& fp = scene.parts[full.firstPart + p];
        const Part& lp = scene.parts[level.firstPart + p];
        const uint64_t tests = 3ull * fp.triangleCount * lp.triangleCount;
        const uint32_t stride = uint32_t(std::max<uint64_t>(1, tests / budget));
        for (uint32_t i = 3 * fp.firstTriangle; i < 3 * (fp.firstTriangle + fp.triangleCount);
             i += stride) {
            const glm::vec3 v =
                scene.vertices[full.firstVertex + scene.indices[full.firstIndex + i]].position;
            float nearest = INFINITY;
            for (uint32_t t = lp.firstTriangle; t < lp.firstTriangle + lp.triangleCount; ++t) {
                const uint32_t* c = &scene.indices[level.firstIndex + 3 * t];
                const glm::vec3 q =
                    closestOnTriangle(v, scene.vertices[level.firstVertex + c[0]].position,
                                      scene.vertices[level.firstVertex + c[1]].position,
                                      scene.vertices[level.firstVertex + c[2]].position);
                nearest = std::min(nearest, glm::length(v - q));
            }
            worst = std::max(worst, nearest);
        }
    }
    return worst;
}

// Builds `shape`'s faces at the current triangulation as the level after `finer`'s; false
// (and the scene as it was) when a face has no triangles, the level saves too little or the
// levels would take too much memory.
bool addLevel(Scene& scene, const CadShapeFaces& shape, uint32_t finer, uint32_t level, float error,
              float fullDeflection, const LodOptions& lod) {
    const size_t vertices = scene.vertices.size(), indices = scene.indices.size(),
                 parts = scene.parts.size();
    Geometry next = levelShell(scene, scene.geometries[shape.geometry], level);
    next.lodError = error;
    scene.geometries.push_back(std::move(next));
    bool whole = true;
    SharedPoints shared;
    for (uint32_t face : scene.geometries[shape.geometry].partFaces)
        if (!(whole = appendFace(scene, TopoDS::Face((*shape.faces)(int(face) + 1)),
                                 uint32_t(vertices), &shared)))
            break;
    Geometry& built = scene.geometries.back();
    built.vertexCount = uint32_t(scene.vertices.size() - vertices);
    const double before = scene.geometries[finer].triangleCount;
    uint64_t levelBytes = geometryBytes(built);
    for (uint32_t l : scene.geometries[shape.geometry].levels)
        levelBytes += geometryBytes(scene.geometries[l]);
    if (!whole || double(built.triangleCount) > double(lod.keepAtMost) * before ||
        double(levelBytes) >
            double(lod.memory) * double(geometryBytes(scene.geometries[shape.geometry]))) {
        scene.geometries.pop_back();
        scene.vertices.resize(vertices);
        scene.indices.resize(indices);
        scene.parts.resize(parts);
        return false;
    }
    // The error: what the mesher was asked for, or what it measurably missed by, with full
    // detail's own deflection on top (its vertices lie on the surface, its triangles not).
    const Geometry& fullDetail = scene.geometries[shape.geometry];
    built.lodError = std::max(error, measuredDistance(scene, fullDetail, built) + fullDeflection);
    built.lodError = std::max(built.lodError, scene.geometries[finer].lodError);
    scene.geometries[shape.geometry].levels.push_back(uint32_t(scene.geometries.size() - 1));
    return true;
}

} // namespace

void meshCounted(const TopoDS_Shape& shape, const IMeshTools_Parameters& parameters,
                 MeshBudget& budget, const Message_ProgressRange& range) {
    // Faces that keep the triangulations they have (a BREP file may hold some, which the
    // mesher keeps where they are fine enough) are never handed to the algorithms: count them
    // first, each face once. Where they alone pass the budget, they go, and every face is
    // meshed at the deflection asked for, so that a larger one can help.
    std::set<const void*> counted;
    uint64_t stored = 0;
    uint32_t storedFaces = 0;
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next())
        if (counted.insert(e.Current().TShape().get()).second) {
            const uint64_t t = trianglesOf(TopoDS::Face(e.Current()));
            stored += t;
            storedFaces += t > 0;
        }
    if (stored > budget.maxTriangles) {
        BRepTools::Clean(shape);
    } else {
        budget.triangles += stored;
        budget.facesMeshed += storedFaces;
    }
    // BRepMesh_IncrementalMesh's own context, with the face step's algorithms wrapped.
    Handle(BRepMesh_Context) context = new BRepMesh_Context(parameters.MeshAlgo);
    context->SetFaceDiscret(new BRepMesh_FaceDiscret(new CountingFactory(budget)));
    BRepMesh_IncrementalMesh mesher;
    mesher.SetShape(shape);
    mesher.ChangeParameters() = parameters;
    mesher.Perform(context, range);
}

void addCadLevels(Scene& scene, const TopoDS_Shape& all, const std::vector<CadShapeFaces>& shapes,
                  double deflection, double angularDeflection, uint32_t levels,
                  const LodOptions& lod, const std::set<const void*>& skipped,
                  const std::function<void(double)>& progress) {
    for (uint32_t level = 1; level < levels; ++level) {
        if (progress) progress(double(level - 1) / double(levels - 1));
        const double scale = std::pow(4.0, double(level));
        IMeshTools_Parameters parameters;
        parameters.Deflection = deflection * scale;
        parameters.Angle =
            std::min(angularDeflection * std::pow(2.0, double(level)), std::numbers::pi / 2);
        parameters.Relative = false;
        parameters.InParallel = true;
        BRepTools::Clean(all); // so that the mesher starts over instead of keeping finer ones
        MeshBudget unlimited;
        unlimited.maxTriangles = std::numeric_limits<uint64_t>::max();
        unlimited.skipped = skipped;
        meshCounted(all, parameters, unlimited, {});
        for (const CadShapeFaces& shape : shapes) {
            const Geometry& full = scene.geometries[shape.geometry];
            // Only shapes that have every level so far go on.
            if (full.levels.size() != level - 1) continue;
            const uint32_t finer = level == 1 ? shape.geometry : full.levels.back();
            addLevel(scene, shape, finer, level, float(parameters.Deflection), float(deflection),
                     lod);
        }
    }
    if (progress) progress(1.0);
}

} // namespace scene
