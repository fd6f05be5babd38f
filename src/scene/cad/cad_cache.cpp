// cad_cache.cpp - the CAD tessellation cache (cad_cache.h): keys, entries, and loadCad
// through them.
#include "scene/cad/cad_cache.h"

#include <chrono>
#include <cstdio>
#include <fstream>

#include "scene/cad/brep_shapes.h"
#include "scene/cad/scene_codec.h"
#include "util/cache_file.h"
#include "util/hash64.h"

namespace scene {

namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'i', 'd', 'v', 'i', 'e', 'w', 'T', 'C'};

// The key's fields and the load's, in the order they are stored (`io`: a ByteWriter or a
// ByteReader, see scene_codec.h).
template <typename IO, typename K>
void keyFields(IO& io, K& key) {
    fields(io, key.path, key.fileSize, key.contentHash, key.deflection, key.angularDeflection,
           key.levels);
}

template <typename IO, typename R>
void resultFields(IO& io, R& r) {
    io.records(r.warnings, [](auto& io, auto& w) { io(w); });
    fields(io, r.deflection, r.faces, r.facesFailed);
}

CadCacheKey getKey(ByteReader& in) {
    CadCacheKey key;
    keyFields(in, key);
    return key;
}

// Every full-detail geometry has its shape, with a face for each of its parts' face numbers.
void checkBrepMatches(const Scene& scene) {
    if (scene.brep->geometryCount() != scene.geometries.size())
        throw std::runtime_error("B-rep: another geometry count");
    for (uint32_t g = 0; g < scene.geometries.size(); ++g) {
        const Geometry& geometry = scene.geometries[g];
        if (scene.brep->has(g) != (geometry.level == 0))
            throw std::runtime_error("B-rep: a shape for a level of detail, or none for a model");
        for (uint32_t face : geometry.partFaces)
            if (geometry.level == 0 && face >= scene.brep->faceCount(g))
                throw std::runtime_error("B-rep: a face missing");
    }
}

CadLoadResult getResult(ByteReader& in) {
    CadLoadResult r;
    r.scene = decodeScene(in);
    resultFields(in, r);
    r.scene.brep = decodeBrep(in.getBytes());
    checkBrepMatches(r.scene);
    if (!in.done()) throw std::runtime_error("bytes after the load");
    return r;
}

std::optional<CadLoadResult> parseEntry(const std::string& bytes, const CadCacheKey& key,
                                        std::string& why) {
    ByteReader in(bytes);
    try {
        char magic[sizeof kMagic];
        for (char& c : magic) c = in.get<char>();
        if (!std::equal(std::begin(magic), std::end(magic), std::begin(kMagic))) {
            why = "not an idview cache entry";
            return std::nullopt;
        }
        if (const uint32_t version = in.get<uint32_t>(); version != kCadCacheVersion) {
            why = "format version " + std::to_string(version) + ", not " +
                  std::to_string(kCadCacheVersion);
            return std::nullopt;
        }
        ByteReader keyIn(in.getBytes());
        if (!(getKey(keyIn) == key) || !keyIn.done()) {
            why = "stale (the file or the settings changed)";
            return std::nullopt;
        }
        const std::string_view payload = in.getBytes();
        const uint64_t checksum = in.get<uint64_t>();
        if (!in.done()) throw std::runtime_error("bytes after the checksum");
        if (util::hash64(payload.data(), payload.size()) != checksum) {
            why = "checksum mismatch";
            return std::nullopt;
        }
        ByteReader payloadIn(payload);
        return getResult(payloadIn);
    } catch (const std::exception& e) {
        why = std::string("damaged (") + e.what() + ")";
        return std::nullopt;
    }
}

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

} // namespace

std::optional<CadCacheKey> cadCacheKey(const std::string& path, const CadOptions& options,
                                       uint32_t levels) {
    std::error_code ec;
    CadCacheKey key;
    key.path = fs::weakly_canonical(fs::absolute(path, ec), ec).string();
    if (ec) return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    // A megabyte at a time, each chunk's hash seeding the next.
    std::string chunk(size_t(1) << 20, '\0');
    uint64_t hash = util::kHashSeed;
    while (in) {
        in.read(chunk.data(), std::streamsize(chunk.size()));
        const auto got = size_t(in.gcount());
        if (got == 0) break;
        hash = util::hash64(chunk.data(), got, hash);
        key.fileSize += got;
    }
    if (in.bad()) return std::nullopt;
    key.contentHash = hash;
    key.deflection = options.deflection;
    key.angularDeflection = options.angularDeflection;
    key.levels = levels;
    return key;
}

fs::path cadCacheEntry(const fs::path& folder, const CadCacheKey& key) {
    ByteWriter name;
    name.putString(key.path);
    name.put(key.deflection);
    name.put(key.angularDeflection);
    name.put(key.levels);
    char hex[32];
    std::snprintf(
        hex, sizeof hex, "%016llx.tess",
        static_cast<unsigned long long>(util::hash64(name.bytes().data(), name.bytes().size())));
    return folder / hex;
}

std::optional<CadLoadResult> readCadCache(const fs::path& entry, const CadCacheKey& key,
                                          std::string& why) {
    std::error_code ec;
    if (!fs::exists(entry, ec)) {
        why = "no entry";
        return std::nullopt;
    }
    const std::optional<std::string> bytes = util::readWholeFile(entry);
    if (!bytes) {
        why = "entry unreadable";
        return std::nullopt;
    }
    return parseEntry(*bytes, key, why);
}

std::string writeCadCache(const fs::path& entry, const CadCacheKey& key,
                          const CadLoadResult& result) {
    ByteWriter keyBytes, payload, head, tail;
    keyFields(keyBytes, key);
    encodeScene(result.scene, payload);
    resultFields(payload, result);
    if (!result.scene.brep) return "the load kept no B-rep";
    payload.putString(encodeBrep(*result.scene.brep));
    for (char c : kMagic) head.put(c);
    head.put(kCadCacheVersion);
    head.putString(keyBytes.bytes());
    head.put(uint64_t(payload.bytes().size())); // the payload's length prefix
    tail.put(util::hash64(payload.bytes().data(), payload.bytes().size()));

    return util::writeFileAtomically(entry, {head.bytes(), payload.bytes(), tail.bytes()});
}

CadLoadResult loadCadCached(const std::string& path, const CadOptions& options,
                            const CadProgress& progress, uint32_t levels,
                            const std::atomic<bool>* cancel) {
    const auto start = std::chrono::steady_clock::now();
    const fs::path folder = util::cacheFolder();
    const std::optional<CadCacheKey> key =
        folder.empty() ? std::nullopt : cadCacheKey(path, options, levels);
    if (!key) {
        CadLoadResult result = loadCad(path, options, progress, levels, cancel);
        result.cacheNote = folder.empty() ? "no cache folder (neither XDG_CACHE_HOME nor HOME)"
                                          : "file not hashed";
        return result;
    }
    const fs::path entry = cadCacheEntry(folder, *key);
    std::string why;
    if (std::optional<CadLoadResult> hit = readCadCache(entry, *key, why)) {
        // Levels are coarser: full detail's triangles are what the limit counts.
        uint64_t fullDetail = 0;
        for (const Geometry& g : hit->scene.geometries)
            if (g.level == 0) fullDetail += g.triangleCount;
        if (fullDetail > options.maxTriangles)
            throw ModelError(
                path + ": " +
                triangleLimitReason(fullDetail, options.maxTriangles, hit->deflection));
        hit->cache = "hit";
        hit->cacheMs = msSince(start);
        return std::move(*hit);
    }
    CadLoadResult result = loadCad(path, options, progress, levels, cancel);
    result.cache = "miss";
    result.cacheNote = why;
    const auto writeStart = std::chrono::steady_clock::now();
    if (const std::string error = writeCadCache(entry, *key, result); !error.empty())
        result.warnings.push_back("tessellation cache not written: " + error);
    result.cacheMs = msSince(writeStart);
    return result;
}

} // namespace scene
