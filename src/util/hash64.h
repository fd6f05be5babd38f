// hash64.h - a small 64-bit hash of bytes, for the CAD cache's file contents, names and
// checksums (scene/cad/cad_cache.h) and the pipeline cache (render/pipeline_file.h). Not for
// adversaries: it tells changed or damaged data from the data it was computed on. Plain C++.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace util {

constexpr uint64_t kHashSeed = 0xcbf29ce484222325ull; // FNV-1a's offset basis
constexpr uint64_t kHashPrime = 0x100000001b3ull;     // FNV-1a's 64-bit prime

// FNV-1a's xor-then-multiply, but a 64-bit word per step, so that hashing a file costs a
// small fraction of reading it; a multiply only carries bits upwards, so each step shifts the
// high bits back down (without that, flipping the top bit of two words would cancel out).
// The bytes after the last whole word go in one at a time; a last mix spreads every bit.
inline uint64_t hash64(const void* data, size_t size, uint64_t seed = kHashSeed) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    uint64_t h = seed ^ (uint64_t(size) * kHashPrime);
    size_t i = 0;
    for (; i + 8 <= size; i += 8) {
        uint64_t word;
        std::memcpy(&word, bytes + i, 8);
        h = (h ^ word) * kHashPrime;
        h ^= h >> 29;
    }
    for (; i < size; ++i) h = (h ^ bytes[i]) * kHashPrime;
    h ^= h >> 32;
    h *= kHashPrime;
    h ^= h >> 29;
    return h;
}

} // namespace util
