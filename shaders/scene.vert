#version 460
// scene.vert - transforms a vertex of the current draw's object; shared by every technique
// without a mesh shader. It hands on what shading needs, the flat draw index and, for
// vertex-fs, the vertex's part (flat: the fragment gets the provoking, first, vertex's).
#include "prelude.glsl"
#if IDV_LOOKUP_IN_VS
#include "technique.glsl"
#endif

layout(location = LOC_POSITION) in vec3 inPosition;
layout(location = LOC_NORMAL) in vec3 inNormal;
#if IDV_MODE_MDI_ATTRIBUTE
layout(location = LOC_DRAW_INDEX) in uint inDrawIndex; // instanced: buffer[firstInstance]
#endif

layout(location = VARYING_WORLD_POS) out vec3 outWorldPos;
layout(location = VARYING_WORLD_NORMAL) out vec3 outWorldNormal;
layout(location = VARYING_DRAW_INDEX) flat out uint outDrawIndex;
#if IDV_LOOKUP_IN_VS
layout(location = VARYING_PART_INDEX) flat out uint outPartIndex;
#endif
#if IDV_RUN_OFFSET
layout(location = VARYING_RUN_OFFSET) flat out uint outRunOffset;
#endif

uint currentDrawIndex() {
#if IDV_MODE_MDI_ATTRIBUTE
    return inDrawIndex;
#elif IDV_MODE_MDI_BASEINSTANCE
    return uint(gl_InstanceIndex); // firstInstance is the draw index, one instance per draw
#else
    return push.draw.drawIndex;
#endif
}

void main() {
    FrameData frame = loadFrame();
    uint drawIndex = currentDrawIndex();
    DrawData draw = loadDraw(frame, drawIndex);
    ObjectData object = loadObject(frame.objectsAddress, draw.objectIndex);
    vec4 world = object.world * vec4(inPosition, 1.0);
    outWorldPos = world.xyz;
    outWorldNormal = mat3(object.normalMatrix) * inNormal;
    outDrawIndex = drawIndex;
#if IDV_LOOKUP_IN_VS
    // gl_VertexIndex includes the draw's vertexOffset: firstElement makes it geometry-local.
    outPartIndex = lookupLocalPart(frame, draw, uint(gl_VertexIndex) - draw.firstElement);
#endif
#if IDV_RUN_OFFSET
    // A culled list of cluster runs (shared.h, RunCommand): gl_PrimitiveID counts from the
    // run's first triangle, the lookup from the draw's.
    outRunOffset = RunCommandsRef(push.commandsAddress).commands[gl_DrawID].runOffset;
#endif
    gl_Position = frame.viewProj * world;
}
