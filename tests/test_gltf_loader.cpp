// test_gltf_loader.cpp - the glTF loader on real models, on the malformed files of the assimp
// test corpus, and on small handmade files that pin each feature and how objects are named;
// the errors, versions and URIs of handmade files: test_gltf_refusals.cpp.
#include "gltf_handmade.h"
#include "test_data.h"

// ---- real models -------------------------------------------------------------------------

// Numbers cross-checked with an independent python script over the GLB's JSON and binary
// chunk (node walk of the default scene, primitive count, union-find over index data).
TEST(GltfReal, TwoCylinderEngineStatistics) {
    REQUIRE_DATA(kCorpus);
    const std::string file = "2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    expectStats(file, PartMode::Primitives, {67, 29, 34, 115, 121496});
    expectStats(file, PartMode::Components, {67, 29, 1069, 1410, 121496});
}

TEST(GltfReal, BoxTexturedVariants) {
    REQUIRE_DATA(kCorpus);
    for (const char* file :
         {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Embedded/BoxTextured.gltf",
          "BoxTextured-glTF-Binary/BoxTextured.glb"}) {
        expectStats(file, PartMode::Primitives, {1, 1, 1, 1, 12});
        // The box's six faces share no vertices: six components.
        expectStats(file, PartMode::Components, {1, 1, 6, 6, 12});
    }
}

TEST(GltfReal, MaterialColourFromBaseColourFactor) {
    REQUIRE_DATA(kCorpus);
    LoadResult r = scene::loadGltf((kCorpus / "BoxTextured-glTF/BoxTextured.gltf").string());
    ASSERT_EQ(r.scene.objects.size(), 1u);
    const scene::Material& m = r.scene.materials[r.scene.objects[0].material];
    EXPECT_EQ(m.color, glm::vec4(1.0f)); // BoxTextured has no factor: the default white
}

// ---- the assimp corpus, malformed files included --------------------------------------------

// Every file either loads into a valid scene or fails with one line naming the file; never a
// crash, never another exception type.
TEST(GltfCorpus, EveryFileLoadsOrFailsWithOneLine) {
    REQUIRE_DATA(kCorpus);
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
    REQUIRE_DATA(kCorpus);
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
    REQUIRE_DATA(kCorpus.parent_path() / "glTF");
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
