#version 460
// part_set.comp - the unique parts inside a pixel rectangle of the resolved ID image, as a
// bitset plus their count: box selection and the visible parts. One invocation per pixel.
// Neighbouring pixels mostly show the same part, so the invocations of a subgroup first agree
// on their distinct parts (a loop that retires one part per turn) and one invocation per part
// goes to memory: a bit already set skips the atomic, so a part covering many pixels costs
// few atomics.
#extension GL_KHR_shader_subgroup_ballot : require

#include "buffers.glsl"

layout(local_size_x = ID_PASS_TILE, local_size_y = ID_PASS_TILE) in;

layout(set = 0, binding = 0, r32ui) uniform readonly uimage2D ids;

layout(push_constant, std430) uniform PartSetBlock {
    PartSetPush query;
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
        PartSetRef result = PartSetRef(query.resultAddress);
        // A part over many pixels would send every subgroup's atomic to one word: a bit
        // already set is left alone.
        if ((result.words[part >> 5] & bit) != 0u) continue;
        // Of all invocations that reach here for one part, exactly one sees the bit unset
        // before its atomic: it counts.
        if ((atomicOr(result.words[part >> 5], bit) & bit) == 0u) atomicAdd(result.head.count, 1u);
    }
}

void main() {
    const uvec2 p = query.rectMin + gl_GlobalInvocationID.xy;
    const bool inside = all(lessThanEqual(p, query.rectMax));
    add(inside ? imageLoad(ids, ivec2(p)).r : BACKGROUND_ID);
}
