// shared_cull.h - culling and levels of detail on the GPU: the design in one table
// (CULL_PHASES), then its constants and structs. Part of shared.h's family (include
// shared.h). render/culling.h records the passes; shaders/cull.comp (with cull_*.glsl) and
// scene.task run them.
#ifndef IDVIEW_SHARED_CULL_H
#define IDVIEW_SHARED_CULL_H

// Every test is conservative: a draw, cluster or meshlet is left out only where no sample of
// it could lie in the view or pass the depth test, and every list keeps the draw order, so
// the images are those drawn without culling (but for surfaces that tie exactly in depth,
// where the one drawn first wins: render/culling.h).
//
// The draw lists cull.comp writes, by what the draws are:
// - runs:  the vertex pipelines with culling on. A draw's triangles come in clusters of up
//          to CLUSTER_MAX_TRIANGLES of one part, a (draw, cluster) pair each, and a list
//          holds a RunCommand per run of consecutive clusters that passed.
// - draws: whole draws: the mesh techniques (a MeshTaskCommand per draw; the task shader
//          then culls its meshlets, one (draw, meshlet) pair per meshlet bit), and the
//          vertex pipelines when culling is off but levels of detail are on.
// Push mode draws from the CPU: it tests each object's box against the frustum, and the task
// shader of the mesh techniques culls meshlets in every phase.
//
// History: what the last frame's late (or frustum) test found may show. It decides what the
// early pass draws, and each history is a buffer of its own that one step writes in a pass
// (CullBuffers; HistoryTest in tests/test_cull_history.cpp reads them back):
// - pair history (runs): a word per (draw, cluster) pair, 1 where the cluster passed; written
//   by the clusters step of the passes that make history (CULL_PASS_HISTORY).
// - history ends (runs): per object one more than the last of its pairs with history, so that
//   its early clusters are its first ones and keep their order where two tie in depth.
//   Two slots: the early pass reads the one the last late pass wrote; the late pass's runs
//   count step writes the other, which the frame zeroes before its first pass.
// - meshlet history (mesh draws): a bit per meshlet, written by the late pass's meshlets step
//   where cull.comp lists the draws, else by the task shader of the passes that make history.
// A mesh draw goes early where one of its meshlets has history, and the task shader draws
// those meshlets. Every technique, the floors included, culls by this.
// A still view (FRAME_VIEW_UNCHANGED: nothing moved since a frame culled in two passes)
// draws each cluster with history early by itself: one without lay wholly behind that
// frame's early depth, so behind its final depth, which this frame draws again; drawn late,
// it writes no sample and ties none, so no order can change.
//
// The phases (CullPush::phase, DrawPush::cullPhase), rows of CULL_PHASES below, in its order.
IDV_CONST CULL_PHASE_NONE = 0;        // culling off
IDV_CONST CULL_PHASE_FRUSTUM = 1;     // frustum culling
IDV_CONST CULL_PHASE_EARLY = 2;       // occlusion, first half; then the pyramid of its depth
IDV_CONST CULL_PHASE_LATE = 3;        // occlusion, second half
IDV_CONST CULL_PHASE_FROZEN = 4;      // freeze culling: the last culled frame's first list
IDV_CONST CULL_PHASE_FROZEN_LATE = 5; // and its second list
IDV_CONST CULL_PHASE_COUNT = 6;

// The steps (CullPush::step), each a dispatch over the list's draws or pairs:
// - levels: whether each draw is of the level its object draws (CULL_OTHER_LEVEL);
// - decide: each draw's bits for this pass, and a count per workgroup of the draws listed;
// - clusters (runs): each (draw, cluster) pair of a draw in play is tested by its own box;
// - meshlets (mesh draws, late): each (draw, meshlet) pair of a draw whose box passed is
//   tested as the task shader would; what passed becomes history, what passed and was not
//   drawn early is what the late task shader draws (FrameData::lateMeshletsAddress);
// - count (mesh draws, late): each workgroup's draws counted again after the meshlets;
// - compact: each workgroup adds the counts of the workgroups before its own and writes its
//   commands there, so the list keeps the draw order;
// - runs count, runs compact: the same for the runs of clusters that passed.
IDV_CONST CULL_STEP_LEVELS = 0;
IDV_CONST CULL_STEP_DECIDE = 1;
IDV_CONST CULL_STEP_CLUSTERS = 2;
IDV_CONST CULL_STEP_MESHLETS = 3;
IDV_CONST CULL_STEP_COUNT = 4;
IDV_CONST CULL_STEP_COMPACT = 5;
IDV_CONST CULL_STEP_RUNS_COUNT = 6;
IDV_CONST CULL_STEP_RUNS_COMPACT = 7;
// A phase's steps as bits, the letters of the docs' table; a pass dispatches them in the
// order of their numbers. Levels runs only where levels are chosen (CullPlan::levels: lists
// holding every level of every object, mdi modes).
IDV_CONST CULL_L = 1u << CULL_STEP_LEVELS;
IDV_CONST CULL_D = 1u << CULL_STEP_DECIDE;
IDV_CONST CULL_C = 1u << CULL_STEP_CLUSTERS;
IDV_CONST CULL_M = 1u << CULL_STEP_MESHLETS;
IDV_CONST CULL_N = 1u << CULL_STEP_COUNT;
IDV_CONST CULL_P = 1u << CULL_STEP_COMPACT;
IDV_CONST CULL_RN = 1u << CULL_STEP_RUNS_COUNT;
IDV_CONST CULL_RP = 1u << CULL_STEP_RUNS_COMPACT;
// The steps dispatched over the pairs, not the draws.
IDV_CONST CULL_STEPS_OVER_PAIRS = CULL_C | CULL_M | CULL_RN | CULL_RP;

// What a phase's pass of cull.comp does (CullPhase::pass).
IDV_CONST CULL_PASS_TESTS = 1u;   // leaves out draws out of view; without it every draw is listed
IDV_CONST CULL_PASS_EARLY = 2u;   // lists what the history says may show, marked drawn early
IDV_CONST CULL_PASS_LATE = 4u;    // the second list: what the first found in view, tested against
                                  // the pyramid, and what passed that the first did not draw
IDV_CONST CULL_PASS_HISTORY = 8u; // what passed becomes the history (pairs', meshlets')

// What the task shader draws in a phase (CullPhase::task): the meshlets that meet every bit;
// none: every meshlet.
IDV_CONST CULL_TASK_WITH_HISTORY = 1u;     // with history
IDV_CONST CULL_TASK_NOT_EARLY = 2u;        // of draws not drawn early
IDV_CONST CULL_TASK_CHOSEN = 4u;           // where cull.comp lists the draws (mdi): those the
                                           // meshlets step chose, instead of the tests below
IDV_CONST CULL_TASK_IN_VIEW = 8u;          // in the view frustum
IDV_CONST CULL_TASK_NOT_BEHIND = 16u;      // not behind the depth pyramid
IDV_CONST CULL_TASK_WITHOUT_HISTORY = 32u; // without history

// One phase: the steps cull.comp runs for lists of runs, of mesh draws and of whole vertex
// draws, what those steps do, and what the task shader draws. render/culling.cpp records the
// steps, cull_*.glsl and scene.task read the rest; docs/techniques.md prints the table
// (tests/test_cull_table.cpp checks it).
struct CullPhase {
    uint runs;
    uint meshDraws;
    uint vertexDraws;
    uint pass; // CULL_PASS_*
    uint task; // CULL_TASK_*
};
// Each row: the steps for runs, for mesh draws, for whole vertex draws; pass; task.
IDV_TABLE CullPhase CULL_PHASES[CULL_PHASE_COUNT] = {
    // NONE
    {0u, CULL_L | CULL_D | CULL_P, CULL_L | CULL_D | CULL_P, 0u, 0u},
    // FRUSTUM
    {CULL_L | CULL_D | CULL_C | CULL_RN | CULL_RP, CULL_L | CULL_D | CULL_P,
     CULL_L | CULL_D | CULL_P, CULL_PASS_TESTS | CULL_PASS_HISTORY, CULL_TASK_IN_VIEW},
    // EARLY
    {CULL_L | CULL_D | CULL_C | CULL_RN | CULL_RP, CULL_L | CULL_D | CULL_P,
     CULL_L | CULL_D | CULL_P, CULL_PASS_TESTS | CULL_PASS_EARLY,
     CULL_TASK_WITH_HISTORY | CULL_TASK_IN_VIEW},
    // LATE
    {CULL_D | CULL_C | CULL_RN | CULL_RP, CULL_D | CULL_M | CULL_N | CULL_P, CULL_D | CULL_P,
     CULL_PASS_TESTS | CULL_PASS_LATE | CULL_PASS_HISTORY,
     CULL_TASK_CHOSEN | CULL_TASK_IN_VIEW | CULL_TASK_NOT_BEHIND | CULL_TASK_WITHOUT_HISTORY},
    // FROZEN, FROZEN_LATE: no pass; the two lists of the last culled frame are drawn again.
    {0u, 0u, 0u, 0u, CULL_TASK_WITH_HISTORY},
    {0u, 0u, 0u, CULL_PASS_LATE, CULL_TASK_WITH_HISTORY | CULL_TASK_NOT_EARLY},
};

// A draw's state word (CullPush::stateAddress), written anew every frame: by the levels step
// (or decide where it does not run), then by each pass.
IDV_CONST CULL_OTHER_LEVEL = 1u;    // levels: another level of its object draws: no pass lists it
IDV_CONST CULL_IN_FRUSTUM = 2u;     // may lie in the view frustum, and not all its parts hidden
IDV_CONST CULL_INSIDE_FRUSTUM = 4u; // its box lies wholly inside the view frustum
IDV_CONST CULL_EARLY = 8u;          // in view, and its object's history reaches it: drawn early
IDV_CONST CULL_DRAW_NOW = 16u;      // listed by the current pass (decide, count -> compact)
IDV_CONST CULL_RETEST = 32u;        // late: its box passed the pyramid; its pairs are tested
IDV_CONST CULL_NEW_MESHLETS = 64u;  // draws, late: a meshlet passed that was not drawn early
IDV_CONST CULL_LISTED = 128u;       // runs: the current pass lists one of its clusters
IDV_CONST CULL_LISTED_EARLY = 256u; // runs: the early pass listed one (the counters)
// Runs: after the draws' words, a word of CULL_PAIR_* bits per (draw, cluster) pair, written
// anew by each pass's clusters step.
IDV_CONST CULL_PAIR_EARLY = 1u;  // drawn by this frame's early pass
IDV_CONST CULL_PAIR_NOW = 2u;    // listed by the current pass
IDV_CONST CULL_PAIR_PASSED = 4u; // passed the current pass's test (late: its new history)

// CullPush::flags: what the list is (see the top).
IDV_CONST CULL_MESH_DRAWS = 1u;   // draws of the mesh techniques: MeshTaskCommand, meshlet pairs
IDV_CONST CULL_CLUSTER_RUNS = 2u; // runs: RunCommand, (draw, cluster) pairs

IDV_CONST CULL_GROUP_SIZE = 256; // cull.comp: draws or pairs per workgroup
IDV_CONST TASK_GROUP_SIZE = 32;  // scene.task: meshlets per workgroup, one per invocation
// Clusters: runs of up to this many triangles of one part (CullBox::triangles packs the count
// in 6 bits).
IDV_CONST CLUSTER_MAX_TRIANGLES = 64;
// Boxes are inflated by this fraction of the largest coordinate magnitude involved (world
// position and eye): 16 float ulps, several times the rounding of one matrix product. The CPU's
// frustum test of push mode (render/culling.cpp) inflates by the same.
IDV_FLOAT CULL_RELATIVE_MARGIN = 1.0 / 524288.0;

// depth_pyramid.comp: a workgroup reduces 32 x 32 texels of a pass's first level to one,
// so each dispatch writes 6 levels (two for a 2560 x 1440 image).
IDV_CONST PYRAMID_GROUP = 32;
IDV_CONST PYRAMID_LEVELS_PER_PASS = 6;
IDV_CONST PYRAMID_MAX_LEVELS = 16;

// A draw's box for culling, in its geometry's coordinates, for mesh draws where its meshlet
// bits start (each draw's run of bits starting on a word, so a task workgroup's 32 have one
// word to themselves), its clusters (CullPush::clusterBoxesAddress) and, for runs and mesh
// draws, its first pair.
struct DrawCull {
    vec3 boxMin;
    uint meshletBit;
    vec3 boxMax;
    uint meshletCount;
    uint firstCluster;
    uint clusterCount;
    uint firstPair;
    uint unused; // pads the row to 16 bytes
    // Levels of detail (cull.glsl's lodChosen): the box around the object's own geometry, the
    // same in all its draws; the errors of the draw's level (below 0: the object's own
    // geometry) and of the next coarser one (FLT_MAX: none), in model units.
    vec3 lodBoxMin;
    float lodError;
    vec3 lodBoxMax;
    float lodNextError;
};

// A cluster's or a meshlet's box, in its geometry's coordinates (min above max: no triangles).
struct CullBox {
    vec3 boxMin;
    uint part; // clusters: the part its triangles belong to, in its geometry; meshlets: 0
    vec3 boxMax;
    // Clusters: the first triangle in its geometry times 64, plus its triangle count less one
    // (runs compact reads both); meshlets: 0.
    uint triangles;
};

// Counters of one frame: the indirect draw counts of the two passes (the vertex draws' count
// buffer), draws of the late list that the early list did not have, triangles of the listed
// draws (vertex pipelines), and meshlets and their triangles the task shader let through;
// the triangles per level of detail too.
struct CullStats {
    uint draws[2];
    uint lateNew, triangles;
    uint listed; // draws of the early (or only) list; runs: draws with a run in it
    uint levelTriangles[LOD_MAX_LEVELS];
    uint meshlets, meshletTriangles;
    uint levelMeshletTriangles[LOD_MAX_LEVELS];
    // The compute rasterizer: of those meshlets, the ones each pass's task shader listed for
    // raster.comp (RasterEntry[] at FrameData::rasterListAddress) and their triangles.
    uint rasterTriangles;
    uint rasterMeshlets[2];
    uint unused[2]; // pads to 16 bytes
};

// The depth pyramid (render/culling.h): level 0 holds, per 2x2 pixels, the farthest depth of
// any sample (the least: depth is reversed, scene/camera.h); level k + 1 the farthest of 2x2
// texels of level k. Texel (x, y) of level k covers pixels [x, x + 1) * 2^(k + 1) exactly,
// edges clipped to the image.
struct PyramidLevel {
    uint offset; // first float of the level, after the header
    uint width, height;
    uint unused; // pads to 16 bytes
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
    uint64_t stateAddress;  // uint per draw: CULL_* bits (runs: then CULL_PAIR_* per pair)
    uint64_t groupsAddress; // uint per workgroup: draws (runs: runs) it lists
    uint64_t statsAddress;  // CullStats
    // Runs and mesh draws: per pair its draw (uint), and the box of every cluster of the
    // scene (CullBox).
    uint64_t pairsAddress;
    uint64_t clusterBoxesAddress;
    // Runs: the pair history, and the slot of history ends this pass uses (the early pass
    // reads it, the late pass writes it; see History above).
    uint64_t pairHistoryAddress;
    uint64_t historyEndsAddress;
    uint drawCount;
    uint phase;
    uint step;
    uint commandWords; // 5: VkDrawIndexedIndirectCommand, 4: MeshTaskCommand
    uint flags;        // CULL_MESH_DRAWS or CULL_CLUSTER_RUNS (none: whole vertex draws)
    uint pairCount;
};

// depth_pyramid.comp: PYRAMID_LEVELS_PER_PASS levels from `level` on, from the depth
// attachment (level 0) or the level below.
struct PyramidPush {
    uint64_t pyramidAddress;
    uvec2 extent; // pixels of the depth attachment
    uint level;
    uint samples;
    // The compute rasterizer's 64-bit samples (shared_visibility.h), whose depth counts as
    // the attachment's does; 0 for the other techniques.
    uint64_t rasterSamplesAddress;
};

#ifdef __cplusplus
static_assert(sizeof(DrawCull) == 80 && sizeof(CullBox) == 32);
static_assert(sizeof(CullStats) == 80);
static_assert(sizeof(PyramidHeader) == 16 + 16 * PYRAMID_MAX_LEVELS);
static_assert(sizeof(CullPush) == 120 && offsetof(CullPush, drawCount) == 96);
static_assert(sizeof(PyramidPush) == 32);
#endif

#endif
