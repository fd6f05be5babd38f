// pick.h - what the CPU learns from a frame's pick: the nearest part at the picked pixel and
// its depth, decoded from the 64-bit value the fragment shaders atomicMin'ed (see PickData);
// from its part set queries, the unique parts inside pixel rectangles (id_passes.h); and from
// its composition, the tiles the hovered part covers.
#pragma once

#include <bit>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scene/part_set.h"
#include "shared.h"

namespace render {

struct PickReading {
    uint64_t frame = 0;           // FrameSlots frame number the pick was rendered in
    glm::uvec2 pixel{0};          // framebuffer pixel, top-left origin
    std::optional<uint32_t> part; // unique part ID; nullopt: background
    float depth = 0.0f;           // framebuffer depth of the nearest fragment (1 near, 0 far)
};

inline PickReading decodePick(uint64_t value, uint64_t frame, glm::uvec2 pixel) {
    PickReading reading{frame, pixel, std::nullopt, 0.0f};
    if (value == gpu::PICK_NONE) return reading;
    reading.part = static_cast<uint32_t>(value & 0xFFFFFFFFu);
    // The depth bits are stored inverted (shared.h pickKey): nearer, greater depth, less key.
    reading.depth = std::bit_cast<float>(~static_cast<uint32_t>(value >> 32));
    return reading;
}

// An inclusive rectangle of framebuffer pixels, top-left origin; clamped to the image.
struct PartSetQuery {
    glm::uvec2 min{0}, max{0};
    bool operator==(const PartSetQuery&) const = default;
};

// The rectangle spanned by two corners given in any order.
inline PartSetQuery spanning(glm::uvec2 a, glm::uvec2 b) {
    return {glm::min(a, b), glm::max(a, b)};
}

// The tiles (gpu::ID_PASS_TILE pixels square) a whole composition found holding the hovered
// part or pixel (gpu::HoverBox): a step of the blink after it composes only these again.
struct HoveredTiles {
    uint64_t frame = 0;     // FrameSlots frame number of the composition
    glm::uvec2 first{0};    // the first tile
    glm::uvec2 count{0, 0}; // tiles across and down; 0 when none holds them
};

inline HoveredTiles decodeHoverBox(const gpu::HoverBox& box, uint64_t frame) {
    HoveredTiles tiles{frame, box.tileMin, glm::uvec2(0)};
    if (glm::all(glm::lessThanEqual(box.tileMin, box.tileMax)))
        tiles.count = box.tileMax - box.tileMin + 1u;
    else
        tiles.first = glm::uvec2(0);
    return tiles;
}

struct PartSetReading {
    uint64_t frame = 0; // FrameSlots frame number the sets were taken in
    std::vector<PartSetQuery> queries;
    // Per query: the parts found, and their count as the GPU counted it.
    std::vector<scene::PartSet> sets;
    std::vector<uint32_t> counts;
};

} // namespace render
