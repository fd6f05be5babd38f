// shared_animate.h - animate.comp, which places the objects for each frame (render/animator.h):
// objects[i].world = rest[i] with its translation moved by offsets[i] * explode (the exploded
// view, src/scene/explode.h), relative to the frame's origin. Part of shared.h's family
// (include shared.h).
#ifndef IDVIEW_SHARED_ANIMATE_H
#define IDVIEW_SHARED_ANIMATE_H

IDV_CONST ANIMATE_GROUP_SIZE = 64; // objects per workgroup, one thread each
// ObjectData::world is relative to the frame's origin (the eye, render::eyeRelative): this
// pass writes it from the double placements whenever the origin or the explode value moves.
struct AnimationPush {
    dvec4 origin;            // world coordinates of the point the matrices are relative to (w 0)
    uint64_t objectsAddress; // ObjectData[], world written
    uint64_t restAddress;    // dmat4[]: the scene's world matrices, double
    uint64_t offsetsAddress; // vec4[]: per-object offset at explode 1 (w unused)
    uint objectCount;
    float explode; // 0: at rest, 1: twice as far from the scene centre
};

#ifdef __cplusplus
static_assert(sizeof(AnimationPush) == 64 && offsetof(AnimationPush, explode) == 60);
#endif

#endif
