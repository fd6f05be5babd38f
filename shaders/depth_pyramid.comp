#version 460
// depth_pyramid.comp - up to PYRAMID_LEVELS_PER_PASS levels of the depth pyramid (shared.h
// PyramidHeader) in one dispatch, from the depth attachment (the first pass, level 0: the
// farthest depth of every sample of 2 x 2 pixels, the least, depth being reversed;
// IDV_PYRAMID_MSAA: a multisampled one) or
// from the last level of the pass before. Each workgroup reduces a tile of its first level
// down to one texel in shared memory; texels past an edge are left out, so a texel covers
// exactly its pixels and the occlusion test (cull.glsl) stays conservative.

#include "buffers.glsl"

layout(local_size_x = PYRAMID_GROUP, local_size_y = PYRAMID_GROUP) in;

#if IDV_PYRAMID_MSAA
layout(set = 0, binding = 0) uniform sampler2DMS depthImage;
#else
layout(set = 0, binding = 0) uniform sampler2D depthImage;
#endif

layout(push_constant, std430) uniform PyramidBlock {
    PyramidPush pyramid;
};

// Level-by-level halves of the tile: PYRAMID_GROUP texels a side, then half of that, ...
shared float tile[PYRAMID_GROUP][PYRAMID_GROUP];

// The farthest (least: depth is reversed) depth at input position `p` (a pixel, or a texel of
// the level below the pass's first), 1 past the edge: depths are 1 or less, so 1 never wins a
// min.
float sourceDepth(PyramidRef p, ivec2 at) {
    if (pyramid.level == 0u) {
        if (any(greaterThanEqual(uvec2(at), pyramid.extent))) return 1.0;
        float farthest = 1.0;
        for (int s = 0; s < int(pyramid.samples); ++s) {
#if IDV_PYRAMID_MSAA
            float depth = texelFetch(depthImage, at, s).r;
#else
            float depth = texelFetch(depthImage, at, 0).r;
#endif
            // The compute rasterizer's samples (the high word is their depth's bits).
            if (pyramid.rasterSamplesAddress != 0ul) {
                uint index = (uint(at.y) * pyramid.extent.x + uint(at.x)) * pyramid.samples + s;
                uint64_t computed = RasterSamplesRef(pyramid.rasterSamplesAddress).values[index];
                depth = max(depth, uintBitsToFloat(uint(computed >> 32)));
            }
            farthest = min(farthest, depth);
        }
        return farthest;
    }
    PyramidLevel below = p.header.level[pyramid.level - 1u];
    if (uint(at.x) >= below.width || uint(at.y) >= below.height) return 1.0;
    return p.depth[below.offset + uint(at.y) * below.width + uint(at.x)];
}

void store(PyramidRef p, uint level, uvec2 texel, float value) {
    PyramidLevel l = p.header.level[level];
    if (texel.x < l.width && texel.y < l.height)
        p.depth[l.offset + texel.y * l.width + texel.x] = value;
}

void main() {
    PyramidRef p = PyramidRef(pyramid.pyramidAddress);
    uint levels = p.header.levels;
    uvec2 lane = gl_LocalInvocationID.xy;
    // The first level: one texel per invocation, from 2 x 2 inputs.
    uvec2 texel = gl_WorkGroupID.xy * PYRAMID_GROUP + lane;
    ivec2 at = ivec2(texel * 2u);
    float farthest = min(min(sourceDepth(p, at), sourceDepth(p, at + ivec2(1, 0))),
                         min(sourceDepth(p, at + ivec2(0, 1)), sourceDepth(p, at + ivec2(1, 1))));
    store(p, pyramid.level, texel, farthest);
    tile[lane.y][lane.x] = farthest;
    // The next levels within the tile: PYRAMID_GROUP / 2, / 4, ... texels a side. Texels
    // past the level's edge hold 1 from the inputs past it, so they never win a min.
    uint size = PYRAMID_GROUP;
    for (uint level = pyramid.level + 1u; size > 1u; ++level) {
        barrier();
        size >>= 1;
        float value = 1.0;
        bool inLevel = all(lessThan(lane, uvec2(size)));
        if (inLevel) {
            uvec2 s = lane * 2u;
            value = min(min(tile[s.y][s.x], tile[s.y][s.x + 1u]),
                        min(tile[s.y + 1u][s.x], tile[s.y + 1u][s.x + 1u]));
        }
        barrier();
        if (inLevel) {
            tile[lane.y][lane.x] = value;
            if (level < levels) store(p, level, gl_WorkGroupID.xy * size + lane, value);
        }
    }
}
