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

// Keeps `value` at sample `index` where it is nearer than what is there. The plain load first
// skips the atomic where the sample already holds a nearer surface (values only grow within a
// frame, so a stale load is never too large).
void keepNearer(RasterSamplesRef samples, uint index, uint64_t value) {
    if (value > samples.values[index]) atomicMax(samples.values[index], value);
}

// Every sample of the framebuffer the snapped triangle covers, by its pixels' rectangle: the
// edge functions of raster.glsl's rasterCovers, stepped a pixel at a time (exact integers,
// so each sample gets the same values, coverage and depth rasterCovers gives it).
void rasterize(FrameData frame, RasterSetup s, uint payload) {
    if (s.area == 0) return;
    ivec2 lo = max(min(s.corner[0], min(s.corner[1], s.corner[2])) >> int(s.bits), ivec2(0));
    ivec2 hi = min(max(s.corner[0], max(s.corner[1], s.corner[2])) >> int(s.bits),
                   ivec2(frame.viewport) - 1);
    if (any(greaterThan(lo, hi))) return;
    RasterSamplesRef samples = RasterSamplesRef(frame.rasterSamplesAddress);
    int one = 1 << int(s.bits);
    ivec2 c1 = s.corner[1] - s.corner[0], c2 = s.corner[2] - s.corner[0];
    // A sample is covered where each edge function reaches its edge's least: 0 on an edge the
    // top-left rule gives the triangle, 1 elsewhere (raster.glsl's edgeCovers).
    ivec3 least = ivec3(ownsEdge(s.corner[0], s.corner[1]) ? 0 : 1,
                        ownsEdge(s.corner[1], s.corner[2]) ? 0 : 1,
                        ownsEdge(s.corner[2], s.corner[0]) ? 0 : 1);
    // Per pixel right and down, for e01, e12 and e20 (raster.glsl's order).
    ivec3 stepX = ivec3(-c1.y, c1.y - c2.y, c2.y) * one;
    ivec3 stepY = ivec3(c1.x, c2.x - c1.x, -c2.x) * one;
    for (uint k = 0u; k < raster.samples; ++k) {
        ivec2 p = lo * one + snapToGrid(sampleOffset(raster.samples, k), s.bits) - s.corner[0];
        ivec3 row = ivec3(edgeFunction(ivec2(0), c1, p), edgeFunction(c1, c2, p),
                          edgeFunction(c2, ivec2(0), p));
        for (int y = lo.y; y <= hi.y; ++y, row += stepY) {
            ivec3 e = row;
            for (int x = lo.x; x <= hi.x; ++x, e += stepX) {
                if (any(lessThan(e, least))) continue;
                float depth =
                    (float(e.y) * s.depth.x + float(e.z) * s.depth.y + float(e.x) * s.depth.z) /
                    float(s.area);
                // Depth outside 0..1 is clipped away, and 0 is the cleared far plane.
                if (depth <= 0.0 || depth > 1.0) continue;
                uint index = (uint(y) * frame.viewport.x + uint(x)) * raster.samples + k;
                keepNearer(samples, index, visibilitySample(depth, payload));
            }
        }
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
