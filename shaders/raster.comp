#version 460
// raster.comp - the compute rasterizer (the visbuffer-compute technique,
// render/compute_raster.h): rasterizes the meshlets the task shader listed for one pass
// (shared_visibility.h) into the 64-bit visibility samples, by raster.glsl's rules, so that
// each sample gets what the hardware would have written: the nearest triangle's depth and
// payload. A workgroup takes a meshlet at a time: its vertices placed and projected once, as
// scene.mesh places them, then a triangle per invocation over the samples of its bounds.
#include "buffers.glsl"
#include "raster.glsl"
#include "techniques/packed_ids.glsl"

layout(local_size_x = RASTER_GROUP_SIZE) in;

layout(push_constant, std430) uniform RasterBlock {
    RasterPush raster;
};

shared vec2 cornerPixel[MESHLET_MAX_VERTICES]; // framebuffer pixels, y down
shared float cornerDepth[MESHLET_MAX_VERTICES];

// As the pipeline takes scene.mesh's gl_Position to the framebuffer: divided by w, then the
// viewport's scale and offset (the whole framebuffer, depth 0..1).
void project(FrameData frame, ObjectData object, uint vertex, uint slot) {
    FloatsRef vertices = FloatsRef(frame.verticesAddress);
    uint base = vertex * 6u; // floats per Vertex
    vec3 position =
        vec3(vertices.values[base], vertices.values[base + 1u], vertices.values[base + 2u]);
    vec4 world = object.world * vec4(position, 1.0);
    vec4 clip = frame.viewProj * world;
    float invW = 1.0 / clip.w;
    vec2 scale = vec2(frame.viewport) * 0.5;
    cornerPixel[slot] = clip.xy * invW * scale + scale;
    cornerDepth[slot] = clip.z * invW;
}

// Every sample of the framebuffer the snapped triangle covers, by its pixels' rectangle.
void rasterize(FrameData frame, RasterSetup s, uint payload) {
    ivec2 lo = min(s.corner[0], min(s.corner[1], s.corner[2])) >> int(s.bits);
    ivec2 hi = max(s.corner[0], max(s.corner[1], s.corner[2])) >> int(s.bits);
    lo = max(lo, ivec2(0));
    hi = min(hi, ivec2(frame.viewport) - 1);
    RasterSamplesRef samples = RasterSamplesRef(frame.rasterSamplesAddress);
    int one = 1 << int(s.bits);
    for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x)
            for (uint k = 0u; k < raster.samples; ++k) {
                float depth;
                ivec2 at = ivec2(x, y) * one + snapToGrid(sampleOffset(raster.samples, k), s.bits);
                // Depth outside 0..1 is clipped away, and 0 is the cleared far plane.
                if (!rasterCovers(s, at, depth) || depth <= 0.0 || depth > 1.0) continue;
                uint index = (uint(y) * frame.viewport.x + uint(x)) * raster.samples + k;
                atomicMax(samples.values[index], visibilitySample(depth, payload));
            }
}

void drawMeshlet(FrameData frame, RasterEntry entry) {
    VisibilityDraw draw = VisibilityDrawsRef(frame.visibilityDrawsAddress).draws[entry.drawIndex];
    Meshlet meshlet = MeshletsRef(frame.meshletsAddress).meshlets[draw.firstMeshlet + entry.local];
    ObjectData object = ObjectsRef(frame.objectsAddress).objects[draw.objectIndex];
    uint vertexCount = meshlet.counts & 0xFFFFu;
    uint triangleCount = meshlet.counts >> 16;
    UintsRef data = UintsRef(frame.meshletDataAddress);
    for (uint i = gl_LocalInvocationIndex; i < vertexCount; i += RASTER_GROUP_SIZE)
        project(frame, object, data.values[meshlet.firstVertex + i], i);
    barrier();
    DrawData lookup;
    lookup.idsOffset = draw.idsOffset;
    lookup.idsWidth = draw.idsWidth;
    uint payloads = draw.triangleBase + entry.local * VIS_MESHLET_PAYLOADS;
    for (uint t = gl_LocalInvocationIndex; t < triangleCount; t += RASTER_GROUP_SIZE) {
        // Hidden parts' triangles are not drawn (scene.mesh collapses them).
        if ((frame.flags & FRAME_HIDING) != 0u) {
            uint part = lookupLocalPart(frame, lookup, meshlet.firstLocalTriangle + t);
            uint id = object.uniquePartOffset + part;
            if ((UintsRef(frame.hiddenAddress).values[id >> 5] & (1u << (id & 31u))) != 0u)
                continue;
        }
        uint corners = data.values[meshlet.firstTriangle + t];
        uvec3 c = uvec3(corners & 0xFFu, (corners >> 8) & 0xFFu, (corners >> 16) & 0xFFu);
        vec2 pixels[3] = vec2[3](cornerPixel[c.x], cornerPixel[c.y], cornerPixel[c.z]);
        vec3 depths = vec3(cornerDepth[c.x], cornerDepth[c.y], cornerDepth[c.z]);
        rasterize(frame, rasterSetup(pixels, depths, raster.subpixelBits), payloads + t);
    }
    barrier(); // the next meshlet's corners replace these
}

void main() {
    FrameData frame = FrameRef(raster.frameAddress).frame;
    RasterListRef list = RasterListRef(frame.rasterListAddress);
    uint count = min(CullStatsRef(frame.cullStatsAddress).stats.rasterMeshlets[raster.list],
                     frame.rasterCapacity);
    uint first = raster.list * frame.rasterCapacity;
    for (uint e = gl_WorkGroupID.x; e < count; e += gl_NumWorkGroups.x)
        drawMeshlet(frame, list.entries[first + e]);
}
