#version 460
// scene.geom - the gs techniques: finds the triangle's part once per primitive and hands it
// to the fragment shader. With VK_NV_geometry_shader_passthrough (IDV_GS_PASSTHROUGH) the
// vertices pass through untouched and only the per-primitive part index is written (hidden
// parts are then discarded by the fragment shader; the ordinary form drops them here).
#if IDV_GS_PASSTHROUGH
#extension GL_NV_geometry_shader_passthrough : require
#endif
#include "prelude.glsl"
// Resolved by the shader compiler to the technique's lookup file (src/render/technique.cpp).
#include "technique.glsl"

layout(triangles) in;

// The triangle's place in its draw: a culled list of cluster runs (IDV_RUN_OFFSET) starts
// gl_PrimitiveIDIn at each run's first triangle.
#if IDV_RUN_OFFSET
#define primitiveInDraw(runOffset) ((runOffset) + uint(gl_PrimitiveIDIn))
#else
#define primitiveInDraw(runOffset) uint(gl_PrimitiveIDIn)
#endif

#if IDV_GS_PASSTHROUGH
layout(passthrough) in gl_PerVertex {
    vec4 gl_Position;
} gl_in[];
layout(location = VARYING_WORLD_POS, passthrough) in Varyings {
    vec3 worldPos;
    vec3 worldNormal;
    flat uint drawIndex;
#if IDV_RUN_OFFSET
    layout(location = VARYING_RUN_OFFSET) flat uint runOffset;
#endif
} inVertices[];
layout(location = VARYING_PART_INDEX) flat out uint outPartIndex;

void main() {
    FrameData frame = loadFrame();
    DrawData draw = loadDraw(frame, inVertices[0].drawIndex);
    outPartIndex = lookupLocalPart(frame, draw, primitiveInDraw(inVertices[0].runOffset));
}
#else
layout(triangle_strip, max_vertices = 3) out;
layout(location = VARYING_WORLD_POS) in vec3 inWorldPos[];
layout(location = VARYING_WORLD_NORMAL) in vec3 inWorldNormal[];
layout(location = VARYING_DRAW_INDEX) flat in uint inDrawIndex[];
#if IDV_RUN_OFFSET
layout(location = VARYING_RUN_OFFSET) flat in uint inRunOffset[];
#endif
layout(location = VARYING_WORLD_POS) out vec3 outWorldPos;
layout(location = VARYING_WORLD_NORMAL) out vec3 outWorldNormal;
layout(location = VARYING_DRAW_INDEX) flat out uint outDrawIndex;
layout(location = VARYING_PART_INDEX) flat out uint outPartIndex;

void main() {
    FrameData frame = loadFrame();
    DrawData draw = loadDraw(frame, inDrawIndex[0]);
    uint part = lookupLocalPart(frame, draw, primitiveInDraw(inRunOffset[0]));
#if IDV_HIDE_PARTS
    // A hidden part's triangle is not emitted: the fragment shader keeps its early tests.
    uint offset = loadObject(frame.objectsAddress, draw.objectIndex).uniquePartOffset;
    if (partInSet(frame.hiddenAddress, offset + part)) return;
#endif
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_in[i].gl_Position;
        outWorldPos = inWorldPos[i];
        outWorldNormal = inWorldNormal[i];
        outDrawIndex = inDrawIndex[i];
        outPartIndex = part;
        EmitVertex();
    }
    EndPrimitive();
}
#endif
