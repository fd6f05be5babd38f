// cad_cache.h - CAD tessellations kept on disk, so that a file opened again skips Open
// CASCADE: one entry per file path and tessellation settings in util::cacheFolder()
// (util/cache_file.h), holding what loadCad returned (the scene with its levels of detail, the
// warnings, the deflection used, the face counts, the B-rep shapes). An entry is used only when its
// magic, format version, key (the path, the file's size and content hash, the deflections and
// levels asked for) and the checksum of its payload all match and the payload decodes to a valid
// scene; anything else is a miss, and the entry is written anew (to a temporary file renamed over
// it, so that a crash never leaves half an entry under the entry's name). This header stays free of
// Open CASCADE types.
//
// Entry layout: "idviewTC" (8 bytes), format version (u32), key size (u64) and key, payload
// size (u64), payload checksum (u64, hash64), payload (the scene, the load's figures, and the
// B-rep's table: per geometry its faces and where its shape's bytes lie, with their hash), then
// the shapes' bytes one after the other. Host byte order. A hit reads the head and the payload
// only: each shape is read back from the entry when a query first asks for it.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "scene/cad/cad_loader.h"

namespace scene {

// Bumped whenever the entry layout or what the loader puts in a scene changes.
// 7: faces that did not triangulate keep their (empty) parts; STEP files split and read by
// worker processes, healing in the key; each shape's bytes apart, read when asked. 6: levels of
// detail chosen by the policy meshes share (lod_policy.h), among tessellations at more deflections;
// 5: the B-rep kept (brep_shapes.h); 4: placements in double; 3: IGES gaps sewn, edge points
// shared.
constexpr uint32_t kCadCacheVersion = 7;

struct CadCacheKey {
    std::string path; // absolute, symbolic links resolved
    uint64_t fileSize = 0;
    uint64_t contentHash = 0; // hash64 of the file's bytes
    double deflection = 0.0;  // as asked (0: automatic)
    double angularDeflection = 0.0;
    uint32_t levels = 1;
    Healing healing = Healing::On;
    bool operator==(const CadCacheKey&) const = default;
};

// Reads and hashes the file; nullopt where it cannot be read (loadCad then says why).
std::optional<CadCacheKey> cadCacheKey(const std::string& path, const CadOptions& options,
                                       uint32_t levels);

// The entry's file in `folder`: named by a hash of the path and settings, so that a changed
// file replaces its own entry.
std::filesystem::path cadCacheEntry(const std::filesystem::path& folder, const CadCacheKey& key);

// The load the entry holds, or nullopt with `why` ("no entry", "truncated", "checksum
// mismatch", ...) when it is missing or not to be trusted.
std::optional<CadLoadResult> readCadCache(const std::filesystem::path& entry,
                                          const CadCacheKey& key, std::string& why);

// Writes `result` as the entry; returns "" or why it could not. Once written, the scene's
// B-rep reads its shapes back from the entry, and the bytes it held in memory go.
std::string writeCadCache(const std::filesystem::path& entry, const CadCacheKey& key,
                          CadLoadResult& result);

// loadCad through the cache: a valid entry is returned (CadLoadResult::cache "hit", no
// progress reported, the --max-triangles limit still applied); otherwise the file is loaded
// ("miss", cacheNote saying why) and its entry written, a failure to write being a warning.
CadLoadResult loadCadCached(const std::string& path, const CadOptions& options,
                            const CadProgress& progress = {}, uint32_t levels = 1,
                            const std::atomic<bool>* cancel = nullptr,
                            const CadPartialSink& partial = {});

} // namespace scene
