#version 460
// scene.frag - finds the unique part ID of the fragment (the technique's job, here or in the
// geometry shader), writes it to the ID attachment and shades the fragment with it.
#include "prelude.glsl"
#include "shading.glsl"
// Resolved by the shader compiler to the technique's lookup file (src/render/technique.cpp).
#include "technique.glsl"

// Depth test before the shader, even though the pick writes memory: keeps early-Z for every
// technique, and only fragments that pass the test at their time take part in the pick, which
// makes the pick agree with the ID attachment even where surfaces share a depth.
layout(early_fragment_tests) in;

layout(location = VARYING_WORLD_POS) in vec3 inWorldPos;
layout(location = VARYING_WORLD_NORMAL) in vec3 inWorldNormal;
layout(location = VARYING_DRAW_INDEX) flat in uint inDrawIndex;
#if IDV_LOOKUP_IN_GS
layout(location = VARYING_GS_PART_INDEX) flat in uint inGsPartIndex;
#endif

layout(location = OUT_COLOR) out vec4 outColor;
layout(location = OUT_PART_ID) out uint outPartId;

void main() {
    FrameData frame = loadFrame();
    DrawData draw = loadDraw(frame, inDrawIndex);
    ObjectData object = loadObject(frame.objectsAddress, draw.objectIndex);
#if IDV_LOOKUP_IN_GS
    uint localPart = inGsPartIndex;
#else
    uint localPart = lookupLocalPart(frame, draw, uint(gl_PrimitiveID));
#endif
    uint uniquePartId = object.uniquePartOffset + localPart;
    outPartId = uniquePartId;

    vec3 base = MaterialsRef(frame.materialsAddress).materials[object.materialIndex].color.rgb;
    if ((frame.flags & FRAME_COLORIZE_DRAWS) != 0u) base = hashColor(draw.drawIndex ^ 0x9e3779b9u);
    base = mix(base, hashColor(uniquePartId), frame.partColorWeight);
    vec3 color = headlight(base, inWorldPos, inWorldNormal, frame.eyePosition.xyz);

    PickRef pick = PickRef(frame.pickAddress);
    if (uvec2(gl_FragCoord.xy) == frame.pickPixel) {
        uint64_t depthBits = uint64_t(floatBitsToUint(gl_FragCoord.z));
        atomicMin(pick.pick.current, (depthBits << 32) | uint64_t(uniquePartId));
    }
    if (uniquePartId == uint(pick.pick.last)) color = highlightHovered(color, frame.time);
    if (uniquePartId == frame.selectedPart) color = highlightSelected(color);
    outColor = vec4(color, 1.0);
}
