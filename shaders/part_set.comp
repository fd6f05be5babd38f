#version 460
// part_set.comp - the unique parts inside a pixel rectangle of the resolved ID image, as a
// bitset plus their count: box selection and the visible parts. One invocation per pixel; a
// bit already seen skips the atomic, so a part covering many pixels costs few atomics.
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_buffer_reference : require

#include "shared.h"

layout(local_size_x = ID_PASS_TILE, local_size_y = ID_PASS_TILE) in;

layout(set = 0, binding = 0, r32ui) uniform readonly uimage2D ids;

layout(push_constant, std430) uniform PartSetBlock {
    PartSetPush query;
};

layout(buffer_reference, std430, buffer_reference_align = 16) buffer Result {
    PartSetResult head;
    uint words[];
};

void main() {
    const uvec2 p = query.rectMin + gl_GlobalInvocationID.xy;
    if (any(greaterThan(p, query.rectMax))) return;
    const uint id = imageLoad(ids, ivec2(p)).r;
    const uint word = id >> 5;
    if (id == BACKGROUND_ID || word >= query.words) return;
    const uint bit = 1u << (id & 31u);
    Result result = Result(query.resultAddress);
    if ((result.words[word] & bit) != 0u) return;
    // Of all pixels of one part, exactly one sees the bit unset before its atomic: it counts.
    if ((atomicOr(result.words[word], bit) & bit) == 0u) atomicAdd(result.head.count, 1u);
}
