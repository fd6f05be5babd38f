// cad_build.h - the CAD scene from the leaves a file was read into (cad_read.h), stage by stage
// for cad_loader.cpp: the distinct shapes with their faces' colours, a geometry per shape with
// one part per triangulated face, a material per colour, an object per leaf, and the shapes
// kept for exact inspection. Internal to the CAD loader; speaks Open CASCADE.
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Bnd_Box.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>

#include "scene/cad/brep_occt.h"
#include "scene/cad/cad_read.h"

namespace scene::cad {

// A shape as the leaves use it: the same TShape in the same orientation is one, however many
// leaves place it.
struct Distinct {
    TopoDS_Shape shape;
    std::string name; // the product's
    TopTools_IndexedMapOfShape faces;
    std::vector<std::optional<Rgba>> faceColor; // by face index - 1: its own colour
    Bnd_Box box;
    int64_t geometry = -1; // the scene geometry built from it; -1: none (yet)
};

struct DistinctShapes {
    std::vector<Distinct> shapes;
    std::vector<size_t> ofLeaf; // each leaf's, by index into `shapes`
    uint32_t faceless = 0;      // leaves whose shape has no face
    Bnd_Box world;              // the leaves with faces, placed
};

// A colour material's name, "colour #rrggbbaa" (8 bits each): materials of one name are one.
std::string colourName(const glm::dvec4& rgba);

// Double, as Open CASCADE keeps it: a part placed kilometres away keeps its millimetres.
glm::dmat4 toMatrix(const gp_Trsf& t);

// The leaves' distinct shapes, with their faces and their faces' own colours.
DistinctShapes distinctShapes(const std::vector<Leaf>& leaves);

// A material per distinct colour, for objects and for faces with colours of their own, and
// the default grey of objects without one.
class Materials {
  public:
    explicit Materials(Scene& scene);
    uint32_t grey() const { return grey_; }
    uint32_t of(const Rgba& color);

  private:
    Scene& scene_;
    uint32_t grey_ = 0;
    std::map<std::string, uint32_t> byName_; // colourName to material
};

// What building the geometries counted.
struct BuiltGeometries {
    uint32_t faces = 0;       // over all distinct shapes
    uint32_t facesFailed = 0; // of those, without triangles (parts that draw nothing)
    uint32_t emptyShapes = 0; // shapes no face of which triangulated (geometries that draw nothing)
};

// A geometry per distinct shape with faces, from the shapes' current triangulations, named
// after the product (else "<stem> shape N"), one part per face, in TopExp::MapShapes order: a
// face without triangles keeps its part, empty; sets each shape's `geometry`. Reports "building"
// progress; throws Bad when `cancel` is set or the tessellation is too large for 32-bit indices.
BuiltGeometries buildGeometries(Scene& scene, std::vector<Distinct>& shapes,
                                const std::string& stem, Materials& materials,
                                const CadProgress& progress, const std::atomic<bool>* cancel);

// The name addObjects gives a leaf: its own, else "<stem> solid N", N counting the leaves
// named so far in this way.
std::string objectName(const Leaf& leaf, const std::string& stem, uint32_t& unnamed);

// One object per leaf whose shape has a geometry, placed by the leaf, with the leaf's colour
// (else grey) and name (else "<stem> solid N"). Throws Bad where no leaf has one.
void addObjects(Scene& scene, const std::vector<Leaf>& leaves, const DistinctShapes& shapes,
                Materials& materials, const std::string& stem);

// The shapes the geometries were built from, by geometry index (`geometries` of them), for
// exact inspection (brep_shapes.h) and levels of detail.
std::vector<BrepShapes::Shape> keptShapes(const std::vector<Distinct>& shapes, size_t geometries);

} // namespace scene::cad
