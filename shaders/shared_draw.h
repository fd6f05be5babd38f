// shared_draw.h - what one draw of a draw list reads: its DrawData, the push block that
// carries it (or its index), meshlets, and the indirect commands the mdi modes and culling
// write. Part of shared.h's family (include shared.h).
#ifndef IDVIEW_SHARED_DRAW_H
#define IDVIEW_SHARED_DRAW_H

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

// Push constants. The frame address is pushed once per frame at offset 0; in `push` mode
// each draw then pushes the fields of `draw` that changed since the previous draw. Where
// cull.comp lists the draws, each pass pushes the list it draws and its phase.
struct DrawPush {
    uint64_t frameAddress; // FrameData
    DrawData draw;
    // The list drawn where cull.comp wrote it: MeshTaskCommand[] for the mesh techniques,
    // RunCommand[] for lists of cluster runs
    uint64_t commandsAddress;
    uint cullPhase; // CULL_PHASE_*: what the task shader lets through
    uint unused;    // pads the block to 8 bytes
};
IDV_CONST DRAW_PUSH_DRAW_OFFSET = 8;
IDV_CONST DRAW_PUSH_CULL_OFFSET = 40; // commandsAddress, cullPhase

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

// What the mesh techniques' indirect draws hold where the task shader runs: task
// workgroups (TASK_GROUP_SIZE meshlets each), then the draw.
struct MeshTaskCommand {
    uint groupCountX;
    uint groupCountY;
    uint groupCountZ;
    uint drawIndex;
};

#ifdef __cplusplus
static_assert(sizeof(DrawData) == 32 && sizeof(Meshlet) == 16);
static_assert(sizeof(DrawPush) == 56 && offsetof(DrawPush, draw) == DRAW_PUSH_DRAW_OFFSET);
static_assert(offsetof(DrawPush, commandsAddress) == DRAW_PUSH_CULL_OFFSET);
static_assert(sizeof(RunCommand) == 24 && sizeof(MeshTaskCommand) == 16);
#endif

#endif
