// cad_build.cpp - the CAD scene's shapes, geometries, materials and objects (cad_build.h).
#include "scene/cad/cad_build.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <BRepBndLib.hxx>
#include <BRepTools.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>

#include "scene/cad/cad_mesh.h"
#include "scene/cad/cad_surface.h"

namespace scene::cad {
namespace {

glm::dvec4 rgbaOf(const Rgba& c) {
    const Quantity_Color& rgb = c.GetRGB();
    return {rgb.Red(), rgb.Green(), rgb.Blue(), c.Alpha()};
}

// A new distinct shape: its faces, bounds and the colours its leaf gives them. Coloured
// sub-shapes name their faces by TShape: their locations are the product's, which the leaf's
// shape no longer carries.
Distinct distinctOf(const Leaf& leaf) {
    Distinct d;
    d.shape = leaf.shape;
    d.name = leaf.product;
    TopExp::MapShapes(d.shape, TopAbs_FACE, d.faces);
    if (d.faces.Extent() > 0) BRepBndLib::Add(d.shape, d.box, false);
    d.faceColor.resize(size_t(d.faces.Extent()));
    std::map<const void*, int> faceIndex;
    for (int f = d.faces.Extent(); f >= 1; --f) // the first of equal TShapes wins
        faceIndex[d.faces(f).TShape().get()] = f;
    for (const auto& [sub, color] : leaf.subColors) {
        TopTools_IndexedMapOfShape subFaces;
        TopExp::MapShapes(sub, TopAbs_FACE, subFaces);
        for (int f = 1; f <= subFaces.Extent(); ++f) {
            const auto found = faceIndex.find(subFaces(f).TShape().get());
            // A face's own label wins over a solid's or shell's that holds it.
            if (found != faceIndex.end() &&
                (!d.faceColor[size_t(found->second - 1)] || sub.ShapeType() == TopAbs_FACE))
                d.faceColor[size_t(found->second - 1)] = color;
        }
    }
    return d;
}

// Appends the faces of `d` as the parts of a new geometry (the last of the scene), one part
// per face: a face that did not triangulate keeps its part, with no triangles, so that the
// parts after it keep their unique IDs.
void appendFaces(Scene& scene, const Distinct& d, Materials& materials, BuiltGeometries& counts) {
    SharedPoints shared;
    const uint32_t firstVertex = scene.geometries.back().firstVertex;
    for (Standard_Integer f = 1; f <= d.faces.Extent(); ++f) {
        ++counts.faces;
        if (!appendFace(scene, TopoDS::Face(d.faces(f)), firstVertex, &shared)) {
            appendEmptyPart(scene);
            ++counts.facesFailed;
        }
        Geometry& built = scene.geometries.back();
        built.partFaces.push_back(uint32_t(f - 1));
        built.partSurfaces.push_back(surfaceOf(TopoDS::Face(d.faces(f))));
        const auto& own = d.faceColor[size_t(f - 1)];
        built.partMaterials.push_back(own ? materials.of(*own) : gpu::OBJECT_MATERIAL);
        if (scene.vertices.size() > std::numeric_limits<uint32_t>::max() / 2 ||
            scene.indices.size() > std::numeric_limits<uint32_t>::max() / 2)
            throw Bad("the tessellation is too large (try a larger --deflection)");
    }
}

} // namespace

std::string colourName(const glm::dvec4& rgba) {
    auto byte = [](double v) { return uint32_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
    // Colours as stored (XCAF keeps them linear); 8 bits each is plenty to tell them apart.
    char text[32];
    std::snprintf(text, sizeof text, "colour #%08x",
                  byte(rgba.r) << 24 | byte(rgba.g) << 16 | byte(rgba.b) << 8 | byte(rgba.a));
    return text;
}

glm::dmat4 toMatrix(const gp_Trsf& t) {
    glm::dmat4 m(1.0);
    for (int row = 1; row <= 3; ++row)
        for (int col = 1; col <= 4; ++col) m[col - 1][row - 1] = t.Value(row, col);
    return m;
}

DistinctShapes distinctShapes(const std::vector<Leaf>& leaves) {
    DistinctShapes out;
    std::map<std::pair<const void*, int>, size_t> index;
    out.ofLeaf.resize(leaves.size());
    for (size_t i = 0; i < leaves.size(); ++i) {
        const Leaf& leaf = leaves[i];
        const auto key = std::make_pair(static_cast<const void*>(leaf.shape.TShape().get()),
                                        int(leaf.shape.Orientation()));
        auto [it, added] = index.try_emplace(key, out.shapes.size());
        if (added) out.shapes.push_back(distinctOf(leaf));
        out.ofLeaf[i] = it->second;
        const Distinct& d = out.shapes[it->second];
        if (d.faces.Extent() == 0) {
            ++out.faceless;
            continue;
        }
        if (!d.box.IsVoid()) out.world.Add(d.box.Transformed(leaf.world));
    }
    return out;
}

Materials::Materials(Scene& scene)
    : scene_(scene), grey_(addMaterial(scene, "default", Material{}.color)) {}

uint32_t Materials::of(const Rgba& color) {
    const glm::dvec4 rgba = rgbaOf(color);
    const std::string name = colourName(rgba);
    auto [it, added] = byName_.try_emplace(name, 0);
    // XCAF holds linear RGB, as the renderer's material colours are.
    if (added) it->second = addMaterial(scene_, name, glm::vec4(rgba));
    return it->second;
}

BuiltGeometries buildGeometries(Scene& scene, std::vector<Distinct>& shapes,
                                const std::string& stem, Materials& materials,
                                const CadProgress& progress, const std::atomic<bool>* cancel) {
    BuiltGeometries counts;
    uint32_t unnamed = 0;
    for (size_t di = 0; di < shapes.size(); ++di) {
        Distinct& d = shapes[di];
        if (progress) progress("building", double(di) / double(shapes.size()));
        if (cancel && *cancel) throw Bad("cancelled");
        if (d.faces.Extent() == 0) continue;
        Geometry& g = scene.geometries.emplace_back();
        g.name = d.name.empty() ? stem + " shape " + std::to_string(++unnamed) : d.name;
        g.firstVertex = uint32_t(scene.vertices.size());
        g.firstIndex = uint32_t(scene.indices.size());
        g.firstPart = uint32_t(scene.parts.size());
        appendFaces(scene, d, materials, counts);
        Geometry& built = scene.geometries.back();
        if (std::all_of(built.partMaterials.begin(), built.partMaterials.end(),
                        [](uint32_t m) { return m == gpu::OBJECT_MATERIAL; }))
            built.partMaterials.clear(); // every face takes its object's colour
        built.vertexCount = uint32_t(scene.vertices.size()) - built.firstVertex;
        built.partCount = uint32_t(scene.parts.size()) - built.firstPart;
        counts.emptyShapes += built.triangleCount == 0; // kept: its parts keep their IDs
        d.geometry = int64_t(scene.geometries.size() - 1);
    }
    return counts;
}

std::string objectName(const Leaf& leaf, const std::string& stem, uint32_t& unnamed) {
    return leaf.name.empty() ? stem + " solid " + std::to_string(++unnamed) : leaf.name;
}

void addObjects(Scene& scene, const std::vector<Leaf>& leaves, const DistinctShapes& shapes,
                Materials& materials, const std::string& stem) {
    uint32_t unnamed = 0;
    for (size_t i = 0; i < leaves.size(); ++i) {
        const Leaf& leaf = leaves[i];
        const Distinct& d = shapes.shapes[shapes.ofLeaf[i]];
        if (d.geometry < 0) continue;
        // The instance's colour, else the product's.
        const uint32_t material = leaf.color ? materials.of(*leaf.color) : materials.grey();
        const std::string name = objectName(leaf, stem, unnamed);
        addObject(scene, uint32_t(d.geometry), material, toMatrix(leaf.world), name,
                  joinPath(leaf.group, name));
    }
    if (scene.objects.empty()) throw Bad("no face of the model could be triangulated");
}

std::vector<BrepShapes::Shape> keptShapes(const std::vector<Distinct>& shapes, size_t geometries) {
    std::vector<BrepShapes::Shape> kept(geometries);
    for (const Distinct& d : shapes) {
        if (d.geometry < 0) continue;
        auto& shape = kept[size_t(d.geometry)];
        shape.shape = d.shape;
        for (int f = 1; f <= d.faces.Extent(); ++f) shape.faces.push_back(TopoDS::Face(d.faces(f)));
    }
    return kept;
}

} // namespace scene::cad
