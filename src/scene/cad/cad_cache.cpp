// cad_cache.cpp - the CAD tessellation cache (cad_cache.h): keys, entries, and loadCad
// through them.
#include "scene/cad/cad_cache.h"

#include <chrono>
#include <cstdio>
#include <fcntl.h>
#include <fstream>
#include <unistd.h>

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
           key.levels, key.healing);
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
        if (geometry.level != 0 && scene.brep->has(g))
            throw std::runtime_error("B-rep: a shape for a level of detail");
        for (uint32_t face : geometry.partFaces)
            if (geometry.level == 0 && face != kNoFace && face >= scene.brep->faceCount(g))
                throw std::runtime_error("B-rep: a face missing");
    }
}

// The shapes' table: per geometry whether it has one, its faces, and where its bytes lie in
// the blobs after the payload, with their hash.
template <typename IO, typename S>
void storedFields(IO& io, S& s) {
    fields(io, s.present, s.faces, s.offset, s.size, s.hash);
}

// The shapes of an entry, read from its file (kept open: a newer entry renamed over it leaves
// this one readable) when a query first asks for one.
class EntryShapes : public EncodedShapeFile {
  public:
    EntryShapes(int fd, uint64_t blobs) : fd_(fd), blobs_(blobs) {}
    ~EntryShapes() override { ::close(fd_); }
    std::string read(uint64_t offset, uint64_t size, uint64_t hash) const override {
        std::string bytes(size, '\0');
        if (::pread(fd_, bytes.data(), size, off_t(blobs_ + offset)) != ssize_t(size))
            throw std::runtime_error("the tessellation cache's entry can no longer be read");
        if (util::hash64(bytes.data(), bytes.size()) != hash)
            throw std::runtime_error("the tessellation cache's entry changed under the scene");
        return bytes;
    }

  private:
    int fd_;
    uint64_t blobs_;
};

CadLoadResult getResult(ByteReader& in, int fd, uint64_t blobs, uint64_t fileSize) {
    CadLoadResult r;
    r.scene = decodeScene(in);
    resultFields(in, r);
    std::vector<BrepShapes::Stored> stored;
    in.records(stored, [](auto& io, auto& s) { storedFields(io, s); });
    if (!in.done()) throw std::runtime_error("bytes after the load");
    // The shapes' bytes are checked when read; their extent now, so that a cut entry is a miss.
    uint64_t end = blobs;
    for (const BrepShapes::Stored& s : stored)
        if (s.present) {
            if (blobs > fileSize || s.offset > fileSize - blobs ||
                s.size > fileSize - blobs - s.offset)
                throw std::runtime_error("shapes cut off");
            end = std::max(end, blobs + s.offset + s.size);
        }
    if (end != fileSize) throw std::runtime_error("shapes cut off");
    r.scene.brep = std::make_shared<const BrepShapes>(
        std::move(stored), std::make_shared<const EntryShapes>(::dup(fd), blobs));
    checkBrepMatches(r.scene);
    return r;
}

// Reads exactly `size` bytes at `offset`, or throws.
std::string readAt(int fd, uint64_t offset, uint64_t size) {
    std::string bytes(size, '\0');
    if (::pread(fd, bytes.data(), size, off_t(offset)) != ssize_t(size))
        throw std::runtime_error("truncated");
    return bytes;
}

// The head: magic, version, key, the payload's size and checksum; the rest is read after.
std::optional<CadLoadResult> parseEntry(int fd, uint64_t fileSize, const CadCacheKey& key,
                                        std::string& why) {
    try {
        // The head is small: magic, version, key (a path and a few numbers), two sizes.
        const std::string head = readAt(fd, 0, std::min<uint64_t>(fileSize, 1 << 16));
        ByteReader in(head);
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
        const uint64_t size = in.get<uint64_t>(), checksum = in.get<uint64_t>();
        const uint64_t start = head.size() - in.left();
        if (size > fileSize - start) throw std::runtime_error("payload past the end");
        const std::string payload = readAt(fd, start, size);
        if (util::hash64(payload.data(), payload.size()) != checksum) {
            why = "checksum mismatch";
            return std::nullopt;
        }
        ByteReader payloadIn(payload);
        return getResult(payloadIn, fd, start + size, fileSize);
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
    key.healing = options.healing;
    return key;
}

fs::path cadCacheEntry(const fs::path& folder, const CadCacheKey& key) {
    ByteWriter name;
    name.putString(key.path);
    name.put(key.deflection);
    name.put(key.angularDeflection);
    name.put(key.levels);
    name.put(key.healing);
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
    const int fd = ::open(entry.c_str(), O_RDONLY | O_CLOEXEC);
    const uintmax_t size = fs::file_size(entry, ec);
    if (fd < 0 || ec) {
        if (fd >= 0) ::close(fd);
        why = "entry unreadable";
        return std::nullopt;
    }
    std::optional<CadLoadResult> result = parseEntry(fd, size, key, why);
    ::close(fd); // the shapes keep a descriptor of their own
    return result;
}

std::string writeCadCache(const fs::path& entry, const CadCacheKey& key, CadLoadResult& result) {
    if (!result.scene.brep) return "the load kept no B-rep";
    const BrepShapes& brep = *result.scene.brep;
    ByteWriter keyBytes, payload, head;
    keyFields(keyBytes, key);
    encodeScene(result.scene, payload);
    resultFields(payload, result);
    std::vector<std::string> blobs(brep.geometryCount());
    std::vector<BrepShapes::Stored> table(brep.geometryCount());
    uint64_t offset = 0;
    for (uint32_t g = 0; g < brep.geometryCount(); ++g) {
        if (!brep.has(g)) continue;
        blobs[g] = brep.encoded(g);
        table[g] = {brep.faceCount(g),
                    {},
                    offset,
                    blobs[g].size(),
                    util::hash64(blobs[g].data(), blobs[g].size()),
                    true};
        offset += blobs[g].size();
    }
    payload.records(table, [](auto& io, const auto& s) { storedFields(io, s); });
    for (char c : kMagic) head.put(c);
    head.put(kCadCacheVersion);
    head.putString(keyBytes.bytes());
    head.put(uint64_t(payload.bytes().size()));
    head.put(util::hash64(payload.bytes().data(), payload.bytes().size()));
    std::vector<std::string_view> parts{head.bytes(), payload.bytes()};
    for (const std::string& blob : blobs) parts.push_back(blob);
    if (std::string error = util::writeFileAtomically(entry, parts); !error.empty()) return error;
    // From now on the shapes are read back from the entry: the bytes held here go.
    const int fd = ::open(entry.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return {};
    result.scene.brep = std::make_shared<const BrepShapes>(
        std::move(table),
        std::make_shared<const EntryShapes>(fd, head.bytes().size() + payload.bytes().size()));
    return {};
}

CadLoadResult loadCadCached(const std::string& path, const CadOptions& options,
                            const CadProgress& progress, uint32_t levels,
                            const std::atomic<bool>* cancel, const CadPartialSink& partial) {
    const auto start = std::chrono::steady_clock::now();
    const fs::path folder = util::cacheFolder();
    const std::optional<CadCacheKey> key =
        folder.empty() ? std::nullopt : cadCacheKey(path, options, levels);
    if (!key) {
        CadLoadResult result = loadCad(path, options, progress, levels, cancel, partial);
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
    CadLoadResult result = loadCad(path, options, progress, levels, cancel, partial);
    result.cache = "miss";
    result.cacheNote = why;
    const auto writeStart = std::chrono::steady_clock::now();
    if (const std::string error = writeCadCache(entry, *key, result); !error.empty())
        result.warnings.push_back("tessellation cache not written: " + error);
    result.cacheMs = msSince(writeStart);
    return result;
}

} // namespace scene
