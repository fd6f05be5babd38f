#version 460
// animate.comp - the exploded view on the GPU: writes every object's world matrix as its rest
// matrix with the translation moved by offset * explode, before the scene pass reads it.
// It has its own push constant block, so it includes shared.h directly instead of
// prelude.glsl (whose block is the scene pipelines' DrawPush).
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_buffer_reference : require

#include "shared.h"

layout(local_size_x = ANIMATE_GROUP_SIZE) in;

layout(buffer_reference, std430, buffer_reference_align = 16) writeonly buffer AnimatedObjects {
    ObjectData objects[];
};
layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer RestMatrices {
    mat4 rest[];
};
layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer Offsets {
    vec4 offsets[];
};

layout(push_constant, std430) uniform AnimationBlock {
    AnimationPush anim;
};

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= anim.objectCount) return;
    mat4 world = RestMatrices(anim.restAddress).rest[i];
    // `precise`: one rounded multiply, then one rounded add, never fused into an fma, exactly
    // as scene::explodedScene computes it on the CPU; the tests compare images bit for bit.
    precise vec3 step = Offsets(anim.offsetsAddress).offsets[i].xyz * anim.explode;
    precise vec3 moved = world[3].xyz + step;
    world[3].xyz = moved;
    // Only the translation changes, so the 3x3 of normalMatrix that shading uses stays valid.
    AnimatedObjects(anim.objectsAddress).objects[i].world = world;
}
