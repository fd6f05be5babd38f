// scene_codec.cpp - Scene to bytes and back (scene_codec.h), field by field so that no
// padding byte is written and every count read is checked.
#include "scene/cad/scene_codec.h"

namespace scene {

namespace {

// The fixed-size records that go as whole arrays: their layouts have no padding.
static_assert(sizeof(Vertex) == 6 * sizeof(float));
static_assert(sizeof(Part) == 2 * sizeof(uint32_t));
// The records written field by field, at their sizes on this platform (libstdc++, x86-64):
// a field added to one of them changes its size and stops the build here, until it is
// encoded below and kCadCacheVersion (cad_cache.h) is bumped, so that no old entry is read
// as a new one.
static_assert(sizeof(Geometry) == 160 && sizeof(Object) == 208 && sizeof(Material) == 48 &&
                  sizeof(SurfaceInfo) == 104,
              "a scene record changed: encode its fields and bump kCadCacheVersion");

// The records' fields in the order they are stored: `io` is a ByteWriter (records const) or
// a ByteReader (records to fill).
template <typename IO, typename S>
void surfaceFields(IO& io, S& s) {
    fields(io, s.kind, s.area, s.normal, s.d, s.radius, s.axisOrigin, s.axisDirection);
}

template <typename IO, typename G>
void geometryFields(IO& io, G& g) {
    fields(io, g.name, g.firstVertex, g.vertexCount, g.firstIndex, g.triangleCount, g.firstPart,
           g.partCount, g.level, g.lodError, g.partFaces);
    io.records(g.partSurfaces, [](auto& io, auto& s) { surfaceFields(io, s); });
    fields(io, g.partMaterials, g.levels);
}

template <typename IO, typename S>
void sceneFields(IO& io, S& scene) {
    fields(io, scene.vertices, scene.indices, scene.parts);
    io.records(scene.geometries, [](auto& io, auto& g) { geometryFields(io, g); });
    io.records(scene.materials, [](auto& io, auto& m) { fields(io, m.name, m.color); });
    io.records(scene.objects, [](auto& io, auto& o) {
        fields(io, o.geometry, o.material, o.world, o.uniquePartOffset, o.name, o.path);
    });
}

} // namespace

void encodeScene(const Scene& scene, ByteWriter& out) {
    sceneFields(out, scene);
}

Scene decodeScene(ByteReader& in) {
    Scene scene;
    sceneFields(in, scene);
    // What the bytes may hold that no scene does; validate() checks the rest (ranges, parts,
    // indices, materials, unique IDs).
    for (const Geometry& g : scene.geometries) {
        for (size_t size : {g.partFaces.size(), g.partSurfaces.size(), g.partMaterials.size()})
            if (size != 0 && size != g.partCount) throw std::runtime_error("per-part list length");
        for (const SurfaceInfo& s : g.partSurfaces)
            if (uint8_t(s.kind) > uint8_t(SurfaceKind::Other))
                throw std::runtime_error("unknown surface kind");
        for (uint32_t l : g.levels)
            if (l >= scene.geometries.size()) throw std::runtime_error("level out of range");
    }
    try {
        validate(scene);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(e.what());
    }
    return scene;
}

} // namespace scene
