// cad_mesh.cpp - Open CASCADE triangulations into scene geometry, and tessellations counted.
#include "scene/cad/cad_mesh.h"

#include <algorithm>
#include <new>
#include <set>

#include <BRepMesh_Context.hxx>
#include <BRepMesh_DelabellaMeshAlgoFactory.hxx>
#include <BRepMesh_FaceDiscret.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepMesh_MeshAlgoFactory.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <IMeshData_Face.hxx>
#include <Poly.hxx>
#include <Poly_Triangulation.hxx>
#include <Standard_OutOfMemory.hxx>
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

void appendEmptyPart(Scene& scene) {
    scene.parts.push_back({scene.geometries.back().triangleCount, 0});
}

namespace {

uint64_t trianglesOf(const TopoDS_Face& face) {
    TopLoc_Location location;
    const Handle(Poly_Triangulation)& t = BRep_Tool::Triangulation(face, location);
    return t.IsNull() ? 0 : uint64_t(t->NbTriangles());
}

// Open CASCADE's own meshing of a face, then its triangles counted; skipped once the budget
// is spent. Faces are meshed on the mesher's threads, so the budget is atomic. Where the first
// algorithm leaves the face without triangles, the fallback (when there is one) tries again.
class CountingAlgo : public IMeshTools_MeshAlgo {
  public:
    CountingAlgo(const Handle(IMeshTools_MeshAlgo) & inner,
                 const Handle(IMeshTools_MeshAlgo) & fallback, MeshBudget& budget)
        : inner_(inner), fallback_(fallback), budget_(budget) {}
    void Perform(const IMeshData::IFaceHandle& face, const IMeshTools_Parameters& parameters,
                 const Message_ProgressRange& range) override {
        if (budget_.stop() || inner_.IsNull() ||
            budget_.skipped.count(face->GetFace().TShape().get()))
            return;
        // A triangulation the face had (read from a BREP file) was counted before meshing
        // began, and this one replaces it.
        const uint64_t before = trianglesOf(face->GetFace());
        try {
            inner_->Perform(face, parameters, range);
            if (!fallback_.IsNull() && trianglesOf(face->GetFace()) == 0 && !budget_.stop())
                fallback_->Perform(face, parameters, range);
        } catch (const Standard_OutOfMemory&) {
            budget_.outOfMemory = true;
            throw;
        } catch (const std::bad_alloc&) {
            budget_.outOfMemory = true;
            throw;
        }
        const uint64_t after = trianglesOf(face->GetFace());
        const uint64_t total = budget_.triangles.fetch_add(after - before) + (after - before);
        if (total > budget_.maxTriangles) budget_.over = true;
        if (before == 0) ++budget_.facesMeshed;
    }

  private:
    Handle(IMeshTools_MeshAlgo) inner_, fallback_;
    MeshBudget& budget_;
};

// Open CASCADE's default algorithms (Watson's incremental Delaunay), but for planar faces its
// Delabella one: a sweep in O(n log n) where Watson's grows much faster with a face's points.
// A KiCad board's outline, a plane with hundreds of holes, took 10.5 s and 530 MB on one
// thread, Delabella 1.4 s and 140 MB, for the same 98,580 triangles (they are the triangles of
// the same boundary points, which both keep). A face Delabella leaves empty is meshed again
// the default way.
class CountingFactory : public IMeshTools_MeshAlgoFactory {
  public:
    explicit CountingFactory(MeshBudget& budget) : budget_(budget) {}
    Handle(IMeshTools_MeshAlgo) GetAlgo(const GeomAbs_SurfaceType type,
                                        const IMeshTools_Parameters& parameters) const override {
        if (type == GeomAbs_Plane)
            return new CountingAlgo(planes_->GetAlgo(type, parameters),
                                    default_->GetAlgo(type, parameters), budget_);
        return new CountingAlgo(default_->GetAlgo(type, parameters), nullptr, budget_);
    }

  private:
    Handle(IMeshTools_MeshAlgoFactory) default_ = new BRepMesh_MeshAlgoFactory;
    Handle(IMeshTools_MeshAlgoFactory) planes_ = new BRepMesh_DelabellaMeshAlgoFactory;
    MeshBudget& budget_;
};

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
    try {
        mesher.Perform(context, range);
    } catch (const Standard_Failure&) {
        // Open CASCADE's own thread pool (without TBB) hands a worker's std::bad_alloc on as
        // a Standard_ProgramError.
        if (!budget.outOfMemory) throw;
    }
    if (budget.outOfMemory) throw std::bad_alloc();
}

} // namespace scene
