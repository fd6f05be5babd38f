// shared.h - the one header family for everything the GPU sees: every struct, constant and
// binding index, declared once for C++ and GLSL. C++ includes this file, which puts the
// family in namespace gpu with static_assert'ed layouts; GLSL includes it through
// shaders/buffers.glsl after enabling the 64-bit integer extension. By concern:
//   shared_frame.h      the scene pass's interface: vertex input, varyings, outputs, the
//                       frame's constants, objects and materials, the pick
//   shared_draw.h       what one draw reads: DrawData, the push block, meshlets, the indirect
//                       commands
//   shared_cull.h       culling and levels of detail: phases, steps, state bits, boxes, the
//                       depth pyramid and the counters (its table is the culling's design)
//   shared_animate.h    the exploded view's placement pass
//   shared_id_passes.h  the passes over the resolved ID image and the compute resolve
//   shared_visibility.h the visibility buffer's payload and its shading pass
//   shared_census.h     the visibility census's counters
// Layout rule: members are ordered largest-alignment first so that std430 (GLSL) and the C++
// ABI agree without hidden padding; each header's static_asserts prove it for its structs.
// Include this file, never a member of the family alone: it defines what they share.
#ifndef IDVIEW_SHARED_H
#define IDVIEW_SHARED_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
namespace gpu {
using uint = uint32_t;
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec2 = glm::uvec2;
using mat4 = glm::mat4;
using dvec4 = glm::dvec4;
// A constant both languages read: written once below with these, so C++ and GLSL agree.
#define IDV_CONST constexpr uint32_t
#define IDV_FLOAT constexpr float
#define IDV_TABLE constexpr // before the type of a constant array of structs
#else
#define IDV_CONST const uint
#define IDV_FLOAT const float
#define IDV_TABLE const
#endif

#include "shared_frame.h"

#include "shared_draw.h"

#include "shared_cull.h"

#include "shared_animate.h"

#include "shared_id_passes.h"

#include "shared_visibility.h"

#include "shared_census.h"

#ifdef __cplusplus
} // namespace gpu
#endif
#undef IDV_CONST
#undef IDV_FLOAT
#undef IDV_TABLE
#endif
