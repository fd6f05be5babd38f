#version 460
// part_set.comp - the unique parts inside a pixel rectangle of the resolved ID image (or, for
// culling with MSAA, of every sample), as a bitset plus their count: box selection and the
// visible parts. One invocation per pixel.
// Neighbouring pixels mostly show the same part, so the invocations of a subgroup first agree
// on their distinct parts (a loop that retires one part per turn) and one invocation per part
// goes to memory: a bit already set skips the atomic, so a part covering many pixels costs
// few atomics.
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_buffer_reference : require
#extension GL_KHR_shader_subgroup_ballot : require
// Culling's visible parts with MSAA (IDV_PART_SET_SAMPLES): every sample of the multisampled
// IDs rather than the resolved sample 0, so that a part showing in any sample counts.
#ifndef IDV_PART_SET_SAMPLES
#define IDV_PART_SET_SAMPLES 0
#endif
#if IDV_PART_SET_SAMPLES
#extension GL_EXT_samplerless_texture_functions : require
#endif
// Culling's visible parts need the bits alone (IDV_PART_SET_COUNT 0): an atomic whose old
// value nobody waits for, rather than an atomic and a count that wait for it.
#ifndef IDV_PART_SET_COUNT
#define IDV_PART_SET_COUNT 1
#endif

#include "shared.h"

layout(local_size_x = ID_PASS_TILE, local_size_y = ID_PASS_TILE) in;

#if IDV_PART_SET_SAMPLES
layout(set = 0, binding = 0) uniform utexture2DMS ids;
// A sample whose depth is the clear value (0, reversed depth) was covered by no triangle: on
// the compute clear path its ID is whatever the image held (render/resolve.h).
layout(set = 0, binding = 1) uniform texture2DMS depth;
#else
layout(set = 0, binding = 0, r32ui) uniform readonly uimage2D ids;
#endif

layout(push_constant, std430) uniform PartSetBlock {
    PartSetPush query;
};

layout(buffer_reference, std430, buffer_reference_align = 16) buffer Result {
    PartSetResult head;
    uint words[];
};

// Offers `id` (BACKGROUND_ID: nothing) of each invocation to the set.
void add(uint id) {
    bool pending = id != BACKGROUND_ID && (id >> 5) < query.words;
    while (pending) {
        // The lowest pending invocation's part: every invocation showing it is done with it.
        const uint part = subgroupBroadcastFirst(id);
        if (id != part) continue;
        pending = false;
        if (!subgroupElect()) continue;
        const uint bit = 1u << (part & 31u);
        Result result = Result(query.resultAddress);
        // A part over many pixels would send every subgroup's atomic to one word: a bit
        // already set is left alone.
        if ((result.words[part >> 5] & bit) != 0u) continue;
#if IDV_PART_SET_COUNT
        // Of all invocations that reach here for one part, exactly one sees the bit unset
        // before its atomic: it counts.
        if ((atomicOr(result.words[part >> 5], bit) & bit) == 0u) atomicAdd(result.head.count, 1u);
#else
        atomicOr(result.words[part >> 5], bit);
#endif
    }
}

void main() {
    const uvec2 p = query.rectMin + gl_GlobalInvocationID.xy;
    const bool inside = all(lessThanEqual(p, query.rectMax));
#if IDV_PART_SET_SAMPLES
    // A sample showing the part of the sample before it adds nothing new.
    uint last = BACKGROUND_ID;
    for (uint s = 0u; s < query.samples; ++s) {
        const bool covered = inside && texelFetch(depth, ivec2(p), int(s)).r != 0.0;
        const uint id = covered ? texelFetch(ids, ivec2(p), int(s)).r : BACKGROUND_ID;
        add(id == last ? BACKGROUND_ID : id);
        last = id;
    }
#else
    add(inside ? imageLoad(ids, ivec2(p)).r : BACKGROUND_ID);
#endif
}
