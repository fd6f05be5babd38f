// cad_conform.cpp - a piece's parts laid out in the file's numbers (cad_conform.h).
#include "scene/cad/cad_conform.h"

#include <algorithm>
#include <map>

#include <BRep_Builder.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

namespace scene::cad {
namespace {

bool matches(const Scene& piece, const std::vector<uint32_t>& objectFaces) {
    if (piece.objects.size() != objectFaces.size()) return false;
    for (size_t k = 0; k < objectFaces.size(); ++k)
        if (piece.geometries[piece.objects[k].geometry].partCount != objectFaces[k]) return false;
    return true;
}

// A part as read: its object and its number in that object's geometry.
struct Source {
    uint32_t object = 0, part = 0;
};

// Builds the layout's objects from the parts as read, one geometry each.
class Relayout {
  public:
    Relayout(const Scene& piece, const std::vector<BrepShapes::Shape>& kept)
        : piece_(piece), kept_(kept) {
        out_.materials = piece.materials;
    }

    // The next layout object: `parts` of the sources (an empty part past their end), and with
    // `rest` the sources after them joined to its last part.
    void addObject(const std::vector<Source>& sources, size_t& next, uint32_t parts, bool rest) {
        Geometry& g = out_.geometries.emplace_back();
        g.name = piece_.geometries.empty() ? std::string() : piece_.geometries[0].name;
        g.firstVertex = uint32_t(out_.vertices.size());
        g.firstIndex = uint32_t(out_.indices.size());
        g.firstPart = uint32_t(out_.parts.size());
        BrepShapes::Shape& shape = kept_out_.emplace_back();
        BRep_Builder builder;
        TopoDS_Compound compound;
        builder.MakeCompound(compound);
        vertexBase_.clear();
        for (uint32_t q = 0; q < parts; ++q) {
            const uint32_t first = out_.geometries.back().triangleCount;
            const bool joinRest = rest && q + 1 == parts;
            const size_t end = joinRest ? sources.size() : std::min(next + 1, sources.size());
            bool described = false;
            for (; next < end; ++next) {
                appendTriangles(sources[next]);
                if (!described) describe(sources[next], shape, builder, compound);
                described = true;
            }
            if (!described) describeNothing();
            Geometry& built = out_.geometries.back();
            out_.parts.push_back({first, built.triangleCount - first});
        }
        Geometry& built = out_.geometries.back();
        built.vertexCount = uint32_t(out_.vertices.size()) - built.firstVertex;
        built.partCount = parts;
        shape.shape = compound;
        const uint32_t material = piece_.objects.empty() ? 0 : piece_.objects[0].material;
        scene::addObject(out_, uint32_t(out_.geometries.size() - 1), material, glm::dmat4(1.0));
    }

    Scene take(std::vector<BrepShapes::Shape>& kept) {
        kept = std::move(kept_out_);
        return std::move(out_);
    }

  private:
    // The source's triangles, its object's vertices placed by the object (once per geometry).
    void appendTriangles(const Source& s) {
        const Object& object = piece_.objects[s.object];
        const Geometry& from = piece_.geometries[object.geometry];
        auto [it, added] = vertexBase_.try_emplace(s.object, 0);
        Geometry& to = out_.geometries.back();
        if (added) {
            it->second = uint32_t(out_.vertices.size()) - to.firstVertex;
            const glm::dmat3 turn(object.world);
            for (uint32_t v = 0; v < from.vertexCount; ++v) {
                const Vertex& vertex = piece_.vertices[from.firstVertex + v];
                out_.vertices.push_back(
                    {glm::vec3(placed(object.world, vertex.position)),
                     glm::vec3(glm::normalize(turn * glm::dvec3(vertex.normal)))});
            }
        }
        const Part& part = piece_.parts[from.firstPart + s.part];
        const uint32_t first = from.firstIndex + 3 * part.firstTriangle;
        for (uint32_t i = 0; i < 3 * part.triangleCount; ++i)
            out_.indices.push_back(piece_.indices[first + i] + it->second);
        to.triangleCount += part.triangleCount;
    }

    void describe(const Source& s, BrepShapes::Shape& shape, BRep_Builder& builder,
                  TopoDS_Compound& compound) {
        const Object& object = piece_.objects[s.object];
        const Geometry& from = piece_.geometries[object.geometry];
        Geometry& to = out_.geometries.back();
        const uint32_t face = s.part < from.partFaces.size() ? from.partFaces[s.part] : kNoFace;
        const auto& faces = kept_[object.geometry].faces;
        if (face < faces.size()) {
            const TopoDS_Face moved = TopoDS::Face(faces[face].Moved(placement(object.world)));
            builder.Add(compound, moved);
            to.partFaces.push_back(uint32_t(shape.faces.size()));
            shape.faces.push_back(moved);
        } else {
            to.partFaces.push_back(kNoFace);
        }
        to.partSurfaces.push_back(s.part < from.partSurfaces.size() ? from.partSurfaces[s.part]
                                                                    : SurfaceInfo{});
        to.partMaterials.push_back(s.part < from.partMaterials.size() ? from.partMaterials[s.part]
                                                                      : gpu::OBJECT_MATERIAL);
    }

    void describeNothing() {
        Geometry& to = out_.geometries.back();
        to.partFaces.push_back(kNoFace);
        to.partSurfaces.push_back(SurfaceInfo{});
        to.partMaterials.push_back(gpu::OBJECT_MATERIAL);
    }

    const Scene& piece_;
    const std::vector<BrepShapes::Shape>& kept_;
    Scene out_;
    std::vector<BrepShapes::Shape> kept_out_;
    std::map<uint32_t, uint32_t> vertexBase_; // source object -> its vertices' first, here
};

} // namespace

void conformToLayout(Scene& piece, std::vector<BrepShapes::Shape>& kept,
                     const std::vector<uint32_t>& objectFaces, std::vector<std::string>& warnings) {
    if (matches(piece, objectFaces)) return;
    std::vector<Source> sources;
    uint64_t listed = 0;
    for (uint32_t k = 0; k < piece.objects.size(); ++k)
        for (uint32_t p = 0; p < piece.geometries[piece.objects[k].geometry].partCount; ++p)
            sources.push_back({k, p});
    for (uint32_t faces : objectFaces) listed += faces;
    warnings.push_back("Open CASCADE gave " + std::to_string(sources.size()) + " faces in " +
                       std::to_string(piece.objects.size()) + " solids where the file lists " +
                       std::to_string(listed) + " in " + std::to_string(objectFaces.size()) +
                       ": the parts are numbered as the file lists its faces");
    Relayout relayout(piece, kept);
    size_t next = 0;
    for (size_t j = 0; j < objectFaces.size(); ++j)
        relayout.addObject(sources, next, objectFaces[j], j + 1 == objectFaces.size());
    piece = relayout.take(kept);
    // A part that takes nothing keeps no material of its own either.
    for (Geometry& g : piece.geometries)
        if (std::all_of(g.partMaterials.begin(), g.partMaterials.end(),
                        [](uint32_t m) { return m == gpu::OBJECT_MATERIAL; }))
            g.partMaterials.clear();
}

} // namespace scene::cad
