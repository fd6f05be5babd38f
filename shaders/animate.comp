#version 460
// animate.comp - writes every object's world matrix relative to the frame's origin (the eye)
// from its double placement, with the translation moved by offset * explode (the exploded
// view), before the scene pass reads it. The subtraction of the origin is done in double and
// rounded to float once, exactly as SceneGpu::worldAt does on the CPU: a part kilometres from
// the world's origin but near the eye keeps the precision of one near both.
// It has its own push constant block, so it includes buffers.glsl instead of prelude.glsl
// (whose block is the scene pipelines' DrawPush).
#include "buffers.glsl"

layout(local_size_x = ANIMATE_GROUP_SIZE) in;

layout(push_constant, std430) uniform AnimationBlock {
    AnimationPush anim;
};

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= anim.objectCount) return;
    dmat4 rest = DMat4sRef(anim.restAddress).matrices[i];
    // `precise`: one rounded multiply, then one rounded add, never fused into an fma, exactly
    // as scene::explodedScene computes it on the CPU; the tests compare images bit for bit.
    precise vec3 step = Vec4sRef(anim.offsetsAddress).values[i].xyz * anim.explode;
    precise dvec3 moved = rest[3].xyz + dvec3(step);
    precise dvec3 relative = moved - anim.origin.xyz;
    mat4 world = mat4(rest);
    world[3] = vec4(vec3(relative), 1.0);
    // Only the translation changes, so the 3x3 of normalMatrix that shading uses stays valid.
    ObjectsRef(anim.objectsAddress).objects[i].world = world;
}
