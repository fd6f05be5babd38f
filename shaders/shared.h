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
using vec2 = glm::vec2;
using mat4 = glm::mat4;
using dvec4 = glm::dvec4;
#define IDV_CONST constexpr uint32_t
#else
#define IDV_CONST const uint
#endif

// Vertex attribute locations and the vertex buffer bindings they come from.
IDV_CONST LOC_POSITION = 0;
IDV_CONST LOC_NORMAL = 1;
IDV_CONST LOC_DRAW_INDEX = 2; // mdi-attribute: instanced uint, buffer[i] = i
IDV_CONST BINDING_VERTICES = 0;
IDV_CONST BINDING_DRAW_INDICES = 1;

// Varyings between stages: only what shading needs plus a flat draw index.
IDV_CONST VARYING_WORLD_POS = 0;
IDV_CONST VARYING_WORLD_NORMAL = 1;
IDV_CONST VARYING_DRAW_INDEX = 2;
// The local part found before the fragment shader: by a geometry shader (per triangle), the
// vertex shader (flat, from the provoking vertex) or a mesh shader (per primitive).
IDV_CONST VARYING_PART_INDEX = 3;
// Culled lists of cluster runs (IDV_RUN_OFFSET): the run's first triangle in its draw, which
// the techniques that read gl_PrimitiveID add to it (it restarts at 0 in every command).
IDV_CONST VARYING_RUN_OFFSET = 4;

// Fragment outputs, matching the colour attachments of the scene render pass.
IDV_CONST OUT_COLOR = 0;
IDV_CONST OUT_PART_ID = 1;

// The ID attachment holds this where no part covers the pixel.
IDV_CONST BACKGROUND_ID = 0xFFFFFFFFu;

// FrameData::flags bits.
IDV_CONST FRAME_COLORIZE_DRAWS = 1u;
IDV_CONST FRAME_IGNORE_MATERIALS = 2u; // every object shaded with NEUTRAL_MATERIAL
IDV_CONST FRAME_HIDING = 4u;           // some part is hidden: culling skips draws of hidden parts
// The floors write no ID image, so their culling remembers what passed the last frame's
// occlusion test instead of what the ID image showed (CULL_PASSED, and the meshlet bits).
IDV_CONST FRAME_BOUNDS_HISTORY = 8u;
// The view, the objects' placement and the hidden parts are those of the last culled frame:
// cluster runs then draw early just the clusters that passed its late test where that test
// ran (cull_runs.glsl says why the images stay those of culling off).
IDV_CONST FRAME_VIEW_UNCHANGED = 16u;
// Shade each object in the colour of the level of detail it is drawn at (shading.glsl).
IDV_CONST FRAME_TINT_LEVELS = 32u;
IDV_CONST SECTION_PLANES_MAX = 3u; // scene::maxSectionPlanes
// The one material of FRAME_IGNORE_MATERIALS (linear RGB): a mid grey, so that only part
// colours (--part-weight) tint the image.
#ifdef __cplusplus
constexpr float NEUTRAL_MATERIAL = 0.5f;
#else
const float NEUTRAL_MATERIAL = 0.5;
#endif

// X-ray (render/xray.h): the opacity of the parts outside the selection, drawn over the scene
// pass's picture. Low enough that three layers of them still let the selection show.
#ifdef __cplusplus
constexpr float XRAY_ALPHA = 0.25f;
#else
const float XRAY_ALPHA = 0.25;
#endif

// FrameData::pickPixel.x when no pixel is picked this frame.
IDV_CONST NO_PICK = 0xFFFFFFFFu;

// One vertex of the shared vertex buffer. Procedural CAD faces have vertices of their own, so
// normals are per face and edges stay hard; glTF parts share vertices where the file does.
struct Vertex {
    vec3 position, normal;
};

// Per-frame constants, in a device-local buffer per frame slot.
struct FrameData {
    mat4 viewProj;
    vec4 eyePosition; // the eye, w 1; ortho: unit direction toward the viewer, w 0 (toViewer)
    uvec2 viewport;
    float partColorWeight; // 0: material colour only, 1: part colour only
    uint flags;
    uint64_t objectsAddress;     // ObjectData[]
    uint64_t materialsAddress;   // Material[]
    uint64_t idsAddress;         // the technique's ID buffer (see DrawData::idsOffset), or 0
    uint64_t drawsAddress;       // DrawData[] of the mdi modes, or 0
    uint64_t pickAddress;        // PickData, shared by all frames (see PickData)
    uint64_t verticesAddress;    // Vertex[]: the meshlets' part vertices, as floats, or 0
    uint64_t meshletsAddress;    // Meshlet[] (mesh techniques), or 0
    uint64_t meshletDataAddress; // uint[]: meshlet vertices, then packed triangles, or 0
    uint64_t drawIndicesAddress; // uint[]: the draw index attribute (mdi-attribute), or 0
    uint64_t selectedAddress;    // uint[]: bitset over unique part IDs (compose.comp tints them)
    uint64_t hiddenAddress;      // uint[]: bitset over unique part IDs, never drawn (see HIDING)
    // uint[] per part of the scene (Scene::parts order): its own material, or OBJECT_MATERIAL
    // for its object's; 0 when no part has one (CAD face colours)
    uint64_t partMaterialsAddress;
    // Culling (render/culling.h), 0 where it is off: the parts the last ID image showed
    // (uint[] bitset), the depth pyramid (PyramidHeader, then floats), each draw's DrawCull,
    // each meshlet's CullBox, one bit per (draw, meshlet) that the last culled frame found
    // in view (and not occluded), and this frame's CullStats.
    uint64_t visibleAddress;
    uint64_t pyramidAddress;
    uint64_t drawCullAddress;
    uint64_t meshletBoxesAddress;
    uint64_t meshletBitsAddress;
    uint64_t cullStatsAddress;
    uint64_t cullStateAddress; // mdi modes: per draw the CULL_* bits of this frame's first pass
    uvec2 pickPixel;           // framebuffer pixel whose nearest part is picked; x NO_PICK: none
    vec2 sampleZero;           // where sample 0 lies in a pixel (0.5, 0.5 without MSAA)
    float time;                // seconds since the start (no shader reads it today)
    // Occlusion, mesh techniques: the word of meshletBits where a second bitset starts, the
    // meshlets the late pass draws (mdi modes: lateMeshletWord, chosen by cull.comp; push
    // mode: lateDrawnWord, written by the task shader, which tests them itself), and where a
    // third starts, the early pass's (a still view draws both again); 0 where unused
    uint lateMeshletWord, lateDrawnWord, earlyMeshletWord;
    float lodErrorPixels; // levels in the lists (cull.glsl's lodChosen): their pixels, else 0
    float eyeReach;       // |eye| in either projection: cull.glsl's rounding margins grow with it
    // IDV_SECTION (scene/section.h): cut away where dot(plane, (p, 1)) > 0; unused (0,0,0,-1)
    vec4 sectionPlanes[SECTION_PLANES_MAX];
};

// A part without a material of its own (FrameData::partMaterialsAddress).
IDV_CONST OBJECT_MATERIAL = 0xFFFFFFFFu;

// Part bitsets (selection, hidden parts, the result of a part set pass): bit (id & 31) of
// word (id >> 5) is set when unique part `id` is in the set. Hidden parts are discarded by a
// pipeline variant without early fragment tests (IDV_HIDE_PARTS), used only while something
// is hidden: with early tests a discarded fragment would still write depth.

// The pick: during the scene pass, fragments at FrameData::pickPixel atomicMin `current` with
// pickKey (~depth bits << 32 | unique part ID); positive floats order like their bits, and
// depth is reversed (nearer is greater), so the inverted bits make the nearest surface win.
// After the pass `current` is copied to `last` and to the frame slot's host-visible readback.
// (The hovered part's highlight reads the ID image: compose.comp.)
struct PickData {
    uint64_t current; // reset to PICK_NONE before each pass
    uint64_t last;
};
#ifdef __cplusplus
constexpr uint64_t PICK_NONE = ~uint64_t(0);
#else
const uint64_t PICK_NONE = 0xFFFFFFFFFFFFFFFFul;
uint64_t pickKey(float depth, uint uniquePartId) {
    return (uint64_t(~floatBitsToUint(depth)) << 32) | uint64_t(uniquePartId);
}
#endif

// What one draw of a draw list needs. `push` mode pushes it; the mdi modes read it from the
// per-draw buffer at the draw's index.
struct DrawData {
    // The first four are what a vertex or mesh shader reads per vertex (object, and where
    // the part indices are), so they come from one 16-byte load.
    uint objectIndex;
    // Where the draw's data starts in the technique's ID buffer: tri-*, vertex-fs, mesh-fs:
    // byte offset of the geometry's packed part indices; search-*: index of the batch's first
    // triangle count; bsearch-*: index of the geometry's first running triangle offset;
    // mesh-vertex-fs: that byte offset minus the geometry's first meshlet vertex times the
    // width (modulo 2^32), so the shader indexes by the meshlet vertex's absolute position.
    uint idsOffset;
    uint idsWidth; // tri-*, vertex-fs, mesh-*: bytes per part index (1, 2 or 4)
    // vertex-fs: the geometry's first vertex in the part-vertex array (gl_VertexIndex minus
    // this is the geometry-local vertex); mesh-*: the geometry's first meshlet.
    uint firstElement;
    uint firstPart; // local index of the draw's first part in the object's geometry
    uint partCount; // parts the draw covers
    uint drawIndex; // position in the draw list, for colorize drawcalls
    uint lodLevel;  // the level of detail the draw's geometry is (0: full detail)
};

// One meshlet of a geometry (scene/meshlets.h): up to MESHLET_MAX_VERTICES vertices and
// MESHLET_MAX_TRIANGLES triangles, drawn by one mesh shader workgroup.
IDV_CONST MESHLET_MAX_VERTICES = 64;
IDV_CONST MESHLET_MAX_TRIANGLES = 124;
IDV_CONST MESH_GROUP_SIZE = 32; // invocations per meshlet: one warp on NVIDIA
struct Meshlet {
    uint firstVertex;        // into the meshlet data: the indices of its vertices
    uint firstTriangle;      // into the meshlet data: corners packed 8 bits each, low byte first
    uint counts;             // vertex count | triangle count << 16
    uint firstLocalTriangle; // its first triangle's position in its geometry (mesh-fs's IDs)
};

// One placed instance of a geometry.
struct ObjectData {
    mat4 world;
    mat4 normalMatrix; // inverse transpose of world, so non-uniform scale shades right
    uint materialIndex;
    uint uniquePartOffset; // unique part ID of the geometry's part 0 in this object
    uint geometryIndex;
    uint firstPart; // the geometry's first part in the scene's parts (part materials)
};

struct Material {
    vec4 color; // linear RGB, a unused
};

// Push constants. The frame address is pushed once per frame at offset 0; in `push` mode
// each draw then pushes the fields of `draw` that changed since the previous draw. With
// culling, each pass pushes its phase and, in the mdi modes, the commands it draws.
struct DrawPush {
    uint64_t frameAddress; // FrameData
    DrawData draw;
    // mdi modes with culling: the list drawn, MeshTaskCommand[] for the mesh techniques and
    // RunCommand[] for lists of cluster runs
    uint64_t commandsAddress;
    uint cullPhase; // CULL_PHASE_*: what the task shader lets through
    uint unused;
};
IDV_CONST DRAW_PUSH_DRAW_OFFSET = 8;
IDV_CONST DRAW_PUSH_CULL_OFFSET = 40; // commandsAddress, cullPhase

// GPU-driven culling (render/culling.h). Draws are culled per draw (an object, a part for
// per-draw, a batch for the search techniques) by a compute pass that writes the indirect
// draws and their count; meshlets by the task shader (scene.task). Every test is
// conservative: a draw or meshlet is dropped only where no sample of it could pass the depth
// test or lie in the view, so the images equal those drawn without culling.
IDV_CONST CULL_GROUP_SIZE = 256; // cull.comp: draws per workgroup
IDV_CONST TASK_GROUP_SIZE = 32;  // scene.task: meshlets per workgroup, one per invocation
// depth_pyramid.comp: a workgroup reduces 32 x 32 texels of a pass's first level to one,
// so each dispatch writes 6 levels (two for a 2560 x 1440 image).
IDV_CONST PYRAMID_GROUP = 32;
IDV_CONST PYRAMID_LEVELS_PER_PASS = 6;
IDV_CONST PYRAMID_MAX_LEVELS = 16;

// What one culling pass lets through (DrawPush::cullPhase, CullPush::phase).
IDV_CONST CULL_PHASE_NONE = 0;    // culling off: everything
IDV_CONST CULL_PHASE_FRUSTUM = 1; // one pass: what may lie in the view frustum
// Occlusion, two passes: first what the last ID image showed, then the depth pyramid is built
// from that pass's depth and the rest is tested against it.
IDV_CONST CULL_PHASE_EARLY = 2;
IDV_CONST CULL_PHASE_LATE = 3;
// "Freeze culling": the lists of the last culled frame are drawn again, and meshlets by the
// bits that frame left.
IDV_CONST CULL_PHASE_FROZEN = 4;      // the first (or only) list
IDV_CONST CULL_PHASE_FROZEN_LATE = 5; // the late list: meshlets of draws the first had not
// A still view (Renderer::planFrame) draws the early list of the last frame culled in two
// passes with just the meshlets that frame's early pass drew, then its late list with just
// those its late pass drew: the same meshlets in the same order.
IDV_CONST CULL_PHASE_REUSED = 6;
IDV_CONST CULL_PHASE_REUSED_LATE = 7;

// cull.comp runs each phase in two steps: decide (a flag per draw, a count per workgroup),
// then compact (each workgroup adds the counts before it, so draws keep their order).
IDV_CONST CULL_STEP_DECIDE = 0;
IDV_CONST CULL_STEP_COMPACT = 1;
IDV_CONST CULL_STEP_BOTH = 2; // a list of one workgroup: both steps in one dispatch
// Draws of several clusters (scene/bounds.h: runs of up to CLUSTER_MAX_TRIANGLES triangles of
// one part) whose box passes a test are tested again cluster by cluster in the frustum and
// late phases, and drawn when one cluster's box passes: a dispatch over (draw, cluster)
// pairs (step "clusters"), then one that counts each workgroup's draws anew ("count"),
// before "compact".
IDV_CONST CULL_STEP_CLUSTERS = 3;
IDV_CONST CULL_STEP_COUNT = 4;
// Cluster runs (CULL_CLUSTER_RUNS): the pass's commands are runs of a draw's clusters, not
// whole draws. After "clusters" has marked the (draw, cluster) pairs to draw, "runs count"
// counts each workgroup's runs (a marked pair whose pair before it, of the same draw, is not)
// and "runs compact" writes one command per run, in list order.
IDV_CONST CULL_STEP_RUNS_COUNT = 5;
IDV_CONST CULL_STEP_RUNS_COMPACT = 6;
IDV_CONST CLUSTER_MAX_TRIANGLES = 64;
// Per-draw state bits (CullPush::stateAddress), from the first pass of a frame.
IDV_CONST CULL_IN_FRUSTUM = 1u;       // may lie in the view frustum, and not all its parts hidden
IDV_CONST CULL_WAS_VISIBLE = 2u;      // one of its parts is in the last ID image
IDV_CONST CULL_DRAW_NOW = 4u;         // drawn by the current pass (decide -> compact)
IDV_CONST CULL_PASSED = 8u;           // FRAME_BOUNDS_HISTORY: passed the late pass's test
IDV_CONST CULL_NEEDS_CLUSTERS = 16u;  // drawn (and passed) only if a cluster's box passes
IDV_CONST CULL_CLUSTER_PASSED = 32u;  // one did (mesh tasks: one of its meshlets)
IDV_CONST CULL_MESHLETS_NEW = 64u;    // mesh tasks, late: a meshlet passed that was not drawn early
IDV_CONST CULL_LISTED = 128u;         // cluster runs: the current pass lists one of its clusters
IDV_CONST CULL_LISTED_EARLY = 256u;   // cluster runs: the early pass listed one
IDV_CONST CULL_INSIDE_FRUSTUM = 512u; // its box lies wholly inside the view frustum
// Cluster runs: after the draws' words in the state buffer, a word of CULL_PAIR_* bits per
// pair, then per object one more than the last of its pairs that passed the last late test,
// then one word: whether the last frame's late pass ran (its CULL_PAIR_HISTORY is fresh).
IDV_CONST CULL_PAIR_HISTORY = 1u; // passed the last late (or frustum) test
IDV_CONST CULL_PAIR_EARLY = 2u;   // drawn by this frame's early pass
IDV_CONST CULL_PAIR_NOW = 4u;     // listed by the current pass
// CullPush::flags
// Mesh tasks: in the late phase every meshlet of a draw whose box passed is tested here, one
// (draw, meshlet) pair per meshlet bit; the late list holds the draws with a meshlet to draw
// that the early pass did not, and the task shader draws just those (FrameData::lateMeshletWord).
IDV_CONST CULL_MESH_DRAWS = 1u;
// Cluster runs: the vertex pipelines draw runs of clusters (RunCommand; the techniques that
// read gl_PrimitiveID add the run's offset to it). Every draw of the list has a (draw, cluster)
// pair per cluster. An object's clusters are drawn early up to the last that passed the last
// late test, in the draws the last ID image has drawn early; late where they pass the
// pyramid and were not drawn early; so a draw half behind others draws half.
IDV_CONST CULL_CLUSTER_RUNS = 2u;

// A draw's box for culling, in its geometry's coordinates, for mesh techniques where its
// meshlets' bits start (one bit per meshlet, each draw's run starting on a word), its
// clusters (CullPush::clusterBoxesAddress) and, for draws of several, their first
// (draw, cluster) pair (CullPush::pairsAddress).
struct DrawCull {
    vec3 boxMin;
    uint meshletBit;
    vec3 boxMax;
    uint meshletCount;
    uint firstCluster;
    uint clusterCount;
    uint firstPair;
    // The object's parts from the draw's first on: the draw goes first when the last ID image
    // shows one of them, so that an object's draws are never drawn out of their order (a
    // later part drawn first would win where two of its parts tie in depth).
    uint partsToEnd;
    // Levels of detail (cull.glsl's lodChosen): the box around the object's own geometry, the
    // same in all its draws; the errors of the draw's level (below 0: the object's own
    // geometry) and of the next coarser one (FLT_MAX: none), in model units.
    vec3 lodBoxMin;
    float lodError;
    vec3 lodBoxMax;
    float lodNextError;
};
// A meshlet's or a part's box, in its geometry's coordinates (min above max: no triangles).
struct CullBox {
    vec3 boxMin;
    uint unused0;
    vec3 boxMax;
    // Clusters (not meshlets): the first triangle in its geometry, times 64, plus its
    // triangle count less one (CLUSTER_MAX_TRIANGLES is 64).
    uint triangles;
};

// The late phase's indirect dispatches (the depth pyramid's passes, the late cull's steps),
// written whole before each frame's early cull. When the early cull leaves the late pass
// nothing to test (every draw in view was in the last ID image: a still view of what all
// shows), it zeroes them, so the GPU skips that work without the CPU knowing.
IDV_CONST CULL_PYRAMID_PASSES = 4; // PYRAMID_MAX_LEVELS / PYRAMID_LEVELS_PER_PASS, rounded up
struct CullDispatch {
    uint x, y, z; // VkDispatchIndirectCommand
    uint unused;
};
struct CullDispatches {
    CullDispatch pyramid[CULL_PYRAMID_PASSES];
    CullDispatch lateCull;     // decide, count and compact: a workgroup per CULL_GROUP_SIZE draws
    CullDispatch lateClusters; // clusters: a workgroup per CULL_GROUP_SIZE pairs
    // What the late pass would test, counted by the early cull: draws (or, for cluster runs,
    // clusters).
    uint lateCandidates;
    uint unused[3];
};

// A command of a list of cluster runs: an indexed draw over the run's triangles, then the
// run's first triangle in its draw, which the vertex shader hands on (VARYING_RUN_OFFSET)
// to the techniques that read gl_PrimitiveID. The draws are made with this stride.
struct RunCommand {
    uint indexCount; // VkDrawIndexedIndirectCommand
    uint instanceCount;
    uint firstIndex;
    int vertexOffset;
    uint firstInstance; // the draw's index, which names its DrawData
    uint runOffset;     // triangles of the draw before the run
};

// What the mesh techniques' culled indirect draws hold: task workgroups, then the draw.
struct MeshTaskCommand {
    uint groupCountX;
    uint groupCountY;
    uint groupCountZ;
    uint drawIndex;
};

IDV_CONST LOD_MAX_LEVELS = 4; // levels of detail, full detail included (scene::maxLevels)

// Counters of one frame: the indirect draw counts of the two passes (the vertex draws' count
// buffer), draws of the late list that the early list did not have, triangles of the listed
// draws (vertex pipelines), and meshlets and their triangles the task shader let through;
// the triangles per level of detail too. cull.comp's counts come first: they stay with its
// lists while a frame draws them again, and the task shader counts every frame.
struct CullStats {
    uint draws[2];
    uint lateNew, triangles;
    uint listed; // draws of the early (or only) list; with cluster runs, draws with a run in it
    uint levelTriangles[LOD_MAX_LEVELS];
    uint meshlets, meshletTriangles;
    uint levelMeshletTriangles[LOD_MAX_LEVELS];
    uint unused;
};

// The depth pyramid (render/culling.h): level 0 holds, per 2x2 pixels, the farthest depth of
// any sample (the least: depth is reversed, scene/camera.h); level k + 1 the farthest of 2x2
// texels of level k. Texel (x, y) of level k covers pixels [x, x + 1) * 2^(k + 1) exactly,
// edges clipped to the image.
struct PyramidLevel {
    uint offset; // first float of the level, after the header
    uint width, height;
    uint unused;
};
struct PyramidHeader {
    uint levels;
    uint unused[3];
    PyramidLevel level[PYRAMID_MAX_LEVELS];
};

struct CullPush {
    uint64_t frameAddress;  // FrameData
    uint64_t drawsAddress;  // DrawData[] of the whole list
    uint64_t cullAddress;   // DrawCull[]
    uint64_t sourceAddress; // the whole list's indirect commands (uint words)
    uint64_t targetAddress; // this pass's commands, compacted in list order
    uint64_t stateAddress;  // uint per draw: CULL_* bits
    uint64_t groupsAddress; // uint per workgroup: draws it lets through
    uint64_t statsAddress;  // CullStats
    uint drawCount;
    uint phase;
    uint step;
    uint commandWords; // 5: VkDrawIndexedIndirectCommand, 4: MeshTaskCommand
    uint flags;
    uint groupCount;
    // Indirect dispatches the late phase may leave out (CullDispatches), or 0.
    uint64_t dispatchesAddress;
    // The draws of several clusters: per (draw, cluster) pair its draw (uint), the box of
    // every cluster of the scene (CullBox, unused0 its part in its geometry), and the number
    // of pairs. Mesh tasks have a pair per meshlet bit instead (CULL_MESH_DRAWS).
    uint64_t pairsAddress;
    uint64_t clusterBoxesAddress;
    uint pairCount;
    uint objectCount; // cluster runs: the objects, whose words end the state buffer
};

// depth_pyramid.comp: PYRAMID_LEVELS_PER_PASS levels from `level` on, from the depth
// attachment (level 0) or the level below.
struct PyramidPush {
    uint64_t pyramidAddress;
    uvec2 extent; // pixels of the depth attachment
    uint level;
    uint samples;
};

// animate.comp: objects[i].world = rest[i] with its translation moved by offsets[i] * explode
// (the exploded view, see src/scene/explode.h). One thread per object.
IDV_CONST ANIMATE_GROUP_SIZE = 64;
// ObjectData::world is relative to the frame's origin (the eye, render::eyeRelative): this
// pass writes it from the double placements whenever the origin or the explode value moves.
struct AnimationPush {
    dvec4 origin;            // world coordinates of the point the matrices are relative to (w 0)
    uint64_t objectsAddress; // ObjectData[], world written
    uint64_t restAddress;    // dmat4[]: the scene's world matrices, double
    uint64_t offsetsAddress; // vec4[]: per-object offset at explode 1 (w unused)
    uint objectCount;
    float explode; // 0: at rest, 1: twice as far from the scene centre
};

// The passes over the resolved ID image after the scene pass: the picture's composition and
// the part sets (their own header of this family).
#include "shared_id_passes.h"

#ifdef __cplusplus
static_assert(sizeof(Vertex) == 24);
static_assert(sizeof(FrameData) == 336 && offsetof(FrameData, pickPixel) == 248);
static_assert(sizeof(DrawCull) == 80 && sizeof(CullBox) == 32);
static_assert(sizeof(MeshTaskCommand) == 16 && sizeof(CullStats) == 64);
static_assert(sizeof(CullDispatches) == 16 * (CULL_PYRAMID_PASSES + 3));
static_assert(CULL_PYRAMID_PASSES * PYRAMID_LEVELS_PER_PASS >= PYRAMID_MAX_LEVELS);
static_assert(sizeof(PyramidHeader) == 16 + 16 * PYRAMID_MAX_LEVELS);
static_assert(sizeof(CullPush) == 120 && offsetof(CullPush, dispatchesAddress) == 88);
static_assert(sizeof(PyramidPush) == 24);
static_assert(offsetof(DrawPush, commandsAddress) == DRAW_PUSH_CULL_OFFSET);
static_assert(sizeof(PickData) == 16 && sizeof(DrawData) == 32 && sizeof(Meshlet) == 16);
static_assert(sizeof(ObjectData) == 144 && sizeof(Material) == 16);
static_assert(sizeof(DrawPush) == 56 && offsetof(DrawPush, draw) == DRAW_PUSH_DRAW_OFFSET);
static_assert(sizeof(AnimationPush) == 64 && offsetof(AnimationPush, explode) == 60);
} // namespace gpu
#endif
#undef IDV_CONST
#endif
