#version 460
// scene.vert - transforms a vertex of the current draw's object; shared by every technique.
#include "prelude.glsl"

layout(location = LOC_POSITION) in vec3 inPosition;
layout(location = LOC_NORMAL) in vec3 inNormal;

layout(location = 0) out vec3 outWorldPos;
layout(location = 1) out vec3 outWorldNormal;

void main() {
    FrameData frame = loadFrame();
    ObjectData object = loadObject(frame.objectsAddress, push.objectIndex);
    vec4 world = object.world * vec4(inPosition, 1.0);
    outWorldPos = world.xyz;
    outWorldNormal = mat3(object.normalMatrix) * inNormal;
    gl_Position = frame.viewProj * world;
}
