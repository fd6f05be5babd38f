// shared_visibility.h - the visibility buffer (the visbuffer technique, render/visibility.h):
// the scene pass writes, per sample, depth and a payload naming the triangle that covers it;
// a compute pass then finds each sample's part, shades it and resolves MSAA. Part of
// shared.h's family (include shared.h).
#ifndef IDVIEW_SHARED_VISIBILITY_H
#define IDVIEW_SHARED_VISIBILITY_H

// The payload: a draw's meshlets take VIS_MESHLET_PAYLOADS payloads each, in the draw's
// meshlet order, from the draw's base (VisibilityDraw::triangleBase, a multiple of it); a
// triangle's payload is its meshlet's first plus its index in the meshlet. So a payload's
// meshlet slot belongs to one draw, and its draw is one load away (FrameData::
// visibilityBlocksAddress: per slot, its draw). BACKGROUND_ID is never a payload.
IDV_CONST VIS_MESHLET_PAYLOADS = 128; // at least MESHLET_MAX_TRIANGLES, a power of two

// What the mesh shader and the shading pass read of a draw (FrameData::visibilityDrawsAddress),
// wherever the per-draw mode keeps its DrawData.
struct VisibilityDraw {
    uint objectIndex;
    uint idsOffset; // DrawData::idsOffset: the part per meshlet triangle (packed_ids.glsl)
    uint idsWidth;
    uint firstMeshlet; // DrawData::firstElement
    uint triangleBase; // the payload of its first meshlet's first triangle
    uint drawIndex;
    uint lodLevel;
    uint unused; // pads to 32 bytes
};

// VisibilityPush::flags.
IDV_CONST VIS_XRAY = 1u;    // X-ray's pass accumulated over black: lay it over the picture
IDV_CONST VIS_SECTION = 2u; // section planes cut: back faces seen through the cut are caps

// The shading pass's push block (visibility.comp).
struct VisibilityPush {
    vec4 background;       // the clear colour, as the colour image stores it
    uint64_t frameAddress; // FrameData, whose visibility*Address name the draw list's data
    uvec2 extent;
    uint samples;
    uint flags;     // VIS_*
    uint unused[2]; // pads to 16 bytes
};

// The compute rasterizer (the visbuffer-compute technique, render/compute_raster.h): the task
// shader sends a meshlet whose triangles project small (FrameData::rasterTrianglePixels) to
// a list of its pass instead of the mesh shader; raster.comp then rasterizes the list's
// meshlets by shaders/raster.glsl's rules into the 64-bit samples (depth << 32 | ~payload) at
// FrameData::rasterSamplesAddress, one per framebuffer sample ((y * width + x) * samples +
// s), with atomicMax. The hardware path's depth and payloads stay in the pass's attachments;
// whoever reads a sample (the shading pass, the depth pyramid, the hover) takes the nearer of
// the two, the smaller payload where they tie, as atomicMax would.
// raster.glsl's 32-bit edge functions hold triangles of up to this many pixels each way.
IDV_CONST RASTER_MAX_SPAN = 64;
IDV_FLOAT RASTER_ALL = 1.0e30;      // FrameData::rasterTrianglePixels: every meshlet it can draw
IDV_CONST RASTER_GROUP_SIZE = 64;   // raster.comp: invocations per meshlet
IDV_CONST RASTER_GROUPS_MAX = 8192; // raster.comp's workgroups, each looping over the list

// A listed meshlet: its draw and its position in the draw's meshlet list.
struct RasterEntry {
    uint drawIndex;
    uint local;
};

// raster.comp's push block: the frame, and which pass's list it draws.
struct RasterPush {
    uint64_t frameAddress;
    uint list; // 0: the early (or only) pass's, 1: the late one's
    uint samples;
    uint subpixelBits; // the device's subPixelPrecisionBits
    uint unused[3];    // pads to 16 bytes
};

#ifdef __cplusplus
static_assert(sizeof(VisibilityDraw) == 32);
static_assert(sizeof(RasterEntry) == 8 && sizeof(RasterPush) == 32);
static_assert(MESHLET_MAX_TRIANGLES <= VIS_MESHLET_PAYLOADS &&
              (VIS_MESHLET_PAYLOADS & (VIS_MESHLET_PAYLOADS - 1)) == 0);
static_assert(sizeof(VisibilityPush) == 48 && offsetof(VisibilityPush, extent) == 24);
#endif

#endif
