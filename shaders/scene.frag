#version 460
// scene.frag - finds the unique part ID of the fragment (the technique's job, here or in an
// earlier stage), writes it to the ID attachment and shades the fragment with it.
#if IDV_LOOKUP_IN_MESH || IDV_VISIBILITY
#extension GL_EXT_mesh_shader : require
#endif
#include "prelude.glsl"
#include "shading.glsl"
// The part comes from an earlier stage, or is looked up here from gl_PrimitiveID.
#define IDV_PART_FROM_EARLIER_STAGE (IDV_LOOKUP_IN_GS || IDV_LOOKUP_IN_VS || IDV_LOOKUP_IN_MESH)
#if !IDV_NO_ID && !IDV_PART_FROM_EARLIER_STAGE
// Resolved by the shader compiler to the technique's lookup file (src/render/technique.cpp).
#include "technique.glsl"
#endif

// Depth test before the shader, even though the pick writes memory: keeps early-Z for every
// technique, and only fragments that pass the test at their time take part in the pick, which
// makes the pick agree with the ID attachment even where surfaces share a depth. While parts
// are hidden and no earlier stage drops them (IDV_HIDE_IN_FRAGMENT), the test must come after
// the shader: a fragment discarded after an early test would still have written its depth
// and hidden what is behind it. Section planes (IDV_SECTION) discard here for every
// technique, for the same reason after the test.
#if !IDV_HIDE_IN_FRAGMENT && !IDV_SECTION
layout(early_fragment_tests) in;
#endif

layout(location = VARYING_WORLD_POS) in vec3 inWorldPos;
layout(location = VARYING_WORLD_NORMAL) in vec3 inWorldNormal;
layout(location = VARYING_DRAW_INDEX) flat in uint inDrawIndex;
#if (IDV_LOOKUP_IN_MESH && !IDV_MESH_PART_PER_VERTEX) || IDV_VISIBILITY
// The part, or the visibility buffer's payload (shared_visibility.h).
layout(location = VARYING_PART_INDEX) perprimitiveEXT flat in uint inPartIndex;
#elif IDV_PART_FROM_EARLIER_STAGE
layout(location = VARYING_PART_INDEX) flat in uint inPartIndex;
#endif

#if IDV_RUN_OFFSET && !IDV_PART_FROM_EARLIER_STAGE
layout(location = VARYING_RUN_OFFSET) flat in uint inRunOffset;
#endif

layout(location = OUT_COLOR) out vec4 outColor;
#if !IDV_NO_ID
layout(location = OUT_PART_ID) out uint outPartId; // no-id masks the attachment off
#endif

// The depth the pick compares: the depth at sample 0, which decides the pixel. Without MSAA
// that is the pixel centre, where the rasterizer's own depth is exact. With MSAA the centre
// can see two surfaces that meet inside the pixel in the other order, so extrapolate to the
// sample: window-space depth is affine across a triangle, so its screen derivatives carry it
// there exactly up to rounding. Derivatives need uniform control flow: hence outside the
// pick's branch, and the branch on sampleZero is the same for the whole draw.
float pickDepth(FrameData frame) {
    float z = gl_FragCoord.z;
    if (frame.sampleZero == vec2(0.5)) return z;
    vec2 offset = frame.sampleZero - vec2(0.5);
    return clamp(z + dFdx(z) * offset.x + dFdy(z) * offset.y, 0.0, 1.0);
}

#if IDV_SECTION
// Whether any section plane cuts the point away (shared.h, FrameData::sectionPlanes), by the
// in-plane rule where the surface lies in a plane: kept where its outward normal (the vertex
// normals') faces the side cut away, cut otherwise, the same for every fragment of it and
// for every technique, so a face a plane was put in never mixes with what lies behind it.
// scene::SectionPlane::keeps is the same rule on the CPU.
bool cutAway(FrameData frame, vec3 worldPos, vec3 normal) {
    [[unroll]] for (uint p = 0u; p < SECTION_PLANES_MAX; ++p) {
        vec4 plane = frame.sectionPlanes[p];
        float distance = dot(plane, vec4(worldPos, 1.0));
        float along = dot(plane.xyz, normal);
        bool inPlane = abs(distance) <= frame.sectionTolerance &&
                       abs(along) > SECTION_PARALLEL_COS * length(normal);
        if (inPlane ? along < 0.0 : distance > 0.0) return true;
    }
    return false;
}

// Whether the fragment lies on the back of its surface: where a cut opens a solid, the first
// surface seen through it is the inside of the cut part, which shows as its cap. Windings are
// unreliable in CAD exports, so the triangle's own normal (exact, from the derivatives of the
// position) takes the side its vertex normals point to, and is compared with the view.
bool backFacing(FrameData frame) {
    vec3 faceNormal = cross(dFdx(inWorldPos), dFdy(inWorldPos));
    if (dot(faceNormal, inWorldNormal) < 0.0) faceNormal = -faceNormal;
    return dot(faceNormal, toViewer(frame, inWorldPos)) < 0.0;
}
#endif

#if IDV_VISIBILITY
// The visibility buffer (shared_visibility.h): the mesh shader's payload goes where the other
// techniques write the part ID; the shading pass (visibility.comp) finds the part, shades and
// picks. The mesh shader dropped hidden parts; section planes cut here, so that what they cut
// writes no depth.
void main() {
#if IDV_SECTION
    if (cutAway(loadFrame(), inWorldPos, inWorldNormal)) discard;
#endif
    outPartId = inPartIndex;
}
#else
void main() {
    FrameData frame = loadFrame();
#if IDV_SECTION
    bool cap = backFacing(frame); // derivatives: before any discard
#else
    bool cap = false;
#endif
    DrawData draw = loadDraw(frame, inDrawIndex);
    ObjectData object = loadObject(frame.objectsAddress, draw.objectIndex);
    vec3 base = drawBase(frame, object, draw.drawIndex, draw.lodLevel);
#if IDV_NO_ID
    // The benchmark's floor: no lookup, no ID, no pick, no part colour.
#if IDV_SECTION
    if (cutAway(frame, inWorldPos, inWorldNormal)) discard;
#endif
    // The X-ray pass draws the floor's shading translucent, blended over the picture.
    outColor = vec4(cap ? capColor(base, gl_FragCoord.xy)
                        : headlight(base, inWorldNormal, toViewer(frame, inWorldPos)),
                    IDV_TRANSLUCENT != 0 ? XRAY_ALPHA : 1.0);
#else
#if IDV_PART_FROM_EARLIER_STAGE
    uint localPart = inPartIndex;
#else
#if IDV_RUN_OFFSET
    uint localPart = lookupLocalPart(frame, draw, inRunOffset + uint(gl_PrimitiveID));
#else
    uint localPart = lookupLocalPart(frame, draw, uint(gl_PrimitiveID));
#endif
#endif
    uint uniquePartId = object.uniquePartOffset + localPart;
    // Before any discard: derivatives need the whole quad.
    float depth = pickDepth(frame);
#if IDV_HIDE_IN_FRAGMENT
    if (partInSet(frame.hiddenAddress, uniquePartId)) discard;
#endif
#if IDV_SECTION
    if (cutAway(frame, inWorldPos, inWorldNormal)) discard;
#endif
    outPartId = uniquePartId;

    base = partBase(frame, object, localPart, uniquePartId, base);
    vec3 color = cap ? capColor(base, gl_FragCoord.xy)
                     : headlight(base, inWorldNormal, toViewer(frame, inWorldPos));

    PickRef pick = PickRef(frame.pickAddress);
    // With MSAA, sample 0 decides, as in the resolve of the ID attachment (see targets.h):
    // only fragments covering it take part. Without MSAA the mask is always 1.
    if (uvec2(gl_FragCoord.xy) == frame.pickPixel && (gl_SampleMaskIn[0] & 1) != 0) {
        atomicMin(pick.pick.current, pickKey(depth, uniquePartId));
    }
    outColor = vec4(color, 1.0);
#endif
}
#endif
