#version 460
// depth_pyramid.comp - one level of the depth pyramid (shared.h PyramidHeader), a texel per
// invocation: level 0 takes the farthest depth of every sample of its 2 x 2 pixels of the depth
// attachment (IDV_PYRAMID_MSAA: a multisampled one), a higher level the farthest of 2 x 2
// texels of the level below. Pixels and texels past the edge are left out, so a texel covers
// exactly its pixels and the occlusion test (cull.glsl) stays conservative.
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_buffer_reference : require

#include "shared.h"

layout(local_size_x = PYRAMID_GROUP, local_size_y = PYRAMID_GROUP) in;

#if IDV_PYRAMID_MSAA
layout(set = 0, binding = 0) uniform sampler2DMS depthImage;
#else
layout(set = 0, binding = 0) uniform sampler2D depthImage;
#endif

layout(push_constant, std430) uniform PyramidBlock {
    PyramidPush pyramid;
};

layout(buffer_reference, std430, buffer_reference_align = 16) buffer PyramidRef {
    PyramidHeader header;
    float depth[];
};

float farthestSample(ivec2 pixel) {
#if IDV_PYRAMID_MSAA
    float farthest = 0.0;
    for (int s = 0; s < int(pyramid.samples); ++s)
        farthest = max(farthest, texelFetch(depthImage, pixel, s).r);
    return farthest;
#else
    return texelFetch(depthImage, pixel, 0).r;
#endif
}

void main() {
    PyramidRef p = PyramidRef(pyramid.pyramidAddress);
    PyramidLevel level = p.header.level[pyramid.level];
    uvec2 texel = gl_GlobalInvocationID.xy;
    if (texel.x >= level.width || texel.y >= level.height) return;
    float farthest = 0.0;
    if (pyramid.level == 0u) {
        for (uint dy = 0u; dy < 2u; ++dy)
            for (uint dx = 0u; dx < 2u; ++dx) {
                uvec2 pixel = texel * 2u + uvec2(dx, dy);
                if (all(lessThan(pixel, pyramid.extent)))
                    farthest = max(farthest, farthestSample(ivec2(pixel)));
            }
    } else {
        PyramidLevel below = p.header.level[pyramid.level - 1u];
        for (uint dy = 0u; dy < 2u; ++dy)
            for (uint dx = 0u; dx < 2u; ++dx) {
                uvec2 t = texel * 2u + uvec2(dx, dy);
                if (t.x < below.width && t.y < below.height)
                    farthest = max(farthest, p.depth[below.offset + t.y * below.width + t.x]);
            }
    }
    p.depth[level.offset + texel.y * level.width + texel.x] = farthest;
}
