#version 460
// scene.vert - transforms a vertex of the current draw's object; shared by every technique.
// It hands on only what shading needs plus the flat draw index.
#include "prelude.glsl"

layout(location = LOC_POSITION) in vec3 inPosition;
layout(location = LOC_NORMAL) in vec3 inNormal;
#if IDV_MODE_MDI_ATTRIBUTE
layout(location = LOC_DRAW_INDEX) in uint inDrawIndex; // instanced: buffer[firstInstance]
#endif

layout(location = VARYING_WORLD_POS) out vec3 outWorldPos;
layout(location = VARYING_WORLD_NORMAL) out vec3 outWorldNormal;
layout(location = VARYING_DRAW_INDEX) flat out uint outDrawIndex;

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
    ObjectData object = loadObject(frame.objectsAddress, loadDraw(frame, drawIndex).objectIndex);
    vec4 world = object.world * vec4(inPosition, 1.0);
    outWorldPos = world.xyz;
    outWorldNormal = mat3(object.normalMatrix) * inNormal;
    outDrawIndex = drawIndex;
    gl_Position = frame.viewProj * world;
}
