#version 460
// scene.frag - finds the unique part ID of the fragment (the technique's job), writes it to
// the ID attachment and shades the fragment with it.
#include "prelude.glsl"
#include "shading.glsl"
// Resolved by the shader compiler to the current technique's file (src/render/technique.cpp).
#include "technique.glsl"

layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec3 inWorldNormal;

layout(location = OUT_COLOR) out vec4 outColor;
layout(location = OUT_PART_ID) out uint outPartId;

void main() {
    FrameData frame = loadFrame();
    ObjectData object = loadObject(frame.objectsAddress, push.objectIndex);
    uint uniquePartId = object.uniquePartOffset + techniqueLocalPartIndex();
    outPartId = uniquePartId;

    vec3 base = MaterialsRef(frame.materialsAddress).materials[object.materialIndex].color.rgb;
    if ((frame.flags & FRAME_COLORIZE_DRAWS) != 0u) base = hashColor(push.drawIndex ^ 0x9e3779b9u);
    base = mix(base, hashColor(uniquePartId), frame.partColorWeight);
    outColor = vec4(headlight(base, inWorldPos, inWorldNormal, frame.eyePosition.xyz), 1.0);
}
