// scene_codec.cpp - Scene to bytes and back (scene_codec.h), field by field so that no
// padding byte is written and every count read is checked.
#include "scene/scene_codec.h"

namespace scene {

namespace {

// The fixed-size records that go as whole arrays: their layouts have no padding.
static_assert(sizeof(Vertex) == 6 * sizeof(float));
static_assert(sizeof(Part) == 2 * sizeof(uint32_t));
// The records written field by field, at their sizes on this platform (libstdc++, x86-64):
// a field added to one of them changes its size and stops the build here, until it is
// encoded below and kCadCacheVersion (cad_cache.h) is bumped, so that no old entry is read
// as a new one.
static_assert(sizeof(Geometry) == 160 && sizeof(Object) == 144 && sizeof(Material) == 48 &&
                  sizeof(SurfaceInfo) == 104,
              "a scene record changed: encode its fields and bump kCadCacheVersion");

void putSurface(ByteWriter& out, const SurfaceInfo& s) {
    out.put(uint8_t(s.kind));
    out.put(s.area);
    out.put(s.normal);
    out.put(s.d);
    out.put(s.radius);
    out.put(s.axisOrigin);
    out.put(s.axisDirection);
}

SurfaceInfo getSurface(ByteReader& in) {
    SurfaceInfo s;
    const uint8_t kind = in.get<uint8_t>();
    if (kind > uint8_t(SurfaceKind::Other)) throw std::runtime_error("unknown surface kind");
    s.kind = SurfaceKind(kind);
    s.area = in.get<double>();
    s.normal = in.get<glm::dvec3>();
    s.d = in.get<double>();
    s.radius = in.get<double>();
    s.axisOrigin = in.get<glm::dvec3>();
    s.axisDirection = in.get<glm::dvec3>();
    return s;
}

void putGeometry(ByteWriter& out, const Geometry& g) {
    out.putString(g.name);
    for (uint32_t v : {g.firstVertex, g.vertexCount, g.firstIndex, g.triangleCount, g.firstPart,
                       g.partCount, g.level})
        out.put(v);
    out.put(g.lodError);
    out.putArray(g.partFaces);
    out.put(uint64_t(g.partSurfaces.size()));
    for (const SurfaceInfo& s : g.partSurfaces) putSurface(out, s);
    out.putArray(g.partMaterials);
    out.putArray(g.levels);
}

Geometry getGeometry(ByteReader& in) {
    Geometry g;
    g.name = in.getString();
    for (uint32_t* v : {&g.firstVertex, &g.vertexCount, &g.firstIndex, &g.triangleCount,
                        &g.firstPart, &g.partCount, &g.level})
        *v = in.get<uint32_t>();
    g.lodError = in.get<float>();
    g.partFaces = in.getArray<uint32_t>();
    const uint64_t surfaces = in.get<uint64_t>();
    // Each part's lists are empty or one per part; checking first bounds the allocation.
    if (surfaces != 0 && surfaces != g.partCount) throw std::runtime_error("surface count");
    for (uint64_t i = 0; i < surfaces; ++i) g.partSurfaces.push_back(getSurface(in));
    g.partMaterials = in.getArray<uint32_t>();
    g.levels = in.getArray<uint32_t>();
    for (size_t size : {g.partFaces.size(), g.partMaterials.size()})
        if (size != 0 && size != g.partCount) throw std::runtime_error("per-part list length");
    return g;
}

} // namespace

void encodeScene(const Scene& scene, ByteWriter& out) {
    out.putArray(scene.vertices);
    out.putArray(scene.indices);
    out.putArray(scene.parts);
    out.put(uint64_t(scene.geometries.size()));
    for (const Geometry& g : scene.geometries) putGeometry(out, g);
    out.put(uint64_t(scene.materials.size()));
    for (const Material& m : scene.materials) {
        out.putString(m.name);
        out.put(m.color);
    }
    out.put(uint64_t(scene.objects.size()));
    for (const Object& o : scene.objects) {
        out.put(o.geometry);
        out.put(o.material);
        out.put(o.world);
        out.put(o.uniquePartOffset);
        out.putString(o.name);
        out.putString(o.path);
    }
}

Scene decodeScene(ByteReader& in) {
    Scene scene;
    scene.vertices = in.getArray<Vertex>();
    scene.indices = in.getArray<uint32_t>();
    scene.parts = in.getArray<Part>();
    // Counts of variable-size records are bounded by their smallest encoding, 8 bytes.
    auto count = [&in] {
        const uint64_t n = in.get<uint64_t>();
        if (n > (uint64_t(1) << 32)) throw std::runtime_error("count too large");
        return n;
    };
    for (uint64_t i = count(); i > 0; --i) scene.geometries.push_back(getGeometry(in));
    for (uint64_t i = count(); i > 0; --i) {
        Material& m = scene.materials.emplace_back();
        m.name = in.getString();
        m.color = in.get<glm::vec4>();
    }
    for (uint64_t i = count(); i > 0; --i) {
        Object& o = scene.objects.emplace_back();
        o.geometry = in.get<uint32_t>();
        o.material = in.get<uint32_t>();
        o.world = in.get<glm::mat4>();
        o.uniquePartOffset = in.get<uint32_t>();
        o.name = in.getString();
        o.path = in.getString();
    }
    // validate() checks the rest (ranges, parts, indices, materials, unique IDs).
    for (const Geometry& g : scene.geometries)
        for (uint32_t l : g.levels)
            if (l >= scene.geometries.size()) throw std::runtime_error("level out of range");
    try {
        validate(scene);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(e.what());
    }
    return scene;
}

} // namespace scene
