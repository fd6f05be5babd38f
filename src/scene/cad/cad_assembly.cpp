// cad_assembly.cpp - a split STEP file's scene from its skeleton and pieces (cad_assembly.h).
#include "scene/cad/cad_assembly.h"

#include <algorithm>
#include <cmath>

#include "scene/cad/cad_build.h"
#include "scene/cad/cad_reader_losses.h"

namespace scene::cad {
namespace {

Bounds placedBox(const glm::dmat4& world, const glm::dvec3& min, const glm::dvec3& max) {
    Bounds box{glm::dvec3(std::numeric_limits<double>::max()),
               glm::dvec3(std::numeric_limits<double>::lowest())};
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p((corner & 1) ? max.x : min.x, (corner & 2) ? max.y : min.y,
                           (corner & 4) ? max.z : min.z);
        const glm::dvec3 q(world * glm::dvec4(p, 1.0));
        box.min = glm::min(box.min, q);
        box.max = glm::max(box.max, q);
    }
    return box;
}

} // namespace

CadAssembly::CadAssembly(const SkeletonAnswer& skeleton, const std::vector<step::Piece>& pieces,
                         const std::string& stem)
    : stem_(stem), pieces_(pieces), objectsOf_(pieces.size()), geometryOf_(pieces.size()) {
    addMaterial(scene_, "default", Material{}.color);
    materialByName_["default"] = 0;
    entities_ = skeleton.entities;
    failedEntities_ = skeleton.failedEntities;
    for (const SkeletonLeaf& leaf : skeleton.leaves) {
        if (leaf.piece < 0 || size_t(leaf.piece) >= pieces.size()) {
            if (leaf.faces > 0)
                throw Bad("the assembly structure holds a shape with faces of its own");
            ++faceless_;
            continue;
        }
        const step::Piece& piece = pieces[size_t(leaf.piece)];
        if (piece.layout.faces() == 0) {
            ++faceless_;
            continue;
        }
        addLeaf(leaf, piece, leaf.piece);
    }
    if (scene_.objects.empty()) throw Bad("the file holds no shapes with faces");
}

void CadAssembly::addLeaf(const SkeletonLeaf& leaf, const step::Piece& piece, int32_t index) {
    const step::RepLayout& layout = piece.layout;
    const Bounds box = piece.hasBox ? placedBox(leaf.world, leaf.boxMin, leaf.boxMax)
                                    : Bounds{glm::dvec3(1.0), glm::dvec3(-1.0)};
    // As splitSolids and addObjects name them: a leaf of several solids is a group of its own.
    std::string group = leaf.group;
    if (layout.split)
        group =
            joinPath(leaf.group, !leaf.name.empty() ? leaf.name
                                 : !leaf.product.empty()
                                     ? leaf.product
                                     : stem_ + " compound " + std::to_string(++unnamedCompounds_));
    for (uint32_t k = 0; k < layout.objectFaces.size(); ++k) {
        std::string name, product = leaf.product;
        if (layout.split) {
            const bool free = layout.freeFaces && k + 1 == layout.objectFaces.size();
            name = free ? "free faces" : "solid " + std::to_string(k + 1);
            product = leaf.product.empty() ? std::string() : leaf.product + " " + name;
        } else {
            name = leaf.name.empty() ? stem_ + " solid " + std::to_string(++unnamedSolids_)
                                     : leaf.name;
        }
        const uint32_t geometry = geometryFor(uint32_t(index), k, product, layout.objectFaces[k]);
        const uint32_t object =
            addObject(scene_, geometry, 0, leaf.world, name, joinPath(group, name));
        objectsOf_[size_t(index)].push_back(object);
        leafWorld_.push_back(leaf.world);
        objectLayout_.push_back(k);
        instanceColor_.push_back(leaf.color);
        boxes_.push_back(box);
        state_.push_back(kObjectWaiting);
    }
}

// The geometry of a piece's layout object, waiting: its parts have no triangles yet.
uint32_t CadAssembly::geometryFor(uint32_t piece, uint32_t object, const std::string& name,
                                  uint32_t faces) {
    std::vector<uint32_t>& of = geometryOf_[piece];
    if (of.empty()) of.assign(pieces_[piece].layout.objectFaces.size(), UINT32_MAX);
    if (of[object] != UINT32_MAX) return of[object];
    Geometry& g = scene_.geometries.emplace_back();
    g.name = name.empty() ? stem_ + " shape " + std::to_string(++unnamedShapes_) : name;
    g.firstVertex = uint32_t(scene_.vertices.size());
    g.firstIndex = uint32_t(scene_.indices.size());
    g.firstPart = uint32_t(scene_.parts.size());
    g.partCount = faces;
    scene_.parts.insert(scene_.parts.end(), faces, Part{0, 0});
    brep_.emplace_back();
    of[object] = uint32_t(scene_.geometries.size() - 1);
    return of[object];
}

double CadAssembly::automaticDeflection() const {
    Bounds world{glm::dvec3(std::numeric_limits<double>::max()),
                 glm::dvec3(std::numeric_limits<double>::lowest())};
    for (const Bounds& box : boxes_)
        if (box.min.x <= box.max.x) { // a piece without vertices has none
            world.min = glm::min(world.min, box.min);
            world.max = glm::max(world.max, box.max);
        }
    const double diagonal = world.min.x <= world.max.x ? glm::length(world.max - world.min) : 0.0;
    return std::isfinite(diagonal) && diagonal > 0.0 ? diagonal * kRelativeDeflection : 0.01;
}

uint32_t CadAssembly::materialOf(const std::string& name, const glm::vec4& color) {
    auto [it, added] = materialByName_.try_emplace(name, 0);
    if (added) it->second = addMaterial(scene_, name, color);
    return it->second;
}

} // namespace scene::cad

namespace scene::cad {

void CadAssembly::add(const PieceAnswer& answer) {
    const uint32_t piece = answer.piece;
    const Scene& mesh = answer.mesh;
    const std::vector<uint32_t>& layout = pieces_.at(piece).layout.objectFaces;
    if (mesh.objects.size() != layout.size()) throw Bad("a piece came back in another layout");
    // The piece's colours as this scene's materials.
    std::vector<uint32_t> material(mesh.materials.size(), 0);
    for (size_t m = 1; m < mesh.materials.size(); ++m)
        material[m] = materialOf(mesh.materials[m].name, mesh.materials[m].color);
    const std::vector<uint32_t>& geometries = geometryOf_[piece];
    for (uint32_t k = 0; k < layout.size(); ++k) {
        const Geometry& from = mesh.geometries[mesh.objects[k].geometry];
        if (from.partCount != layout[k]) throw Bad("a piece came back in another layout");
        if (geometries.empty() || geometries[k] == UINT32_MAX) continue;
        Geometry& to = scene_.geometries[geometries[k]];
        to.firstVertex = uint32_t(scene_.vertices.size());
        to.vertexCount = from.vertexCount;
        to.firstIndex = uint32_t(scene_.indices.size());
        to.triangleCount = from.triangleCount;
        scene_.vertices.insert(scene_.vertices.end(), mesh.vertices.begin() + from.firstVertex,
                               mesh.vertices.begin() + from.firstVertex + from.vertexCount);
        scene_.indices.insert(scene_.indices.end(), mesh.indices.begin() + from.firstIndex,
                              mesh.indices.begin() + from.firstIndex + 3 * from.triangleCount);
        std::copy_n(mesh.parts.begin() + from.firstPart, from.partCount,
                    scene_.parts.begin() + to.firstPart);
        to.partFaces = from.partFaces;
        to.partSurfaces = from.partSurfaces;
        to.partMaterials = from.partMaterials;
        for (uint32_t& m : to.partMaterials)
            if (m != gpu::OBJECT_MATERIAL) m = material[m];
        brep_[geometries[k]] = answer.brep.at(mesh.objects[k].geometry);
        for (const GeometryCandidates& c : answer.candidates)
            if (c.geometry == mesh.objects[k].geometry)
                candidates_.push_back({geometries[k], c.chains});
    }
    for (uint32_t object : objectsOf_[piece]) {
        Object& o = scene_.objects[object];
        const Object& from = mesh.objects[objectLayout_[object]];
        o.world = leafWorld_[object] * from.world;
        // The instance's colour, else the product's, else the default grey.
        const auto& own = instanceColor_[object];
        o.material = own ? materialOf(colourName(*own), glm::vec4(*own)) : material[from.material];
        state_[object] = kObjectReady;
    }
    for (const std::string& warning : answer.warnings)
        warnings_.push_back(scene_.objects[objectsOf_[piece].at(0)].path + ": " + warning);
    faces_ += answer.faces;
    facesFailed_ += answer.facesFailed;
    for (const Geometry& g : mesh.geometries) emptyShapes_ += g.triangleCount == 0;
    entities_ += answer.figures.entities;
    failedEntities_ += answer.figures.failedEntities;
    faceEntities_ += answer.figures.faceEntities;
    bytesDone_ += pieces_[piece].bytes;
}

void CadAssembly::lose(uint32_t piece, const std::string& why) {
    const std::vector<uint32_t>& objects = objectsOf_[piece];
    if (objects.empty()) return;
    for (uint32_t object : objects) state_[object] = kObjectLost;
    // Named by the first of its objects' paths: products' own names repeat ("SOLID").
    const Object& first = scene_.objects[objects[0]];
    lost_.push_back(first.path + " (" + std::to_string(objects.size()) +
                    (objects.size() == 1 ? " solid" : " solids") + "): " + why);
    bytesDone_ += pieces_[piece].bytes;
}

CadPartial CadAssembly::partial() const {
    CadPartial out;
    out.scene = std::make_shared<const Scene>(scene_);
    out.boxes = boxes_;
    out.state = state_;
    out.solidsTotal = uint32_t(state_.size());
    for (uint8_t s : state_) {
        out.solidsReady += s == kObjectReady;
        out.solidsLost += s == kObjectLost;
    }
    for (const step::Piece& piece : pieces_) out.bytesTotal += piece.bytes;
    out.bytesDone = bytesDone_;
    return out;
}

// The arrays in geometry order and the materials in the order a whole-file read makes them:
// the default grey, then faces' colours geometry by geometry, then objects' colours.
void CadAssembly::canonicalize() {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    vertices.reserve(scene_.vertices.size());
    indices.reserve(scene_.indices.size());
    for (Geometry& g : scene_.geometries) {
        const auto v = scene_.vertices.begin() + g.firstVertex;
        const auto i = scene_.indices.begin() + g.firstIndex;
        g.firstVertex = uint32_t(vertices.size());
        g.firstIndex = uint32_t(indices.size());
        vertices.insert(vertices.end(), v, v + g.vertexCount);
        indices.insert(indices.end(), i, i + 3 * g.triangleCount);
    }
    scene_.vertices = std::move(vertices);
    scene_.indices = std::move(indices);
    std::vector<uint32_t> renumber(scene_.materials.size(), UINT32_MAX);
    std::vector<Material> materials;
    auto take = [&](uint32_t& m) {
        if (renumber[m] == UINT32_MAX) {
            renumber[m] = uint32_t(materials.size());
            materials.push_back(scene_.materials[m]);
        }
        m = renumber[m];
    };
    uint32_t grey = 0;
    take(grey);
    for (Geometry& g : scene_.geometries)
        for (uint32_t& m : g.partMaterials)
            if (m != gpu::OBJECT_MATERIAL) take(m);
    for (Object& o : scene_.objects) take(o.material);
    scene_.materials = std::move(materials);
}

CadLoadResult CadAssembly::finish(uint32_t levels) {
    if (scene_.indices.empty())
        throw Bad(lost_.empty() ? "no face of the model could be triangulated"
                                : "no solid could be loaded: " + lost_.front());
    canonicalize();
    for (Geometry& g : scene_.geometries)
        if (std::all_of(g.partMaterials.begin(), g.partMaterials.end(),
                        [](uint32_t m) { return m == gpu::OBJECT_MATERIAL; }))
            g.partMaterials.clear();
    CadLoadResult result;
    if (levels > 1) {
        std::stable_sort(candidates_.begin(), candidates_.end(),
                         [](const auto& a, const auto& b) { return a.geometry < b.geometry; });
        addChosenLevels(scene_, candidates_, LodOptions{.levels = levels});
    }
    std::vector<BrepShapes::Stored> stored(scene_.geometries.size());
    for (size_t g = 0; g < brep_.size(); ++g) {
        stored[g].present = !brep_[g].empty();
        stored[g].faces = stored[g].present ? encodedFaceCount(brep_[g]) : 0;
        stored[g].bytes = std::move(brep_[g]);
    }
    scene_.brep = std::make_shared<const BrepShapes>(std::move(stored));
    result.faces = faces_;
    result.facesFailed = facesFailed_;
    if (faceless_)
        result.warnings.push_back(std::to_string(faceless_) +
                                  " shapes without faces (wires or points) skipped");
    ReaderLosses losses{entities_, failedEntities_, faceEntities_};
    if (const auto dropped = lossWarning(losses, faces_, "STEP"))
        result.warnings.push_back(*dropped);
    if (facesFailed_)
        result.warnings.push_back(std::to_string(facesFailed_) + " of " + std::to_string(faces_) +
                                  " faces could not be triangulated: their parts draw nothing");
    if (emptyShapes_)
        result.warnings.push_back(std::to_string(emptyShapes_) +
                                  " shapes had no face that triangulated: they draw nothing");
    for (const std::string& lost : lost_)
        result.warnings.push_back("not loaded, drawing nothing: " + lost);
    result.warnings.insert(result.warnings.end(), warnings_.begin(), warnings_.end());
    result.scene = std::move(scene_);
    return result;
}

} // namespace scene::cad
