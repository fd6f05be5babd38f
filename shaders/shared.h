// shared.h - every struct and binding index the GPU sees, declared once for C++ and GLSL.
// C++ includes it from src/ (inside namespace gpu, with static_assert'ed sizes); GLSL
// includes it through shaders/prelude.glsl after enabling the 64-bit integer extension.
// Layout rule: members are ordered largest-alignment first so that std430 (GLSL) and the
// C++ ABI agree without hidden padding; the static_asserts at the end prove it.
#ifndef IDVIEW_SHARED_H
#define IDVIEW_SHARED_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
namespace gpu {
using uint = uint32_t;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec2 = glm::uvec2;
using mat4 = glm::mat4;
#define IDV_CONST constexpr uint32_t
#else
#define IDV_CONST const uint
#endif

// Vertex attribute locations and the vertex buffer bindings they come from.
IDV_CONST LOC_POSITION = 0;
IDV_CONST LOC_NORMAL = 1;
IDV_CONST BINDING_VERTICES = 0;

// Fragment outputs, matching the colour attachments of the scene render pass.
IDV_CONST OUT_COLOR = 0;
IDV_CONST OUT_PART_ID = 1;

// The ID attachment holds this where no part covers the pixel.
IDV_CONST BACKGROUND_ID = 0xFFFFFFFFu;

// FrameData::flags bits.
IDV_CONST FRAME_COLORIZE_DRAWS = 1u;

// One vertex of the shared vertex buffer. Each CAD face has its own vertices, so normals
// are per face and edges stay hard.
struct Vertex {
    vec3 position;
    vec3 normal;
};

// Per-frame constants, in a device-local buffer per frame slot.
struct FrameData {
    mat4 viewProj;
    vec4 eyePosition; // world space, w unused
    uvec2 viewport;
    float partColorWeight; // 0: material colour only, 1: part colour only
    uint flags;
    uint64_t objectsAddress;   // ObjectData[]
    uint64_t materialsAddress; // Material[]
};

// One placed instance of a geometry.
struct ObjectData {
    mat4 world;
    mat4 normalMatrix; // inverse transpose of world, so non-uniform scale shades right
    uint materialIndex;
    uint uniquePartOffset; // unique part ID of the geometry's part 0 in this object
    uint geometryIndex;
    uint reserved;
};

struct Material {
    vec4 color; // linear RGB, a unused
};

// Push constants of the `push` per-draw mode. The frame address is pushed once per frame at
// offset 0; each draw then pushes only the per-draw tail (DRAW_PUSH_TAIL_OFFSET onwards).
struct DrawPush {
    uint64_t frameAddress; // FrameData
    uint objectIndex;
    uint partIndex; // local part index within the object's geometry
    uint drawIndex; // for colorize drawcalls
    uint reserved;
};
IDV_CONST DRAW_PUSH_TAIL_OFFSET = 8;

#ifdef __cplusplus
static_assert(sizeof(Vertex) == 24);
static_assert(sizeof(FrameData) == 112 && offsetof(FrameData, objectsAddress) == 96);
static_assert(sizeof(ObjectData) == 144);
static_assert(sizeof(Material) == 16);
static_assert(sizeof(DrawPush) == 24 && offsetof(DrawPush, objectIndex) == DRAW_PUSH_TAIL_OFFSET);
} // namespace gpu
#endif
#undef IDV_CONST
#endif
