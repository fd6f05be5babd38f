// test_gltf_loader.cpp - the glTF loader on real models, on the malformed files of the assimp
// test corpus, and on small handmade files that pin each feature and each error.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>

#include <gtest/gtest.h>

#include "scene/gltf/gltf_loader.h"

namespace {

namespace fs = std::filesystem;
using scene::LoadResult;
using scene::ModelError;
using scene::PartMode;

const fs::path kCorpus = "/usr/share/assimp/models/glTF2";

// ---- helpers ---------------------------------------------------------------------------

// Asserts the ModelError contract: one line "<path>: <reason>", reason containing `needle`.
void expectModelError(const std::function<void()>& load, const std::string& path,
                      const std::string& needle) {
    try {
        load();
        ADD_FAILURE() << path << " loaded, expected a ModelError mentioning '" << needle << "'";
    } catch (const ModelError& e) {
        std::string what = e.what();
        EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_NE(what.find(needle), std::string::npos) << what;
    }
}

struct Stats {
    size_t objects, geometries, parts;
    uint32_t uniqueParts;
    uint64_t drawnTriangles;
};

Stats statsOf(const scene::Scene& s) {
    return {s.objects.size(), s.geometries.size(), s.parts.size(), s.uniquePartCount(),
            s.drawnTriangleCount()};
}

void expectStats(const std::string& file, PartMode mode, Stats want) {
    LoadResult r = scene::loadGltf((kCorpus / file).string(), {mode});
    EXPECT_NO_THROW(scene::validate(r.scene));
    Stats got = statsOf(r.scene);
    EXPECT_EQ(got.objects, want.objects) << file;
    EXPECT_EQ(got.geometries, want.geometries) << file;
    EXPECT_EQ(got.parts, want.parts) << file;
    EXPECT_EQ(got.uniqueParts, want.uniqueParts) << file;
    EXPECT_EQ(got.drawnTriangles, want.drawnTriangles) << file;
}

// Binary data for handmade files; each append is 4-byte aligned as accessors require.
struct Blob {
    std::vector<unsigned char> bytes;
    size_t add(const void* data, size_t size) {
        while (bytes.size() % 4) bytes.push_back(0);
        size_t offset = bytes.size();
        auto p = static_cast<const unsigned char*>(data);
        bytes.insert(bytes.end(), p, p + size);
        return offset;
    }
    template <class T>
    size_t add(const std::vector<T>& v) {
        return add(v.data(), v.size() * sizeof(T));
    }
};

std::string base64(const std::vector<unsigned char>& in) {
    static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < in.size(); i += 3) {
        uint32_t n = uint32_t(in[i]) << 16;
        if (i + 1 < in.size()) n |= uint32_t(in[i + 1]) << 8;
        if (i + 2 < in.size()) n |= in[i + 2];
        out += abc[n >> 18 & 63];
        out += abc[n >> 12 & 63];
        out += i + 1 < in.size() ? abc[n >> 6 & 63] : '=';
        out += i + 2 < in.size() ? abc[n & 63] : '=';
    }
    return out;
}

// A glTF document: `rest` holds every top-level member but asset and buffers.
std::string gltfJson(const Blob& blob, const std::string& rest) {
    return R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":)" +
           std::to_string(blob.bytes.size()) + R"(,"uri":"data:application/octet-stream;base64,)" +
           base64(blob.bytes) + "\"}]," + rest + "}";
}

std::vector<unsigned char> glb(const std::string& json, const std::vector<unsigned char>& bin) {
    std::string j = json;
    while (j.size() % 4) j += ' ';
    std::vector<unsigned char> b = bin;
    while (b.size() % 4) b.push_back(0);
    std::vector<unsigned char> out = {'g', 'l', 'T', 'F'};
    auto u32 = [&](uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back((unsigned char)(v >> (8 * i)));
    };
    u32(2);
    u32(uint32_t(12 + 8 + j.size() + 8 + b.size()));
    u32(uint32_t(j.size()));
    u32(0x4E4F534A); // JSON
    out.insert(out.end(), j.begin(), j.end());
    u32(uint32_t(b.size()));
    u32(0x004E4942); // BIN
    out.insert(out.end(), b.begin(), b.end());
    return out;
}

class GltfHandmade : public ::testing::Test {
  protected:
    fs::path dir_;
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("idview_gltf_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text) {
        return write(name, std::vector<unsigned char>(text.begin(), text.end()));
    }
    std::string write(const std::string& name, const std::vector<unsigned char>& bytes) {
        fs::path p = dir_ / name;
        std::ofstream(p, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        return p.string();
    }
    LoadResult load(const std::string& json, PartMode mode = PartMode::Primitives) {
        LoadResult r = scene::loadGltf(write("model.gltf", json), {mode});
        EXPECT_NO_THROW(scene::validate(r.scene));
        return r;
    }
    void expectError(const std::string& json, const std::string& needle) {
        std::string path = write("bad.gltf", json);
        expectModelError([&] { scene::loadGltf(path); }, path, needle);
    }
};

// A unit quad in the xy-plane, counter-clockwise seen from +z.
const std::vector<glm::vec3> kQuad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<uint32_t> kQuadIndices = {0, 1, 2, 0, 2, 3};

std::string accessor(size_t view, int componentType, size_t count, const char* type,
                     const std::string& extra = "") {
    return R"({"bufferView":)" + std::to_string(view) + R"(,"componentType":)" +
           std::to_string(componentType) + R"(,"count":)" + std::to_string(count) + R"(,"type":")" +
           type + "\"" + extra + "}";
}

std::string view(size_t offset, size_t length, const std::string& extra = "") {
    return R"({"buffer":0,"byteOffset":)" + std::to_string(offset) + R"(,"byteLength":)" +
           std::to_string(length) + extra + "}";
}

// One mesh with one primitive, one node, one scene.
std::string singleMesh(const std::string& views, const std::string& accessors,
                       const std::string& primitive, const std::string& node = R"({"mesh":0})") {
    return R"("bufferViews":[)" + views + R"(],"accessors":[)" + accessors +
           R"(],"meshes":[{"primitives":[)" + primitive + R"(]}],"nodes":[)" + node +
           R"(],"scenes":[{"nodes":[0]}],"scene":0)";
}

// Vertex `corner` of triangle `tri` of the first geometry, in geometry-local space.
const scene::Vertex& corner(const scene::Scene& s, uint32_t tri, uint32_t c) {
    const scene::Geometry& g = s.geometries[0];
    return s.vertices[g.firstVertex + s.indices[g.firstIndex + 3 * tri + c]];
}

void expectTriangle(const scene::Scene& s, uint32_t tri, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    EXPECT_EQ(corner(s, tri, 0).position, a) << "triangle " << tri;
    EXPECT_EQ(corner(s, tri, 1).position, b) << "triangle " << tri;
    EXPECT_EQ(corner(s, tri, 2).position, c) << "triangle " << tri;
}

// A quad with indices of `componentType`, packed as `T`.
template <class T>
std::string quadWithIndices(int componentType) {
    Blob blob;
    std::vector<T> idx(kQuadIndices.begin(), kQuadIndices.end());
    size_t p = blob.add(kQuad), i = blob.add(idx);
    return gltfJson(blob, singleMesh(view(p, 48) + "," + view(i, idx.size() * sizeof(T)),
                                     accessor(0, 5126, 4, "VEC3") + "," +
                                         accessor(1, componentType, 6, "SCALAR"),
                                     R"({"attributes":{"POSITION":0},"indices":1})"));
}

} // namespace

// ---- real models -------------------------------------------------------------------------

// Numbers cross-checked with an independent python script over the GLB's JSON and binary
// chunk (node walk of the default scene, primitive count, union-find over index data).
TEST(GltfReal, TwoCylinderEngineStatistics) {
    const std::string file = "2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    expectStats(file, PartMode::Primitives, {67, 29, 34, 115, 121496});
    expectStats(file, PartMode::Components, {67, 29, 1069, 1410, 121496});
}

TEST(GltfReal, BoxTexturedVariants) {
    for (const char* file :
         {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Embedded/BoxTextured.gltf",
          "BoxTextured-glTF-Binary/BoxTextured.glb"}) {
        expectStats(file, PartMode::Primitives, {1, 1, 1, 1, 12});
        // The box's six faces share no vertices: six components.
        expectStats(file, PartMode::Components, {1, 1, 6, 6, 12});
    }
}

TEST(GltfReal, MaterialColourFromBaseColourFactor) {
    LoadResult r = scene::loadGltf((kCorpus / "BoxTextured-glTF/BoxTextured.gltf").string());
    ASSERT_EQ(r.scene.objects.size(), 1u);
    const scene::Material& m = r.scene.materials[r.scene.objects[0].material];
    EXPECT_EQ(m.color, glm::vec4(1.0f)); // BoxTextured has no factor: the default white
}

// ---- the assimp corpus, malformed files included --------------------------------------------

// Every file either loads into a valid scene or fails with one line naming the file; never a
// crash, never another exception type.
TEST(GltfCorpus, EveryFileLoadsOrFailsWithOneLine) {
    size_t files = 0, failures = 0;
    for (const auto& entry : fs::recursive_directory_iterator(kCorpus)) {
        std::string ext = entry.path().extension().string();
        if (ext != ".gltf" && ext != ".glb") continue;
        ++files;
        const std::string path = entry.path().string();
        for (PartMode mode : {PartMode::Primitives, PartMode::Components}) {
            try {
                LoadResult r = scene::loadGltf(path, {mode});
                EXPECT_NO_THROW(scene::validate(r.scene)) << path;
                EXPECT_FALSE(r.scene.objects.empty()) << path;
            } catch (const ModelError& e) {
                std::string what = e.what();
                EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;
                EXPECT_EQ(what.find('\n'), std::string::npos) << what;
                if (mode == PartMode::Primitives) {
                    ++failures;
                    std::cout << "  refused: " << what << "\n";
                }
            }
        }
    }
    EXPECT_GT(files, 40u);
    std::cout << "  " << files << " files, " << failures << " refused\n";
}

TEST(GltfCorpus, ClearlyBrokenFilesAreRefusedWithTheReason) {
    const std::pair<const char*, const char*> cases[] = {
        {"IndexOutOfRange/IndexOutOfRange.gltf", "vertex count"},
        {"IndexOutOfRange/AllIndicesOutOfRange.gltf", "vertex count"},
        {"MissingBin/BoxTextured.gltf", "BoxTextured0.bin"},
        {"RecursiveNodes/RecursiveNodes.gltf", "cycle"},
        {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "infinite POSITION"},
        {"draco/2CylinderEngine.gltf", "KHR_draco_mesh_compression"},
        {"TestNoRootNode/NoScene.gltf", "scene"},
        {"TestNoRootNode/SceneWithoutNodes.gltf", "empty scene"},
    };
    for (const auto& [file, needle] : cases) {
        std::string path = (kCorpus / file).string();
        expectModelError([&] { scene::loadGltf(path); }, path, needle);
    }
}

// assimp's glTF 1.0 models (1.0, 1.0.2, one without asset.version, a version-1 GLB) used to
// come out as "empty scene" or tinygltf's words; each is now refused as what it is.
TEST(GltfCorpus, GltfOneFilesAreRefusedAsGltfOne) {
    size_t files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(kCorpus.parent_path() / "glTF")) {
        std::string ext = entry.path().extension().string();
        if (ext != ".gltf" && ext != ".glb") continue;
        ++files;
        const std::string path = entry.path().string();
        try {
            scene::loadGltf(path);
            ADD_FAILURE() << path << " loaded";
        } catch (const ModelError& e) {
            std::string what = e.what();
            EXPECT_TRUE(what.find(": glTF 1.0") != std::string::npos ||
                        what.find(": binary glTF 1.0 (GLB version 1)") != std::string::npos ||
                        what.find(": asset.version is missing") != std::string::npos)
                << what;
            EXPECT_NE(what.find("convert it"), std::string::npos) << what;
        }
    }
    EXPECT_GE(files, 7u);
}

TEST(GltfCorpus, MissingFile) {
    std::string path = (kCorpus / "no-such-file.glb").string();
    expectModelError([&] { scene::loadGltf(path); }, path, "file not found");
}

// ---- handmade files: features --------------------------------------------------------------

TEST_F(GltfHandmade, IndexComponentTypes) {
    for (const std::string& json : {quadWithIndices<uint8_t>(5121), quadWithIndices<uint16_t>(5123),
                                    quadWithIndices<uint32_t>(5125)}) {
        LoadResult r = load(json);
        ASSERT_EQ(r.scene.geometries.size(), 1u);
        EXPECT_EQ(r.scene.geometries[0].triangleCount, 2u);
        expectTriangle(r.scene, 0, kQuad[0], kQuad[1], kQuad[2]);
        expectTriangle(r.scene, 1, kQuad[0], kQuad[2], kQuad[3]);
    }
}

TEST_F(GltfHandmade, NonIndexedTriangles) {
    Blob blob;
    std::vector<glm::vec3> soup = {kQuad[0], kQuad[1], kQuad[2], kQuad[0], kQuad[2], kQuad[3]};
    blob.add(soup);
    LoadResult r = load(gltfJson(blob, singleMesh(view(0, 72), accessor(0, 5126, 6, "VEC3"),
                                                  R"({"attributes":{"POSITION":0}})")));
    EXPECT_EQ(r.scene.geometries[0].triangleCount, 2u);
    expectTriangle(r.scene, 1, kQuad[0], kQuad[2], kQuad[3]);
}

TEST_F(GltfHandmade, InterleavedByteStride) {
    Blob blob;
    std::vector<glm::vec3> interleaved; // position, normal, position, normal, ...
    for (const auto& p : kQuad) interleaved.insert(interleaved.end(), {p, {0, 0, 1}});
    blob.add(interleaved);
    size_t i = blob.add(kQuadIndices);
    LoadResult r =
        load(gltfJson(blob, singleMesh(view(0, 96, R"(,"byteStride":24)") + "," + view(i, 24),
                                       accessor(0, 5126, 4, "VEC3") + "," +
                                           accessor(0, 5126, 4, "VEC3", R"(,"byteOffset":12)") +
                                           "," + accessor(1, 5125, 6, "SCALAR"),
                                       R"({"attributes":{"POSITION":0,"NORMAL":1},"indices":2})")));
    expectTriangle(r.scene, 1, kQuad[0], kQuad[2], kQuad[3]);
    EXPECT_EQ(corner(r.scene, 1, 1).normal, glm::vec3(0, 0, 1));
}

TEST_F(GltfHandmade, SparseAccessorReplacesVertices) {
    Blob blob;
    size_t p = blob.add(kQuad), i = blob.add(kQuadIndices);
    std::vector<uint16_t> sparseIdx = {2, 0}; // 4 bytes: keeps the next add aligned
    size_t si = blob.add(sparseIdx);
    std::vector<glm::vec3> sparseVal = {{5, 5, 0}};
    size_t sv = blob.add(sparseVal);
    std::string sparse = R"(,"sparse":{"count":1,"indices":{"bufferView":2,"componentType":5123},)"
                         R"("values":{"bufferView":3}})";
    LoadResult r = load(gltfJson(
        blob,
        singleMesh(view(p, 48) + "," + view(i, 24) + "," + view(si, 2) + "," + view(sv, 12),
                   accessor(0, 5126, 4, "VEC3", sparse) + "," + accessor(1, 5125, 6, "SCALAR"),
                   R"({"attributes":{"POSITION":0},"indices":1})")));
    expectTriangle(r.scene, 0, kQuad[0], kQuad[1], glm::vec3(5, 5, 0));
    expectTriangle(r.scene, 1, kQuad[0], glm::vec3(5, 5, 0), kQuad[3]);
}

// Five vertices zig-zagging along x; both modes give three triangles, all facing +z.
TEST_F(GltfHandmade, StripAndFanBecomeTriangleLists) {
    const std::vector<glm::vec3> strip = {{0, 1, 0}, {0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {2, 1, 0}};
    const std::vector<glm::vec3> fan = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 1, 0}};
    for (int mode : {5, 6}) {
        const auto& v = mode == 5 ? strip : fan;
        Blob blob;
        blob.add(v);
        LoadResult r = load(gltfJson(blob, singleMesh(view(0, 60), accessor(0, 5126, 5, "VEC3"),
                                                      R"({"attributes":{"POSITION":0},"mode":)" +
                                                          std::to_string(mode) + "}")));
        ASSERT_EQ(r.scene.geometries[0].triangleCount, 3u) << mode;
        if (mode == 5) {
            // glTF: odd triangles swap their last two corners to keep the winding.
            expectTriangle(r.scene, 0, v[0], v[1], v[2]);
            expectTriangle(r.scene, 1, v[1], v[3], v[2]);
            expectTriangle(r.scene, 2, v[2], v[3], v[4]);
        }
        for (uint32_t t = 0; t < 3; ++t) {
            glm::vec3 a = corner(r.scene, t, 0).position, b = corner(r.scene, t, 1).position,
                      c = corner(r.scene, t, 2).position;
            EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f) << "mode " << mode << " triangle " << t;
        }
        if (mode == 6) {
            for (uint32_t t = 0; t < 3; ++t) expectTriangle(r.scene, t, v[0], v[t + 1], v[t + 2]);
        }
    }
}

TEST_F(GltfHandmade, PointsAndLinesAreSkippedWithWarnings) {
    Blob blob;
    size_t p = blob.add(kQuad), i = blob.add(kQuadIndices);
    std::string json = gltfJson(
        blob, R"("bufferViews":[)" + view(p, 48) + "," + view(i, 24) + R"(],"accessors":[)" +
                  accessor(0, 5126, 4, "VEC3") + "," + accessor(1, 5125, 6, "SCALAR") +
                  R"(],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"mode":0},)"
                  R"({"attributes":{"POSITION":0},"indices":1},)"
                  R"({"attributes":{"POSITION":0},"indices":1,"mode":1}]},)"
                  R"({"primitives":[{"attributes":{"POSITION":0},"mode":3}]}],)"
                  R"("nodes":[{"mesh":0},{"mesh":1}],"scenes":[{"nodes":[0,1]}])");
    LoadResult r = load(json);
    ASSERT_EQ(r.scene.objects.size(), 1u); // mesh 1 has only lines: dropped with its node
    EXPECT_EQ(r.scene.parts.size(), 1u);
    EXPECT_EQ(r.scene.geometries[0].triangleCount, 2u);
    std::string all;
    for (const auto& w : r.warnings) all += w + "|";
    EXPECT_NE(all.find("mesh 0 primitive 0: points skipped"), std::string::npos) << all;
    EXPECT_NE(all.find("mesh 0 primitive 2: lines skipped"), std::string::npos) << all;
    EXPECT_NE(all.find("mesh 1: no triangles, dropped"), std::string::npos) << all;
}

TEST_F(GltfHandmade, MissingNormalsAreComputedFacingTheWinding) {
    LoadResult r = load(quadWithIndices<uint16_t>(5123));
    for (const auto& v : r.scene.vertices) {
        EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-6f);
        EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f); // counter-clockwise seen from +z
    }
}

// Parent TRS (translate (1,2,3), 90 degrees about z, scale 2) times a child matrix
// (translate (10,0,0)): the vertex (1,0,0) lands at (1,4,3) and (1,24,3).
TEST_F(GltfHandmade, TrsAndMatrixNodesCompose) {
    Blob blob;
    size_t p = blob.add(kQuad), i = blob.add(kQuadIndices);
    const float h = std::sqrt(0.5f);
    std::string nodes =
        R"({"mesh":0,"children":[1],"translation":[1,2,3],"scale":[2,2,2],"rotation":[0,0,)" +
        std::to_string(h) + "," + std::to_string(h) +
        R"(]},{"mesh":0,"matrix":[1,0,0,0, 0,1,0,0, 0,0,1,0, 10,0,0,1]})";
    LoadResult r = load(gltfJson(
        blob, singleMesh(view(p, 48) + "," + view(i, 24),
                         accessor(0, 5126, 4, "VEC3") + "," + accessor(1, 5125, 6, "SCALAR"),
                         R"({"attributes":{"POSITION":0},"indices":1})", nodes)));
    ASSERT_EQ(r.scene.objects.size(), 2u);
    glm::vec4 v(1, 0, 0, 1);
    glm::vec3 parent = glm::vec3(r.scene.objects[0].world * v);
    glm::vec3 child = glm::vec3(r.scene.objects[1].world * v);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(parent[k], glm::vec3(1, 4, 3)[k], 1e-4f);
        EXPECT_NEAR(child[k], glm::vec3(1, 24, 3)[k], 1e-4f);
    }
}

TEST_F(GltfHandmade, NodesSharingAMeshShareItsGeometry) {
    Blob blob;
    size_t p = blob.add(kQuad), i = blob.add(kQuadIndices);
    std::string json = gltfJson(
        blob, R"("bufferViews":[)" + view(p, 48) + "," + view(i, 24) + R"(],"accessors":[)" +
                  accessor(0, 5126, 4, "VEC3") + "," + accessor(1, 5125, 6, "SCALAR") +
                  R"(],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1},)"
                  R"({"attributes":{"POSITION":0},"indices":1}]}],)"
                  R"("nodes":[{"mesh":0},{"mesh":0,"translation":[3,0,0]}],)"
                  R"("scenes":[{"nodes":[0,1]}],"scene":0)");
    LoadResult r = load(json);
    ASSERT_EQ(r.scene.geometries.size(), 1u);
    ASSERT_EQ(r.scene.objects.size(), 2u);
    EXPECT_EQ(r.scene.objects[0].geometry, r.scene.objects[1].geometry);
    EXPECT_EQ(r.scene.objects[0].uniquePartOffset, 0u);
    EXPECT_EQ(r.scene.objects[1].uniquePartOffset, 2u);
    EXPECT_EQ(r.scene.uniquePartCount(), 4u);
    // The two primitives read the same vertices but each part gets copies of its own.
    const scene::Geometry& g = r.scene.geometries[0];
    EXPECT_EQ(g.vertexCount, 8u);
    for (uint32_t k = 0; k < 6; ++k) {
        EXPECT_LT(r.scene.indices[g.firstIndex + k], 4u);
        EXPECT_GE(r.scene.indices[g.firstIndex + 6 + k], 4u);
    }
}

TEST_F(GltfHandmade, ComponentsModeSplitsDisjointQuads) {
    Blob blob;
    std::vector<glm::vec3> pos = kQuad;
    for (const auto& q : kQuad) pos.push_back(q + glm::vec3(5, 0, 0));
    std::vector<uint32_t> idx = kQuadIndices;
    for (uint32_t k : kQuadIndices) idx.push_back(k + 4);
    size_t p = blob.add(pos), i = blob.add(idx);
    std::string json = gltfJson(
        blob, singleMesh(view(p, 96) + "," + view(i, 48),
                         accessor(0, 5126, 8, "VEC3") + "," + accessor(1, 5125, 12, "SCALAR"),
                         R"({"attributes":{"POSITION":0},"indices":1})"));
    EXPECT_EQ(load(json, PartMode::Primitives).scene.parts.size(), 1u);
    LoadResult r = load(json, PartMode::Components);
    ASSERT_EQ(r.scene.parts.size(), 2u);
    EXPECT_EQ(r.scene.parts[0].triangleCount, 2u);
    EXPECT_EQ(r.scene.parts[1].triangleCount, 2u);
    EXPECT_EQ(r.scene.geometries[0].vertexCount, 8u);
    EXPECT_EQ(r.scene.uniquePartCount(), 2u);
}

TEST_F(GltfHandmade, GlbWithBinaryChunk) {
    Blob blob;
    size_t p = blob.add(kQuad), i = blob.add(kQuadIndices);
    std::string json =
        R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":72}],)" +
        singleMesh(view(p, 48) + "," + view(i, 24),
                   accessor(0, 5126, 4, "VEC3") + "," + accessor(1, 5125, 6, "SCALAR"),
                   R"({"attributes":{"POSITION":0},"indices":1})") +
        "}";
    LoadResult r = scene::loadGltf(write("model.glb", glb(json, blob.bytes)));
    EXPECT_EQ(r.scene.drawnTriangleCount(), 2u);
}

// ---- handmade files: errors ------------------------------------------------------------------

// A valid quad document, with `edit` applied to its JSON text.
std::string quadJson(const std::function<void(std::string&)>& edit = {}) {
    std::string json = quadWithIndices<uint32_t>(5125);
    if (edit) edit(json);
    return json;
}

void replaceOnce(std::string& text, const std::string& from, const std::string& to) {
    size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
}

TEST_F(GltfHandmade, TruncatedAndWrongMagicGlb) {
    Blob blob;
    blob.add(kQuad);
    std::vector<unsigned char> file = glb(gltfJson(blob, R"("scenes":[])"), {});
    std::vector<unsigned char> half(file.begin(), file.begin() + ptrdiff_t(file.size() / 2));
    std::string path = write("truncated.glb", half);
    expectModelError([&] { scene::loadGltf(path); }, path, "truncated");
    path = write("short.glb", std::vector<unsigned char>(file.begin(), file.begin() + 10));
    expectModelError([&] { scene::loadGltf(path); }, path, "truncated");
    file[3] = 'X';
    path = write("magic.glb", file);
    expectModelError([&] { scene::loadGltf(path); }, path, "wrong magic");
}

TEST_F(GltfHandmade, BrokenJson) {
    std::string json = quadJson();
    expectError(json.substr(0, json.size() / 2), "");
    expectError("", "file is empty");
}

TEST_F(GltfHandmade, AccessorOutOfBounds) {
    expectError(quadJson([](std::string& j) { replaceOnce(j, R"("count":4)", R"("count":5)"); }),
                "accessor 0 is out of bounds of bufferView 0");
    expectError(quadJson([](std::string& j) {
                    replaceOnce(j, R"("count":4)", R"("count":4,"byteOffset":4)");
                }),
                "out of bounds");
    // count * stride far beyond size_t must not wrap around.
    expectError(quadJson([](std::string& j) {
                    replaceOnce(j, R"("count":4)", R"("count":4611686018427387904)");
                }),
                "accessor 0");
}

TEST_F(GltfHandmade, BufferViewOutOfBounds) {
    expectError(quadJson([](std::string& j) {
                    replaceOnce(j, R"("byteOffset":48,"byteLength":24)",
                                R"("byteOffset":56,"byteLength":24)");
                }),
                "bufferView 1");
}

TEST_F(GltfHandmade, IndexBeyondVertexCount) {
    Blob blob;
    std::vector<uint32_t> idx = {0, 1, 7};
    size_t p = blob.add(kQuad), i = blob.add(idx);
    expectError(gltfJson(blob, singleMesh(view(p, 48) + "," + view(i, 12),
                                          accessor(0, 5126, 4, "VEC3") + "," +
                                              accessor(1, 5125, 3, "SCALAR"),
                                          R"({"attributes":{"POSITION":0},"indices":1})")),
                "index 7 is >= the vertex count 4");
}

TEST_F(GltfHandmade, NanPosition) {
    Blob blob;
    std::vector<glm::vec3> pos = kQuad;
    pos[2].y = std::nanf("");
    blob.add(pos);
    expectError(gltfJson(blob, singleMesh(view(0, 48), accessor(0, 5126, 3, "VEC3"),
                                          R"({"attributes":{"POSITION":0}})")),
                "NaN or infinite POSITION");
}

TEST_F(GltfHandmade, NodeCycleAndSharedChild) {
    expectError(quadJson([](std::string& j) {
                    replaceOnce(j, R"("nodes":[{"mesh":0}])",
                                R"("nodes":[{"mesh":0,"children":[1]},{"children":[0]}])");
                }),
                "node cycle");
    expectError(quadJson([](std::string& j) {
                    replaceOnce(j, R"("nodes":[{"mesh":0}])",
                                R"("nodes":[{"children":[1,1]},{"mesh":0}])");
                }),
                "more than one parent");
}

TEST_F(GltfHandmade, EmptyScene) {
    expectError(quadJson([](std::string& j) {
                    replaceOnce(j, R"("nodes":[{"mesh":0}])", R"("nodes":[{}])");
                }),
                "empty scene");
}

TEST_F(GltfHandmade, DracoRequired) {
    expectError(quadJson([](std::string& j) {
                    replaceOnce(j, R"("asset")",
                                R"("extensionsUsed":["KHR_draco_mesh_compression"],)"
                                R"("extensionsRequired":["KHR_draco_mesh_compression"],"asset")");
                }),
                "requires the unsupported extension KHR_draco_mesh_compression");
}

// Found by fuzz_gltf: an accessor without bufferView and count 0 made the loader pass a null
// pointer to memset (undefined behaviour). Zero normals without data fall back to computed.
TEST_F(GltfHandmade, FuzzRegressionNormalsWithoutBufferView) {
    for (const char* count : {"0", "4"}) {
        std::string json = quadJson([&](std::string& j) {
            replaceOnce(j, R"("POSITION":0)", R"("POSITION":0,"NORMAL":2)");
            replaceOnce(j, R"("type":"SCALAR"})",
                        R"("type":"SCALAR"},{"componentType":5126,"type":"VEC3","count":)" +
                            std::string(count) + "}");
        });
        if (std::string(count) == "0") {
            expectError(json, "0 normals for 4 positions");
        } else {
            LoadResult r = load(json);
            EXPECT_EQ(r.scene.vertices[0].normal, glm::vec3(0, 0, 1));
        }
    }
}

namespace {

// A quad mesh per entry of `meshNames` (all over the same accessors; "" leaves one unnamed),
// and `nodes` / `roots` as given.
std::string namedTree(const std::vector<std::string>& meshNames, const std::string& nodes,
                      const std::string& roots) {
    Blob blob;
    size_t p = blob.add(kQuad), i = blob.add(kQuadIndices);
    std::string meshes;
    for (const std::string& name : meshNames) {
        meshes += meshes.empty() ? "{" : ",{";
        if (!name.empty()) meshes += R"("name":")" + name + "\",";
        meshes += R"("primitives":[{"attributes":{"POSITION":0},"indices":1}]})";
    }
    return gltfJson(blob, R"("bufferViews":[)" + view(p, 48) + "," + view(i, 24) +
                              R"(],"accessors":[)" + accessor(0, 5126, 4, "VEC3") + "," +
                              accessor(1, 5125, 6, "SCALAR") + R"(],"meshes":[)" + meshes +
                              R"(],"nodes":[)" + nodes + R"(],"scenes":[{"nodes":[)" + roots +
                              R"(]}],"scene":0)");
}

std::vector<std::string> objectPaths(const scene::Scene& s) {
    std::vector<std::string> paths;
    for (const auto& o : s.objects) paths.push_back(o.path);
    return paths;
}

} // namespace

TEST_F(GltfHandmade, ObjectNameIsTheNodeNameElseTheMeshNameElseNodeIndex) {
    LoadResult r = load(namedTree({"shaft mesh", ""},
                                  R"({"name":"crankshaft","mesh":0},{"mesh":0},{"mesh":1},)"
                                  R"({"name":"","mesh":1})",
                                  "0,1,2,3"));
    ASSERT_EQ(r.scene.objects.size(), 4u);
    EXPECT_EQ(r.scene.objects[0].name, "crankshaft"); // the node's name wins over the mesh's
    EXPECT_EQ(r.scene.objects[1].name, "shaft mesh"); // unnamed node: its mesh's name
    EXPECT_EQ(r.scene.objects[2].name, "node 2");     // neither named: the node's index
    EXPECT_EQ(r.scene.objects[3].name, "node 3");
    // Root nodes: the path is the name.
    EXPECT_EQ(objectPaths(r.scene),
              (std::vector<std::string>{"crankshaft", "shaft mesh", "node 2", "node 3"}));
    const auto info = scene::describePart(r.scene, r.scene.objects[1].uniquePartOffset);
    ASSERT_TRUE(info);
    EXPECT_EQ(info->name, "shaft mesh");
    EXPECT_EQ(info->path, "shaft mesh");
}

TEST_F(GltfHandmade, PathsNameTheNodesFromTheRootDown) {
    // engine -> crankshaft -> {bolt 2, unnamed node with mesh "nut"}, engine -> unnamed group
    // -> cover; a second root "frame" after the whole engine tree.
    LoadResult r = load(namedTree({"", "nut"},
                                  R"({"name":"engine","children":[1,4]},)"         // 0
                                  R"({"name":"crankshaft","children":[2,3]},)"     // 1
                                  R"({"name":"bolt 2","mesh":0},{"mesh":1},)"      // 2, 3
                                  R"({"children":[5]},{"name":"cover","mesh":0},)" // 4, 5
                                  R"({"name":"frame","mesh":0,"children":[7]},)"   // 6
                                  R"({"mesh":0})",                                 // 7
                                  "0,6"));
    EXPECT_EQ(objectPaths(r.scene),
              (std::vector<std::string>{"engine/crankshaft/bolt 2", "engine/crankshaft/nut",
                                        "engine/node 4/cover", "frame", "frame/node 7"}));
    EXPECT_EQ(r.scene.objects[1].name, "nut");
    EXPECT_EQ(r.scene.objects[4].name, "node 7");
}

TEST_F(GltfHandmade, VeryLongPathsKeepTheirLastElements) {
    // A chain of 200 nodes "segment-000" ... "segment-199" (12 characters a level with the
    // '/'), only the last with a mesh: the path keeps the 85 elements that fit in 1024.
    std::string nodes;
    for (int n = 0; n < 200; ++n) {
        char name[16];
        std::snprintf(name, sizeof name, "segment-%03d", n);
        nodes += n ? R"(,{"name":")" : R"({"name":")";
        nodes += name;
        nodes += n < 199 ? R"(","children":[)" + std::to_string(n + 1) + "]}" : R"(","mesh":0})";
    }
    LoadResult r = load(namedTree({""}, nodes, "0"));
    ASSERT_EQ(r.scene.objects.size(), 1u);
    std::string expected = "...";
    for (int n = 115; n < 200; ++n) {
        char name[16];
        std::snprintf(name, sizeof name, "/segment-%03d", n);
        expected += name;
    }
    EXPECT_EQ(r.scene.objects[0].path, expected);
    EXPECT_EQ(r.scene.objects[0].name, "segment-199");
}

// ---- handmade files: versions ----------------------------------------------------------------

std::string withAsset(const std::string& asset) {
    return quadJson([&](std::string& j) {
        replaceOnce(j, R"("asset":{"version":"2.0"})", R"("asset":)" + asset);
    });
}

TEST_F(GltfHandmade, OtherMajorVersionsAreRefusedInWords) {
    const std::string path = write("old.gltf", withAsset(R"({"version":"1.0"})"));
    try {
        scene::loadGltf(path);
        ADD_FAILURE() << "a glTF 1.0 file loaded";
    } catch (const ModelError& e) {
        EXPECT_EQ(std::string(e.what()),
                  path + ": glTF 1.0 is not supported (idview reads glTF 2.0; convert it, e.g. "
                         "with Cesium's gltf-pipeline)");
    }
    expectError(withAsset(R"({"version":"1.0.2"})"), "glTF 1.0.2 is not supported");
    expectError(withAsset(R"({"version":"3.0"})"),
                "glTF 3.0 is not supported (idview reads glTF 2.0)");
    expectError(withAsset(R"({"version":"two"})"), "asset.version 'two' is not a glTF version");
    expectError(withAsset(R"({"version":""})"), "asset.version '' is not a glTF version");
}

TEST_F(GltfHandmade, MissingVersionIsRefused) {
    const std::string missing = "asset.version is missing or not a string: not a glTF 2.0 file";
    expectError(withAsset(R"({"generator":"x"})"), missing);
    expectError(withAsset(R"({"version":2.0})"), missing);
    expectError(
        quadJson([](std::string& j) { replaceOnce(j, R"("asset":{"version":"2.0"},)", ""); }),
        missing);
}

// glTF 2.0, 3.2: a newer minor version can be read (what is new in it is ignored) unless
// asset.minVersion says the file needs more than 2.0.
TEST_F(GltfHandmade, MinorVersionsAreCompatibleUnlessMinVersionSaysOtherwise) {
    EXPECT_EQ(load(withAsset(R"({"version":"2.1"})")).scene.drawnTriangleCount(), 2u);
    EXPECT_EQ(load(withAsset(R"({"version":"2.1","minVersion":"2.0"})")).scene.drawnTriangleCount(),
              2u);
    expectError(withAsset(R"({"version":"2.1","minVersion":"2.1"})"),
                "the file needs glTF 2.1 (asset.minVersion); idview reads glTF 2.0");
    expectError(withAsset(R"({"version":"2.0","minVersion":"x"})"),
                "asset.minVersion 'x' is not a glTF version");
}

TEST_F(GltfHandmade, GlbVersionOneIsRefusedInWords) {
    std::vector<unsigned char> file = glb(quadJson(), {});
    file[4] = 1;
    const std::string path = write("old.glb", file);
    try {
        scene::loadGltf(path);
        ADD_FAILURE() << "a version-1 GLB loaded";
    } catch (const ModelError& e) {
        EXPECT_EQ(std::string(e.what()), path +
                                             ": binary glTF 1.0 (GLB version 1) is not supported "
                                             "(idview reads glTF 2.0; convert it, e.g. with "
                                             "Cesium's gltf-pipeline)");
    }
}

// ---- handmade files: URIs stay inside the model's folder -------------------------------------

// The quad's buffer as a file would hold it (the layout of quadWithIndices<uint32_t>).
std::vector<unsigned char> quadBuffer() {
    Blob blob;
    blob.add(kQuad);
    blob.add(kQuadIndices);
    return blob.bytes;
}

// The quad document with its buffer at `uri` instead of inline.
std::string quadAt(const std::string& uri) {
    return quadJson([&](std::string& j) {
        size_t begin = j.find(R"("uri":"data:)") + 7;
        j.replace(begin, j.find('"', begin) - begin, uri);
    });
}

class GltfUris : public GltfHandmade {
  protected:
    // The model goes in <dir>/model/; a valid copy of its buffer lies outside, beside that
    // folder, and inside it: read, either would load.
    void SetUp() override {
        GltfHandmade::SetUp();
        fs::create_directories(dir_ / "model");
        write("outside.bin", quadBuffer());
        write("model/inside.bin", quadBuffer());
        write("model/in side.bin", quadBuffer());
    }
    std::string model(const std::string& json) { return write("model/model.gltf", json); }
    void expectRefused(const std::string& uri, const std::string& reason) {
        const std::string path = model(quadAt(uri));
        expectModelError([&] { scene::loadGltf(path); }, path, reason);
    }
};

TEST_F(GltfUris, InsideTheFolderAndDataUrisLoad) {
    for (const char* uri : {"inside.bin", "./inside.bin", "sub/../inside.bin", "in%20side.bin"})
        EXPECT_EQ(scene::loadGltf(model(quadAt(uri))).scene.drawnTriangleCount(), 2u) << uri;
    EXPECT_EQ(scene::loadGltf(model(quadJson())).scene.drawnTriangleCount(), 2u); // data: URI
}

// Every refusal comes before any file is looked at: the outside file exists and holds the
// right bytes, so a read would load it, and a lookup that failed would say "not found".
TEST_F(GltfUris, PathsOutsideTheFolderAreRefusedUnread) {
    const std::string rest = " (idview reads only files inside the model's folder, and data: URIs)";
    const std::string path = model(quadAt("../outside.bin"));
    try {
        scene::loadGltf(path);
        ADD_FAILURE() << "a buffer outside the model's folder was read";
    } catch (const ModelError& e) {
        EXPECT_EQ(std::string(e.what()),
                  path + ": uri '../outside.bin' points outside the model's folder" + rest);
    }
    // glTF URIs are percent-encoded; tinygltf decodes them, the message shows what it means.
    expectRefused("%2e%2e/outside.bin", "uri '../outside.bin' points outside the model's folder");
    expectRefused("%2E%2E%2Foutside.bin", "uri '../outside.bin' points outside");
    expectRefused("sub/../../outside.bin", "points outside the model's folder");
    expectRefused("../../../../../../etc/passwd", "points outside the model's folder");
    expectRefused("/etc/passwd", "uri '/etc/passwd' is an absolute path" + rest);
    expectRefused((dir_ / "outside.bin").string(), "is an absolute path");
    expectRefused("file:///etc/passwd", "uri 'file:///etc/passwd' is a URL, not a relative path");
    expectRefused("inside.bin%00/../../outside.bin", "contains a NUL byte");
}

TEST_F(GltfUris, ImagesAreRefusedToo) {
    write("outside.png", std::string("not read"));
    const std::string path = model(quadJson([](std::string& j) {
        replaceOnce(j, R"("asset")", R"("images":[{"uri":"../outside.png"}],"asset")");
    }));
    expectModelError([&] { scene::loadGltf(path); }, path,
                     "uri '../outside.png' points outside the model's folder");
}

// tinygltf looks for a file it does not find in the model's folder in the working directory
// as well; that second place is outside the folder, so the file is simply not found.
TEST_F(GltfUris, TheWorkingDirectoryIsNotSearched) {
    write("only-in-cwd.bin", quadBuffer());
    const std::string path = fs::absolute(model(quadAt("only-in-cwd.bin"))).string();
    const fs::path before = fs::current_path();
    fs::current_path(dir_);
    try {
        scene::loadGltf(path);
        ADD_FAILURE() << "the buffer was read from the working directory";
    } catch (const ModelError& e) {
        EXPECT_NE(std::string(e.what()).find("File not found : only-in-cwd.bin"), std::string::npos)
            << e.what();
    }
    fs::current_path(before);
}
