#version 460
// resolve.comp - the compute clear path's end of the scene pass: the background's colour and
// ID where no triangle covered a sample, and with MSAA the resolve of colour (average) and
// IDs (sample 0) into the single-sample images every later pass reads. shared_id_passes.h
// has the rules; render/resolve.h records it.
#extension GL_EXT_samplerless_texture_functions : require

#include "buffers.glsl"

layout(local_size_x = ID_PASS_TILE, local_size_y = ID_PASS_TILE) in;

#if IDV_RESOLVE_MSAA
layout(set = 0, binding = 0) uniform texture2DMS depth;
layout(set = 0, binding = 1) uniform utexture2DMS sampleIds;
layout(set = 0, binding = 2) uniform texture2DMS sampleColors;
#else
layout(set = 0, binding = 0) uniform texture2D depth;
#endif
layout(set = 0, binding = 3, r32ui) uniform writeonly uimage2D ids;
layout(set = 0, binding = 4, rgba8) uniform writeonly image2D color;

layout(push_constant, std430) uniform ResolveBlock {
    ResolvePush resolve;
};

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), resolve.extent))) return;
    const bool keepColor = (resolve.flags & RESOLVE_KEEP_COLOR) != 0u;
    const bool noIds = (resolve.flags & RESOLVE_NO_IDS) != 0u;
#if IDV_RESOLVE_MSAA
    vec4 sum = vec4(0.0);
    uint id = BACKGROUND_ID;
    for (int s = 0; s < int(resolve.samples); ++s) {
        // Reversed depth: the clear value 0 is the far plane, which the GREATER test never
        // lets a fragment write.
        const bool covered = texelFetch(depth, p, s).r != 0.0;
        sum += covered || keepColor ? texelFetch(sampleColors, p, s) : resolve.background;
        if (s == 0 && covered && !noIds) id = texelFetch(sampleIds, p, 0).r;
    }
    imageStore(color, p, sum / float(resolve.samples));
    imageStore(ids, p, uvec4(id));
#else
    const bool covered = texelFetch(depth, p, 0).r != 0.0;
    if (!covered || noIds) imageStore(ids, p, uvec4(BACKGROUND_ID));
    if (!covered && !keepColor) imageStore(color, p, resolve.background);
#endif
}
