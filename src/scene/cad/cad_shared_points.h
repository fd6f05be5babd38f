// cad_shared_points.h - one set of points for each B-rep edge and vertex, whichever faces mesh
// them. Open CASCADE's mesher samples an edge once for all its faces, but stores each face's
// nodes in that face's own frame: brought back through different locations, the same point
// comes out a few units in the last place apart (CrankArm.brep and Motor-c.brep: 16 edges of
// their tessellations open by position, at coordinates near 0 where a float resolves 1e-14).
// Faces then share no vertex there and the rasterizer's watertight rule does not hold.
#pragma once

#include <cstdint>
#include <vector>

#include <Poly_Triangulation.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopoDS_Face.hxx>

#include "scene/scene.h"

namespace scene {

// The points the first face through each edge (its inner nodes) and each vertex gave them,
// for one geometry: the faces after it take those.
class SharedPoints {
  public:
    // Moves the boundary nodes of `face`, whose triangulation's nodes are `vertices` (node n at
    // vertices[n - 1]), onto the points its edges and vertices were given by faces before it,
    // and records the points of those it is the first to mesh. A node moves only where it lies
    // within the edge's or vertex's tolerance of that point, so a polygon that does not match
    // (another sampling) is left as it is.
    void share(const TopoDS_Face& face, const Handle(Poly_Triangulation) & triangulation,
               const TopLoc_Location& location, Vertex* vertices);

  private:
    // The point kept for `shape` at `index` of `points`, by IsSame (TShape and location).
    TopTools_DataMapOfShapeInteger index_;
    std::vector<std::vector<glm::vec3>> points_;
    std::vector<glm::vec3>* find(const TopoDS_Shape& shape);
    void add(const TopoDS_Shape& shape, std::vector<glm::vec3> points);
};

} // namespace scene
