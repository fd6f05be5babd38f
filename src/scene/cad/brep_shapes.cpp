// brep_shapes.cpp - the kept B-rep: shapes encoded, decoded one geometry at a time when asked
// (brep_shapes.h, brep_occt.h).
#include "scene/cad/brep_shapes.h"

#include <sstream>
#include <stdexcept>

#include <BinTools.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Trsf.hxx>

#include "scene/cad/brep_occt.h"
#include "scene/cad/scene_codec.h"

namespace scene {

uint32_t encodedFaceCount(std::string_view bytes) {
    ByteReader in(bytes);
    return uint32_t(in.get<uint64_t>()); // the face order's length, first
}

BrepShapes::BrepShapes(std::vector<Stored> stored, std::shared_ptr<const EncodedShapeFile> file)
    : stored_(std::move(stored)), file_(std::move(file)), decoded_(stored_.size()) {}

BrepShapes::~BrepShapes() = default;

bool BrepShapes::has(uint32_t geometry) const {
    return geometry < stored_.size() && stored_[geometry].present;
}

uint32_t BrepShapes::faceCount(uint32_t geometry) const {
    return has(geometry) ? stored_[geometry].faces : 0;
}

std::string BrepShapes::encoded(uint32_t geometry) const {
    const Stored& s = stored_.at(geometry);
    if (!s.present) return {};
    if (!s.bytes.empty() || !file_) return s.bytes;
    return file_->read(s.offset, s.size, s.hash);
}

const BrepShapes::Shape& BrepShapes::shape(uint32_t geometry) const {
    static const Shape none;
    if (!has(geometry)) return none;
    const std::lock_guard lock(mutex_);
    std::unique_ptr<Shape>& kept = decoded_[geometry];
    if (!kept) {
        kept = std::make_unique<Shape>(decodeShape(encoded(geometry)));
        if (kept->faces.size() != stored_[geometry].faces)
            throw std::runtime_error("B-rep: another face count than stored");
    }
    return *kept;
}

uint32_t BrepShapes::decodedCount() const {
    const std::lock_guard lock(mutex_);
    uint32_t count = 0;
    for (const auto& kept : decoded_) count += kept != nullptr;
    return count;
}

std::string encodeShape(const BrepShapes::Shape& shape) {
    TopTools_IndexedMapOfShape mapped;
    TopExp::MapShapes(shape.shape, TopAbs_FACE, mapped);
    std::vector<int32_t> order;
    order.reserve(shape.faces.size());
    for (const TopoDS_Face& face : shape.faces) order.push_back(mapped.FindIndex(face));
    std::ostringstream binary;
    // Without triangulations: the scene has its own, and they are most of the bytes.
    BinTools::Write(shape.shape, binary, false, false, BinTools_FormatVersion_CURRENT);
    ByteWriter out;
    out.putArray(order);
    out.putString(binary.str());
    return std::move(out.bytes());
}

BrepShapes::Shape decodeShape(std::string_view bytes) {
    ByteReader in(bytes);
    const std::vector<int32_t> order = in.getArray<int32_t>();
    std::istringstream binary{std::string(in.getBytes())};
    if (!in.done()) throw std::runtime_error("B-rep: bytes after the shape");
    BrepShapes::Shape shape;
    try {
        BinTools::Read(shape.shape, binary);
    } catch (const Standard_Failure& e) {
        throw std::runtime_error(std::string("B-rep: ") + e.GetMessageString());
    }
    if (shape.shape.IsNull()) throw std::runtime_error("B-rep: no shape");
    TopTools_IndexedMapOfShape mapped;
    TopExp::MapShapes(shape.shape, TopAbs_FACE, mapped);
    for (int32_t index : order) {
        if (index < 1 || index > mapped.Extent())
            throw std::runtime_error("B-rep: a face index outside its shape");
        shape.faces.push_back(TopoDS::Face(mapped(index)));
    }
    return shape;
}

std::vector<BrepShapes::Shape> decodedShapes(const BrepShapes& shapes) {
    std::vector<BrepShapes::Shape> out;
    for (uint32_t g = 0; g < shapes.geometryCount(); ++g) out.push_back(shapes.shape(g));
    return out;
}

std::shared_ptr<const BrepShapes> encodedShapes(const std::vector<BrepShapes::Shape>& shapes) {
    std::vector<BrepShapes::Stored> stored(shapes.size());
    for (size_t g = 0; g < shapes.size(); ++g) {
        if (shapes[g].shape.IsNull()) continue;
        stored[g].present = true;
        stored[g].faces = uint32_t(shapes[g].faces.size());
        stored[g].bytes = encodeShape(shapes[g]);
    }
    return std::make_shared<const BrepShapes>(std::move(stored));
}

std::optional<TopoDS_Face> partFace(const Scene& scene, uint32_t uniquePartId) {
    if (!scene.brep) return std::nullopt;
    const auto ref = scene.locate(uniquePartId);
    if (!ref) return std::nullopt;
    const uint32_t geometry = scene.objects[ref->object].geometry;
    const Geometry& g = scene.geometries[geometry];
    if (!scene.brep->has(geometry) || ref->localPart >= g.partFaces.size()) return std::nullopt;
    const uint32_t face = g.partFaces[ref->localPart];
    if (face >= scene.brep->faceCount(geometry)) return std::nullopt;
    return scene.brep->shape(geometry).faces[face];
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
