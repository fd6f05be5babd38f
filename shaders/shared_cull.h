// shared_cull.h - culling and levels of detail on the GPU: the design in one table, then its
// constants and structs. Part of shared.h's family (include shared.h). render/culling.h
// records the passes; shaders/cull.comp (with cull_*.glsl) and scene.task run them.
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
// History: what the last frame's late (or frustum) test found may show, per pair: the
// CULL_PAIR_HISTORY bit of a cluster, the bit of a meshlet (meshletBits). It decides what
// the early pass draws. For runs, an object's early clusters are its first ones, up to its
// last cluster with history (its history end, a word per object), so that its clusters
// keep their order where two tie in depth; a mesh draw goes early where one of its meshlets
// has history, and the task shader draws those meshlets. Every technique, the floors
// included, culls by this.
// A still view (FRAME_VIEW_UNCHANGED: nothing moved since a frame culled in two passes)
// draws each cluster with history early by itself: one without lay wholly behind that
// frame's early depth, so behind its final depth, which this frame draws again; drawn late,
// it writes no sample and ties none, so no order can change.
//
// The phases (CullPush::phase, DrawPush::cullPhase), the steps cull.comp runs in each, for
// lists of runs and of whole draws, and what the task shader draws in each:
// clang-format off
// phase        when                    runs            draws        task shader draws
// NONE         culling off             -               [L] D P      every meshlet
// FRUSTUM      frustum culling         [L] D C RN RP   [L] D P      meshlets in view (history)
// EARLY        occlusion, first half   [L] D C RN RP   [L] D P      meshlets with history, in view
//   then the depth pyramid of the first half's depth
// LATE         occlusion, second half  D C RN RP       D M N P      mdi: those M chose; push: in
//                                                                   view, not behind the pyramid,
//                                                                   without history (history)
// FROZEN       freeze culling          nothing: the two lists of    meshlets with history
// FROZEN_LATE                          the last culled frame again  the same, of draws not early
// Steps: L levels (where FrameData::lodErrorPixels is above 0: a list holding every level of
// every object, mdi modes), D decide, C clusters, M meshlets, N count, P compact, RN runs
// count, RP runs compact (each described below); (history): what passed becomes the history.
// clang-format on
IDV_CONST CULL_PHASE_NONE = 0;
IDV_CONST CULL_PHASE_FRUSTUM = 1;
IDV_CONST CULL_PHASE_EARLY = 2;
IDV_CONST CULL_PHASE_LATE = 3;
IDV_CONST CULL_PHASE_FROZEN = 4;
IDV_CONST CULL_PHASE_FROZEN_LATE = 5;

// The steps (CullPush::step), each a dispatch over the list's draws or pairs:
// - levels: whether each draw is of the level its object draws (CULL_OTHER_LEVEL);
// - decide: each draw's bits for this pass, and a count per workgroup of the draws listed;
// - clusters (runs): each (draw, cluster) pair of a draw in play is tested by its own box;
// - meshlets (draws, late): each (draw, meshlet) pair of a draw whose box passed is tested
//   as the task shader would; what passed becomes history, what passed and was not drawn
//   early is what the late task shader draws (FrameData::lateMeshletWord);
// - count (draws, late): each workgroup's draws counted again after the meshlets;
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
// Runs: after the draws' words, a word of CULL_PAIR_* bits per (draw, cluster) pair, then
// the history end of every object: one more than the last of its pairs with history.
IDV_CONST CULL_PAIR_HISTORY = 1u; // passed the last late (or frustum) test
IDV_CONST CULL_PAIR_EARLY = 2u;   // drawn by this frame's early pass
IDV_CONST CULL_PAIR_NOW = 4u;     // listed by the current pass

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
    uint unused; // pads to 16 bytes
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
    uint64_t stateAddress;  // uint per draw: CULL_* bits (runs: then pairs, objects)
    uint64_t groupsAddress; // uint per workgroup: draws (runs: runs) it lists
    uint64_t statsAddress;  // CullStats
    // Runs and mesh draws: per pair its draw (uint), and the box of every cluster of the
    // scene (CullBox).
    uint64_t pairsAddress;
    uint64_t clusterBoxesAddress;
    uint drawCount;
    uint phase;
    uint step;
    uint commandWords; // 5: VkDrawIndexedIndirectCommand, 4: MeshTaskCommand
    uint flags;        // CULL_MESH_DRAWS or CULL_CLUSTER_RUNS (none: whole vertex draws)
    uint groupCount;   // workgroups over the draws
    uint pairCount;
    uint objectCount; // runs: the objects, whose history ends end the state buffer
};

// depth_pyramid.comp: PYRAMID_LEVELS_PER_PASS levels from `level` on, from the depth
// attachment (level 0) or the level below.
struct PyramidPush {
    uint64_t pyramidAddress;
    uvec2 extent; // pixels of the depth attachment
    uint level;
    uint samples;
};

#ifdef __cplusplus
static_assert(sizeof(DrawCull) == 80 && sizeof(CullBox) == 32);
static_assert(sizeof(CullStats) == 64);
static_assert(sizeof(PyramidHeader) == 16 + 16 * PYRAMID_MAX_LEVELS);
static_assert(sizeof(CullPush) == 112 && offsetof(CullPush, drawCount) == 80);
static_assert(sizeof(PyramidPush) == 24);
#endif

#endif
