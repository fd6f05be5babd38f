// cull.glsl - the conservative tests every culling decision is made of, shared by cull.comp
// (per draw) and scene.task (per meshlet): a box in an object's coordinates against the view
// frustum and against the depth pyramid, and bit ranges of the part bitsets. Something is
// dropped only where no sample of it could pass: the margins below cover the rounding by
// which the vertex shader's positions may differ from the box's corners computed here, and
// the rasterizer's snapping of vertices to its sub-pixel grid (CULL_RELATIVE_MARGIN, which the
// CPU's frustum test shares, is in shared_cull.h).
#ifndef IDVIEW_CULL_GLSL
#define IDVIEW_CULL_GLSL

#include "buffers.glsl"

// The tests can be made wrong on purpose (tests/test_culling_edges.cpp): every screen
// rectangle shrunk by this many pixels on each side must change the images.
#ifndef IDV_CULL_SHRINK_PIXELS
#define IDV_CULL_SHRINK_PIXELS 0
#endif

// Screen rectangles grow by this much on each side (vertices snap to 1/256 pixel).
const float CULL_PIXEL_MARGIN = 1.0 / 16.0;
// Depth comparisons keep this much apart, relative to the depth, for the rasterizer's depth
// interpolation: depth is reversed (scene/camera.h), far surfaces have small depths and float
// rounding is relative to them.
const float CULL_DEPTH_MARGIN = 1.0 / 1048576.0;
// Pyramid texels read per side of a screen rectangle, at most: finer levels hug a rectangle
// closer. Draws and clusters read up to 16 x 16, meshlets 8 x 8 (measured on the H100: the
// meshlets let through fall by a tenth from 4 x 4, and the frame with them).
const int CULL_DRAW_SPAN = 16;
const int CULL_MESHLET_SPAN = 8;

// Whether any (all) of the bits [first, first + count) of a bitset are set.
bool anyBitInRange(uint64_t address, uint first, uint count) {
    if (count == 0u) return false;
    UintsRef bits = UintsRef(address);
    uint last = first + count - 1u;
    for (uint w = first >> 5; w <= (last >> 5); ++w) {
        uint lo = w == (first >> 5) ? (first & 31u) : 0u;
        uint hi = w == (last >> 5) ? (last & 31u) : 31u;
        uint mask = (0xFFFFFFFFu >> (31u - hi)) & (0xFFFFFFFFu << lo);
        if ((bits.values[w] & mask) != 0u) return true;
    }
    return false;
}

bool allBitsInRange(uint64_t address, uint first, uint count) {
    UintsRef bits = UintsRef(address);
    uint last = first + count - 1u;
    for (uint w = first >> 5; count != 0u && w <= (last >> 5); ++w) {
        uint lo = w == (first >> 5) ? (first & 31u) : 0u;
        uint hi = w == (last >> 5) ? (last & 31u) : 31u;
        uint mask = (0xFFFFFFFFu >> (31u - hi)) & (0xFFFFFFFFu << lo);
        if ((bits.values[w] & mask) != mask) return false;
    }
    return true;
}

// A box seen by the camera: outside the frustum, or its screen rectangle (pixels) and its
// nearest depth (the greatest: depth is reversed), unless it reaches in front of the near
// plane (then it cannot be occluded).
struct BoxView {
    bool outside;
    bool inside; // every corner inside every plane: so is all the box holds
    bool crossesNear;
    vec2 minPixel, maxPixel;
    float nearestDepth;
};

BoxView viewBox(FrameData frame, mat4 world, vec3 boxMin, vec3 boxMax) {
    vec3 center = (boxMin + boxMax) * 0.5;
    vec3 halfSize = max((boxMax - boxMin) * 0.5, vec3(0.0));
    vec3 scales = vec3(length(world[0].xyz), length(world[1].xyz), length(world[2].xyz));
    float reach = length(world[3].xyz) + frame.eyeReach +
                  (length(center) + length(halfSize)) * max(scales.x, max(scales.y, scales.z));
    halfSize += reach * CULL_RELATIVE_MARGIN / max(min(scales.x, min(scales.y, scales.z)), 1e-30);

    mat4 mvp = frame.viewProj * world;
    vec4 c = mvp * vec4(center, 1.0);
    vec4 ex = mvp[0] * halfSize.x, ey = mvp[1] * halfSize.y, ez = mvp[2] * halfSize.z;
    uint outsideAll = 63u; // planes every corner is outside of: -x +x -y +y far near
    uint outsideAny = 0u;  // planes some corner is outside of
    BoxView view;
    view.crossesNear = false;
    view.minPixel = vec2(1e30);
    view.maxPixel = vec2(-1e30);
    view.nearestDepth = 0.0;
    [[unroll]] for (uint i = 0u; i < 8u; ++i) {
        vec4 p = c + ((i & 1u) != 0u ? ex : -ex) + ((i & 2u) != 0u ? ey : -ey) +
                 ((i & 4u) != 0u ? ez : -ez);
        uint outside = (p.x < -p.w ? 1u : 0u) | (p.x > p.w ? 2u : 0u) | (p.y < -p.w ? 4u : 0u) |
                       (p.y > p.w ? 8u : 0u) | (p.z < 0.0 ? 16u : 0u) | (p.z > p.w ? 32u : 0u);
        outsideAll &= outside;
        outsideAny |= outside;
        if (p.w <= 0.0 || p.z > p.w) {
            view.crossesNear = true;
            continue;
        }
        vec3 ndc = p.xyz / p.w;
        vec2 pixel = (ndc.xy * 0.5 + 0.5) * vec2(frame.viewport);
        view.minPixel = min(view.minPixel, pixel);
        view.maxPixel = max(view.maxPixel, pixel);
        view.nearestDepth = max(view.nearestDepth, ndc.z);
    }
    view.outside = outsideAll != 0u;
    view.inside = outsideAny == 0u;
    return view;
}

// Whether every sample the box may cover already holds a nearer depth in the pyramid, read
// at the finest level where its rectangle spans at most `span` texels a side: finer levels
// hug the rectangle closer (a coarse texel reaches past an occluder's edge), for more reads.
bool occluded(FrameData frame, BoxView view, int span) {
    if (view.crossesNear || frame.pyramidAddress == 0ul) return false;
    vec2 last = vec2(frame.viewport) - 1.0;
    vec2 lo = clamp(floor(view.minPixel - CULL_PIXEL_MARGIN), vec2(0.0), last);
    vec2 hi = clamp(floor(view.maxPixel + CULL_PIXEL_MARGIN), vec2(0.0), last);
    ivec2 first = ivec2(lo) + IDV_CULL_SHRINK_PIXELS;
    ivec2 end = max(ivec2(hi) - IDV_CULL_SHRINK_PIXELS, first);
    PyramidRef pyramid = PyramidRef(frame.pyramidAddress);
    uint levels = pyramid.header.levels;
    uint k = 0u;
    while (k + 1u < levels &&
           any(greaterThan((end >> (k + 1u)) - (first >> (k + 1u)), ivec2(span - 1))))
        ++k;
    PyramidLevel level = pyramid.header.level[k];
    ivec2 t0 = first >> (k + 1u);
    ivec2 t1 = min(end >> (k + 1u), ivec2(level.width, level.height) - 1);
    // Hidden where every texel holds a depth no farther than the box's nearest, plus the
    // margin: the first texel that does not decides (boxes in view, the most tested, stop soon).
    float nearest = view.nearestDepth * (1.0 + CULL_DEPTH_MARGIN);
    for (int y = t0.y; y <= t1.y; ++y)
        for (int x = t0.x; x <= t1.x; ++x)
            if (pyramid.depth[level.offset + uint(y) * level.width + uint(x)] < nearest)
                return false;
    return true;
}

// Levels of detail: whether the draw `c` culls is of the level its object draws this frame.
// Where the list holds levels (frame.lodErrorPixels above 0), an object draws its coarsest
// level whose error, seen at the nearest depth of the box around it, spans under that many
// pixels: its finest where none does, or where the box reaches the camera's plane. A box
// hugs a long part (a rail, a shaft seen from its side) far closer than a sphere, whose
// nearest point may be next to the camera. All of an object's draws hold the same box and
// the errors grow level by level, so exactly one level is chosen, by the same arithmetic in
// every draw. Elsewhere the list holds one level of each object, which is drawn. In ortho the
// depth does not matter: the budget is the same for every object of one scale.
bool lodChosen(FrameData frame, mat4 world, DrawCull c) {
    if (frame.lodErrorPixels <= 0.0) return true;
    // Pixels per model unit at depth 1: the projection's vertical scale (the length of the
    // view-projection's y row, over a rigid view) times half the viewport's height.
    vec3 yRow = vec3(frame.viewProj[0][1], frame.viewProj[1][1], frame.viewProj[2][1]);
    float scale = max(length(world[0].xyz), max(length(world[1].xyz), length(world[2].xyz)));
    bool finest = c.lodError < 0.0;
    if (frame.eyePosition.w == 0.0) {
        // Orthographic: a world unit spans the same pixels at every depth, the y row's length
        // (2 / the view's height) times half the viewport's height; w is 1 everywhere.
        float pixelsPerUnit = length(yRow) * 0.5 * float(frame.viewport.y);
        float orthoBudget = frame.lodErrorPixels / (pixelsPerUnit * scale);
        return (finest || c.lodError < orthoBudget) && !(c.lodNextError < orthoBudget);
    }
    float wScale = length(vec3(frame.viewProj[0][3], frame.viewProj[1][3], frame.viewProj[2][3]));
    float pixelsAtUnitDepth = length(yRow) / max(wScale, 1e-30) * 0.5 * float(frame.viewport.y);
    // w is linear over the box, so its nearest corner has the smallest.
    mat4 mvp = frame.viewProj * world;
    vec3 halfSize = max(c.lodBoxMax - c.lodBoxMin, vec3(0.0)) * 0.5;
    float w = (mvp * vec4((c.lodBoxMin + c.lodBoxMax) * 0.5, 1.0)).w - abs(mvp[0].w) * halfSize.x -
              abs(mvp[1].w) * halfSize.y - abs(mvp[2].w) * halfSize.z;
    float depth = w / max(wScale, 1e-30);
    if (!(depth > 0.0)) return finest;
    // The largest error in model units that stays under the pixels asked at that depth.
    float budget = frame.lodErrorPixels * depth / (pixelsAtUnitDepth * scale);
    bool fits = finest || c.lodError < budget;
    bool nextFits = c.lodNextError < budget;
    return fits && !nextFits;
}

#endif
