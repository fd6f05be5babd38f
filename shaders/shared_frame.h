// shared_frame.h - the scene pass's interface: where vertex attributes, varyings and
// fragment outputs live, the frame's constants (FrameData), the objects and materials the
// shaders read, and the pick. Part of shared.h's family (include shared.h).
#ifndef IDVIEW_SHARED_FRAME_H
#define IDVIEW_SHARED_FRAME_H

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
// Culled lists of cluster runs (CULL_CLUSTER_RUNS): the run's first triangle in its draw,
// which the techniques that read gl_PrimitiveID add to it (it restarts at 0 in every command).
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
// Shade each object in the colour of the level of detail it is drawn at (shading.glsl).
IDV_CONST FRAME_TINT_LEVELS = 8u;
// The view, the placement, the hidden parts, the cut, the levels and the targets are those of
// the frame before, which culled in two passes: its history is exact for this one (a still
// view, shared_cull.h).
IDV_CONST FRAME_VIEW_UNCHANGED = 16u;

// Levels of detail, full detail included (scene/lod.h's maxLevels is this).
IDV_CONST LOD_MAX_LEVELS = 4;
// FRAME_TINT_LEVELS's colours (linear RGB), which the panel's legend shows too: grey full
// detail, then blue, yellow and red.
#define IDV_LEVEL_TINTS                                                                            \
    vec3(0.75, 0.75, 0.75), vec3(0.1, 0.55, 0.95), vec3(0.95, 0.75, 0.1), vec3(0.9, 0.2, 0.3)
#ifdef __cplusplus
inline const vec3 LEVEL_TINTS[LOD_MAX_LEVELS] = {IDV_LEVEL_TINTS};
#else
const vec3 LEVEL_TINTS[LOD_MAX_LEVELS] = vec3[](IDV_LEVEL_TINTS);
#endif
#undef IDV_LEVEL_TINTS

// Section planes (scene/section.h, whose maxSectionPlanes is this).
IDV_CONST SECTION_PLANES_MAX = 3u;
// The in-plane rule's "parallel": the cosine of the largest angle (2.6 degrees) between a
// surface's normal and a plane's. A planar CAD face's normals are exact; tessellated curves
// pass only where they touch the plane, where either answer draws the same.
IDV_FLOAT SECTION_PARALLEL_COS = 0.999;

// The one material of FRAME_IGNORE_MATERIALS (linear RGB): a mid grey, so that only part
// colours (--part-weight) tint the image.
IDV_FLOAT NEUTRAL_MATERIAL = 0.5;

// X-ray (render/xray.h): the opacity of the parts outside the selection, drawn over the scene
// pass's picture. Low enough that three layers of them still let the selection show.
IDV_FLOAT XRAY_ALPHA = 0.25;

// FrameData::pickPixel.x when no pixel is picked this frame.
IDV_CONST NO_PICK = 0xFFFFFFFFu;

// One vertex of the shared vertex buffer. Procedural CAD faces have vertices of their own, so
// normals are per face and edges stay hard; glTF parts share vertices where the file does.
struct Vertex {
    vec3 position, normal;
};

// Per-frame constants, in a device-local buffer per frame slot. The addresses are 0 where the
// configuration drawn has no such buffer.
struct FrameData {
    mat4 viewProj;
    vec4 eyePosition; // the eye, w 1; ortho: unit direction toward the viewer, w 0 (toViewer)
    uvec2 viewport;
    float partColorWeight;       // 0: material colour only, 1: part colour only
    uint flags;                  // FRAME_*
    uint64_t objectsAddress;     // ObjectData[]
    uint64_t materialsAddress;   // Material[]
    uint64_t idsAddress;         // the technique's ID buffer (see DrawData::idsOffset)
    uint64_t drawsAddress;       // DrawData[] of the mdi modes
    uint64_t pickAddress;        // PickData, shared by all frames (see PickData)
    uint64_t verticesAddress;    // Vertex[]: the meshlets' part vertices, as floats
    uint64_t meshletsAddress;    // Meshlet[] (mesh techniques)
    uint64_t meshletDataAddress; // uint[]: meshlet vertices, then packed triangles
    uint64_t drawIndicesAddress; // uint[]: the draw index attribute (mdi-attribute)
    uint64_t selectedAddress;    // uint[]: bitset over unique part IDs (compose.comp tints them)
    uint64_t hiddenAddress;      // uint[]: bitset over unique part IDs, never drawn (see HIDING)
    // uint[] per part of the scene (Scene::parts order): its own material, or OBJECT_MATERIAL
    // for its object's; 0 when no part has one (CAD face colours)
    uint64_t partMaterialsAddress;
    // Culling (shared_cull.h), 0 where it is off: the depth pyramid (PyramidHeader, then
    // floats), each draw's DrawCull, each meshlet's CullBox, the meshlet history (uint words,
    // a bit per meshlet), this frame's CullStats and, where cull.comp lists the draws, their
    // CULL_* state words.
    uint64_t pyramidAddress;
    uint64_t drawCullAddress;
    uint64_t meshletBoxesAddress;
    uint64_t meshletHistoryAddress;
    uint64_t cullStatsAddress;
    uint64_t cullStateAddress;
    // Mesh tasks listed by cull.comp: the meshlets its late pass chose, bits laid out as the
    // meshlet history's (the task shader draws just those); 0 elsewhere.
    uint64_t lateMeshletsAddress;
    // The visibility buffer (shared_visibility.h), 0 for the other techniques: VisibilityDraw[]
    // of the draw list, and per meshlet slot of payloads its draw (uint[]).
    uint64_t visibilityDrawsAddress;
    uint64_t visibilityBlocksAddress;
    uvec2 pickPixel; // framebuffer pixel whose nearest part is picked; x NO_PICK: none
    vec2 sampleZero; // where sample 0 lies in a pixel (0.5, 0.5 without MSAA)
    float time;      // seconds since the start (no shader reads it today)
    // Levels of detail: above 0, cull.comp's levels step runs and keeps each object's level
    // whose error spans under this many pixels (cull.glsl's lodChosen); 0: it does not run.
    float lodErrorPixels;
    float eyeReach; // |eye| in either projection: cull.glsl's rounding margins grow with it
    // The compute rasterizer (shared_visibility.h), 0 for the other techniques: the task
    // shader's lists of meshlets for raster.comp (RasterEntry[], rasterCapacity a pass), and
    // the 64-bit visibility sample per framebuffer sample it writes.
    uint rasterCapacity;
    uint64_t rasterListAddress;
    uint64_t rasterSamplesAddress;
    // A meshlet goes to the compute path where its projected rectangle holds at most this
    // many pixels per triangle (RASTER_ALL: every meshlet it can draw); 0: none does.
    float rasterTrianglePixels;
    // IDV_SECTION (scene/section.h): cut away where dot(plane, (p, 1)) > 0; unused (0,0,0,-1).
    // A surface parallel to a plane and within sectionTolerance of it lies in it, and is kept
    // or cut whole by the side its outward normal faces (SectionPlane::keeps, the in-plane
    // rule): float rounding at the scene's scale (scene::inPlaneTolerance) stays inside it.
    float sectionTolerance;
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

#ifdef __cplusplus
static_assert(sizeof(Vertex) == 24);
static_assert(sizeof(FrameData) == 368 && offsetof(FrameData, pickPixel) == 264);
static_assert(offsetof(FrameData, rasterListAddress) == 296);
static_assert(offsetof(FrameData, sectionPlanes) == 320);
static_assert(sizeof(PickData) == 16);
static_assert(sizeof(ObjectData) == 144 && sizeof(Material) == 16);
#endif

#endif
