// out_of_memory.h - running out of host memory as a refusal in words: one line that names what
// did not fit ("FILE: out of memory making 16 copies (36,160 objects)") where std::bad_alloc
// would say "std::bad_alloc". The steps wrapped are all or nothing, so what was shown stays.
#pragma once

#include <cstdint>
#include <new>
#include <stdexcept>
#include <string>

#include "scene/scene.h"

namespace app {

struct OutOfMemory : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// work(), or OutOfMemory("<subject>: out of memory <doing>") where it throws std::bad_alloc
// (on any thread whose work it waits for: those hand their exceptions on).
template <typename Work>
decltype(auto) refuseOutOfMemory(const std::string& subject, const std::string& doing,
                                 Work&& work) {
    try {
        return work();
    } catch (const std::bad_alloc&) {
        throw OutOfMemory(subject + ": out of memory " + doing);
    }
}

// 2260 as "2,260".
std::string grouped(uint64_t count);

// What each step of opening a scene was doing, for the line: "loading it (41.2 MB)",
// "building 4 levels of detail of 22 geometries", "making 16 copies (36,160 objects)",
// "uploading 36,160 objects of 22 geometries (155,944 triangles)".
std::string loadingWhat(const std::string& path);
std::string levelsWhat(uint32_t levels, const scene::Scene& scene);
std::string copiesWhat(uint32_t copies, const scene::Scene& scene);
std::string uploadWhat(const scene::Scene& scene);

} // namespace app
