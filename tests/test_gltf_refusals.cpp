// test_gltf_refusals.cpp - handmade glTF files the loader must refuse in one line that says
// why: broken containers and JSON, out-of-range data, cycles, other versions, and URIs that
// leave the model's folder.
#include "gltf_handmade.h"

namespace {
// A suite of its own: gtest tells suites apart by name, and this file's fixture is a type of
// its own (gltf_handmade.h's helpers are file-local).
class GltfRefusals : public GltfHandmade {};
} // namespace

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

TEST_F(GltfRefusals, TruncatedAndWrongMagicGlb) {
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

TEST_F(GltfRefusals, BrokenJson) {
    std::string json = quadJson();
    expectError(json.substr(0, json.size() / 2), "");
    expectError("", "file is empty");
}

TEST_F(GltfRefusals, AccessorOutOfBounds) {
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

TEST_F(GltfRefusals, BufferViewOutOfBounds) {
    expectError(quadJson([](std::string& j) {
                    replaceOnce(j, R"("byteOffset":48,"byteLength":24)",
                                R"("byteOffset":56,"byteLength":24)");
                }),
                "bufferView 1");
}

TEST_F(GltfRefusals, IndexBeyondVertexCount) {
    Blob blob;
    std::vector<uint32_t> idx = {0, 1, 7};
    size_t p = blob.add(kQuad), i = blob.add(idx);
    expectError(gltfJson(blob, singleMesh(view(p, 48) + "," + view(i, 12),
                                          accessor(0, 5126, 4, "VEC3") + "," +
                                              accessor(1, 5125, 3, "SCALAR"),
                                          R"({"attributes":{"POSITION":0},"indices":1})")),
                "index 7 is >= the vertex count 4");
}

TEST_F(GltfRefusals, NanPosition) {
    Blob blob;
    std::vector<glm::vec3> pos = kQuad;
    pos[2].y = std::nanf("");
    blob.add(pos);
    expectError(gltfJson(blob, singleMesh(view(0, 48), accessor(0, 5126, 3, "VEC3"),
                                          R"({"attributes":{"POSITION":0}})")),
                "NaN or infinite POSITION");
}

TEST_F(GltfRefusals, NodeCycleAndSharedChild) {
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

TEST_F(GltfRefusals, EmptyScene) {
    expectError(quadJson([](std::string& j) {
                    replaceOnce(j, R"("nodes":[{"mesh":0}])", R"("nodes":[{}])");
                }),
                "empty scene");
}

TEST_F(GltfRefusals, DracoRequired) {
    expectError(quadJson([](std::string& j) {
                    replaceOnce(j, R"("asset")",
                                R"("extensionsUsed":["KHR_draco_mesh_compression"],)"
                                R"("extensionsRequired":["KHR_draco_mesh_compression"],"asset")");
                }),
                "requires the unsupported extension KHR_draco_mesh_compression");
}

// Found by fuzz_gltf: an accessor without bufferView and count 0 made the loader pass a null
// pointer to memset (undefined behaviour). Zero normals without data fall back to computed.
TEST_F(GltfRefusals, FuzzRegressionNormalsWithoutBufferView) {
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

// ---- handmade files: versions ----------------------------------------------------------------

std::string withAsset(const std::string& asset) {
    return quadJson([&](std::string& j) {
        replaceOnce(j, R"("asset":{"version":"2.0"})", R"("asset":)" + asset);
    });
}

TEST_F(GltfRefusals, OtherMajorVersionsAreRefusedInWords) {
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

TEST_F(GltfRefusals, MissingVersionIsRefused) {
    const std::string missing = "asset.version is missing or not a string: not a glTF 2.0 file";
    expectError(withAsset(R"({"generator":"x"})"), missing);
    expectError(withAsset(R"({"version":2.0})"), missing);
    expectError(
        quadJson([](std::string& j) { replaceOnce(j, R"("asset":{"version":"2.0"},)", ""); }),
        missing);
}

// glTF 2.0, 3.2: a newer minor version can be read (what is new in it is ignored) unless
// asset.minVersion says the file needs more than 2.0.
TEST_F(GltfRefusals, MinorVersionsAreCompatibleUnlessMinVersionSaysOtherwise) {
    EXPECT_EQ(load(withAsset(R"({"version":"2.1"})")).scene.drawnTriangleCount(), 2u);
    EXPECT_EQ(load(withAsset(R"({"version":"2.1","minVersion":"2.0"})")).scene.drawnTriangleCount(),
              2u);
    expectError(withAsset(R"({"version":"2.1","minVersion":"2.1"})"),
                "the file needs glTF 2.1 (asset.minVersion); idview reads glTF 2.0");
    expectError(withAsset(R"({"version":"2.0","minVersion":"x"})"),
                "asset.minVersion 'x' is not a glTF version");
}

TEST_F(GltfRefusals, GlbVersionOneIsRefusedInWords) {
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
