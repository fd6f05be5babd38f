// fuzz_gltf.cpp - libFuzzer entry for the glTF loader: any input must either load into a
// scene that passes validate() or fail with a one-line ModelError; anything else aborts.
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "scene/gltf/gltf_loader.h"

namespace {

// External URIs resolve inside a folder that does not exist, so inputs never read real files.
constexpr const char* kName = "/nonexistent-idview-fuzz/input.gltf";

[[noreturn]] void fail(const char* what, const char* detail) {
    std::fprintf(stderr, "fuzz_gltf: %s: %s\n", what, detail);
    std::abort();
}

void loadBoth(std::span<const unsigned char> bytes, scene::PartMode mode) {
    try {
        scene::LoadResult result = scene::loadGltfFromMemory(bytes, kName, {mode});
        scene::validate(result.scene);
    } catch (const scene::ModelError& e) {
        if (std::strchr(e.what(), '\n') || std::strncmp(e.what(), kName, std::strlen(kName)) != 0)
            fail("ModelError breaks the one-line contract", e.what());
    } catch (const std::exception& e) {
        fail("unexpected exception", e.what());
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::span<const unsigned char> bytes(data, size);
    loadBoth(bytes, scene::PartMode::Primitives);
    loadBoth(bytes, scene::PartMode::Components);
    return 0;
}
