// brep_shapes.cpp - the kept B-rep and its bytes in the tessellation cache (brep_shapes.h).
#include "scene/cad/brep_shapes.h"

#include <sstream>
#include <stdexcept>

#include <BRep_Builder.hxx>
#include <BinTools.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Iterator.hxx>
#include <gp_Trsf.hxx>

#include "scene/cad/brep_occt.h"
#include "scene/cad/scene_codec.h"

namespace scene {

BrepShapes::BrepShapes(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
BrepShapes::~BrepShapes() = default;

uint32_t BrepShapes::geometryCount() const {
    return uint32_t(impl_->geometries.size());
}

bool BrepShapes::has(uint32_t geometry) const {
    return geometry < impl_->geometries.size() && !impl_->geometries[geometry].shape.IsNull();
}

uint32_t BrepShapes::faceCount(uint32_t geometry) const {
    return has(geometry) ? uint32_t(impl_->geometries[geometry].faces.size()) : 0;
}

// Layout: the shapes with one in a BinTools compound (its children in geometry order), then per
// geometry a flag and, for those with a shape, each face's position in the shape's
// TopExp::MapShapes face order (sewing leaves the faces in another order than the map's).
std::string encodeBrep(const BrepShapes& shapes) {
    const auto& geometries = shapes.impl().geometries;
    TopoDS_Compound all;
    BRep_Builder builder;
    builder.MakeCompound(all);
    ByteWriter out;
    out.put(uint64_t(geometries.size()));
    for (const auto& g : geometries) {
        out.put(uint8_t(!g.shape.IsNull()));
        if (g.shape.IsNull()) continue;
        builder.Add(all, g.shape);
        TopTools_IndexedMapOfShape mapped;
        TopExp::MapShapes(g.shape, TopAbs_FACE, mapped);
        std::vector<int32_t> order;
        for (const TopoDS_Face& face : g.faces) order.push_back(mapped.FindIndex(face));
        out.putArray(order);
    }
    std::ostringstream binary;
    BinTools::Write(all, binary, false, false, BinTools_FormatVersion_CURRENT);
    out.putString(binary.str());
    return std::move(out.bytes());
}

std::shared_ptr<const BrepShapes> decodeBrep(std::string_view bytes) {
    ByteReader in(bytes);
    auto impl = std::make_unique<BrepShapes::Impl>();
    const uint64_t count = in.get<uint64_t>();
    if (count > bytes.size()) throw std::runtime_error("B-rep: geometry count too large");
    std::vector<std::vector<int32_t>> orders(count);
    std::vector<bool> present(count);
    for (uint64_t g = 0; g < count; ++g) {
        present[g] = in.get<uint8_t>() != 0;
        if (present[g]) orders[g] = in.getArray<int32_t>();
    }
    std::istringstream binary{std::string(in.getBytes())};
    if (!in.done()) throw std::runtime_error("B-rep: bytes after the shapes");
    TopoDS_Shape all;
    try {
        BinTools::Read(all, binary);
    } catch (const Standard_Failure& e) {
        throw std::runtime_error(std::string("B-rep: ") + e.GetMessageString());
    }
    if (all.IsNull()) throw std::runtime_error("B-rep: no shapes");
    impl->geometries.resize(count);
    TopoDS_Iterator child(all);
    for (uint64_t g = 0; g < count; ++g) {
        if (!present[g]) continue;
        if (!child.More()) throw std::runtime_error("B-rep: fewer shapes than geometries");
        auto& shape = impl->geometries[g];
        shape.shape = child.Value();
        child.Next();
        TopTools_IndexedMapOfShape mapped;
        TopExp::MapShapes(shape.shape, TopAbs_FACE, mapped);
        for (int32_t index : orders[g]) {
            if (index < 1 || index > mapped.Extent())
                throw std::runtime_error("B-rep: a face index outside its shape");
            shape.faces.push_back(TopoDS::Face(mapped(index)));
        }
    }
    if (child.More()) throw std::runtime_error("B-rep: more shapes than geometries");
    return std::make_shared<const BrepShapes>(std::move(impl));
}

std::optional<TopoDS_Face> partFace(const Scene& scene, uint32_t uniquePartId) {
    if (!scene.brep) return std::nullopt;
    const auto ref = scene.locate(uniquePartId);
    if (!ref) return std::nullopt;
    const uint32_t geometry = scene.objects[ref->object].geometry;
    const Geometry& g = scene.geometries[geometry];
    if (!scene.brep->has(geometry) || ref->localPart >= g.partFaces.size()) return std::nullopt;
    const auto& faces = scene.brep->impl().geometries[geometry].faces;
    const uint32_t face = g.partFaces[ref->localPart];
    if (face >= faces.size()) return std::nullopt;
    return faces[face];
}

TopLoc_Location placement(const glm::dmat4& world) {
    gp_Trsf trsf;
    // glm is column-major: world[column][row].
    trsf.SetValues(world[0][0], world[1][0], world[2][0], world[3][0], //
                   world[0][1], world[1][1], world[2][1], world[3][1], //
                   world[0][2], world[1][2], world[2][2], world[3][2]);
    return TopLoc_Location(trsf);
}

} // namespace scene
