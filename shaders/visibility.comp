#version 460
// visibility.comp - the visibility buffer's end of the scene pass (render/visibility.h): the
// pass wrote per sample its depth and the payload of the triangle covering it
// (shared_visibility.h); here each sample's triangle names its part, through the part per
// meshlet triangle mesh-fs reads, and is shaded as scene.frag shades it, at the pixel's
// centre as the rasterizer evaluates a fragment. With MSAA the samples are resolved as the
// pass would (colour averaged, the ID of sample 0), and the pick is read at sample 0.
#extension GL_EXT_samplerless_texture_functions : require

#include "buffers.glsl"
#include "raster.glsl"
#include "shading.glsl"
#include "techniques/packed_ids.glsl"

layout(local_size_x = ID_PASS_TILE, local_size_y = ID_PASS_TILE) in;

#if IDV_RESOLVE_MSAA
layout(set = 0, binding = 0) uniform texture2DMS depth;
layout(set = 0, binding = 1) uniform utexture2DMS samplePayloads;
layout(set = 0, binding = 2) uniform texture2DMS sampleColors; // X-ray's, over black
#else
layout(set = 0, binding = 0) uniform texture2D depth;
#endif
// 1x: the pass's own images (payloads and X-ray's colour), read, then written over.
layout(set = 0, binding = 3, r32ui) uniform uimage2D ids;
layout(set = 0, binding = 4, rgba8) uniform image2D color;

layout(push_constant, std430) uniform VisibilityBlock {
    VisibilityPush vis;
};

// One sample's surface: its part and its colour.
struct Shaded {
    uint id;
    vec3 color;
};

// The triangle's corners placed in the world (relative to the frame's origin), their normals,
// and their clip positions.
struct Corners {
    vec3 world[3];
    vec3 normal[3];
    vec3 clip[3]; // x, y, w
};

Corners cornersOf(FrameData frame, ObjectData object, Meshlet meshlet, uint triangle) {
    Corners c;
    UintsRef data = UintsRef(frame.meshletDataAddress);
    FloatsRef vertices = FloatsRef(frame.verticesAddress);
    uint corners = data.values[meshlet.firstTriangle + triangle];
    for (uint k = 0u; k < 3u; ++k) {
        uint v = data.values[meshlet.firstVertex + ((corners >> (8u * k)) & 0xFFu)] * 6u;
        vec3 position = vec3(vertices.values[v], vertices.values[v + 1u], vertices.values[v + 2u]);
        vec3 normal =
            vec3(vertices.values[v + 3u], vertices.values[v + 4u], vertices.values[v + 5u]);
        c.world[k] = (object.world * vec4(position, 1.0)).xyz;
        c.normal[k] = mat3(object.normalMatrix) * normal;
        c.clip[k] = (frame.viewProj * vec4(c.world[k], 1.0)).xyw;
    }
    return c;
}

// Perspective-correct barycentrics of the point of the triangle seen at `pixel`'s centre:
// the corners' (x, y, w) as the columns of a matrix take the barycentrics to the pixel's
// homogeneous screen point, so its inverse takes that point back, up to a scale the sum
// removes. Exact in perspective and ortho alike, and with corners behind the eye.
vec3 barycentrics(FrameData frame, Corners c, uvec2 pixel) {
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(frame.viewport) * 2.0 - 1.0;
    mat3 m = mat3(c.clip[0], c.clip[1], c.clip[2]);
    vec3 b = inverse(m) * vec3(ndc, 1.0);
    return b / (b.x + b.y + b.z);
}

// Where a section opens a solid, the first surface seen through the cut is the inside of the
// cut part: the triangle's own normal, turned to the side its vertex normals point to, faces
// away from the viewer (scene.frag's backFacing, from the corners instead of derivatives).
bool backFacing(FrameData frame, Corners c, vec3 normal, vec3 worldPos) {
    vec3 faceNormal = cross(c.world[1] - c.world[0], c.world[2] - c.world[0]);
    if (dot(faceNormal, normal) < 0.0) faceNormal = -faceNormal;
    return dot(faceNormal, toViewer(frame, worldPos)) < 0.0;
}

Shaded shade(FrameData frame, uint payload, uvec2 pixel) {
    uint slot = payload / VIS_MESHLET_PAYLOADS;
    uint triangle = payload % VIS_MESHLET_PAYLOADS;
    uint drawIndex = UintsRef(frame.visibilityBlocksAddress).values[slot];
    VisibilityDraw draw = VisibilityDrawsRef(frame.visibilityDrawsAddress).draws[drawIndex];
    uint local = slot - draw.triangleBase / VIS_MESHLET_PAYLOADS;
    Meshlet meshlet = MeshletsRef(frame.meshletsAddress).meshlets[draw.firstMeshlet + local];
    ObjectData object = ObjectsRef(frame.objectsAddress).objects[draw.objectIndex];
    DrawData lookup;
    lookup.idsOffset = draw.idsOffset;
    lookup.idsWidth = draw.idsWidth;
    uint localPart = lookupLocalPart(frame, lookup, meshlet.firstLocalTriangle + triangle);
    uint id = object.uniquePartOffset + localPart;
    vec3 base = drawBase(frame, object, draw.drawIndex, draw.lodLevel);
    base = partBase(frame, object, localPart, id, base);

    Corners c = cornersOf(frame, object, meshlet, triangle);
    vec3 b = barycentrics(frame, c, pixel);
    vec3 worldPos = b.x * c.world[0] + b.y * c.world[1] + b.z * c.world[2];
    vec3 normal = b.x * c.normal[0] + b.y * c.normal[1] + b.z * c.normal[2];
    bool cap = (vis.flags & VIS_SECTION) != 0u && backFacing(frame, c, normal, worldPos);
    vec3 rgb = cap ? capColor(base, vec2(pixel) + 0.5)
                   : headlight(base, normal, toViewer(frame, worldPos));
    return Shaded(id, rgb);
}

// Sample `s`'s depth and payload (BACKGROUND_ID where no triangle covered it: its depth is
// still the clear value 0, the far plane of reversed depth), and X-ray's colour over black.
struct Sample {
    float depth;
    uint payload;
    vec4 xray;
};

Sample sampleAt(FrameData frame, ivec2 p, int s) {
    Sample x;
#if IDV_RESOLVE_MSAA
    x.depth = texelFetch(depth, p, s).r;
    x.payload = x.depth != 0.0 ? texelFetch(samplePayloads, p, s).r : BACKGROUND_ID;
    x.xray = (vis.flags & VIS_XRAY) != 0u ? texelFetch(sampleColors, p, s) : vec4(0, 0, 0, 1);
#else
    x.depth = texelFetch(depth, p, 0).r;
    x.payload = x.depth != 0.0 ? imageLoad(ids, p).r : BACKGROUND_ID;
    x.xray = (vis.flags & VIS_XRAY) != 0u ? imageLoad(color, p) : vec4(0, 0, 0, 1);
#endif
    // The compute rasterizer's sample, where it drew the nearer surface.
    if (frame.rasterSamplesAddress != 0ul) {
        uint index = (uint(p.y) * vis.extent.x + uint(p.x)) * vis.samples + uint(s);
        nearerSample(RasterSamplesRef(frame.rasterSamplesAddress).values[index], x.depth,
                     x.payload);
    }
    return x;
}

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), vis.extent))) return;
    FrameData frame = FrameRef(vis.frameAddress).frame;
    vec3 sum = vec3(0.0);
    uint id0 = BACKGROUND_ID;
    float depth0 = 0.0;
    // Samples of one triangle are shaded once: the rasterizer runs one fragment per pixel.
    Shaded last = Shaded(BACKGROUND_ID, vis.background.rgb);
    uint lastPayload = BACKGROUND_ID;
    for (int s = 0; s < int(vis.samples); ++s) {
        const Sample x = sampleAt(frame, p, s);
        if (x.payload != lastPayload) {
            last = x.payload == BACKGROUND_ID ? Shaded(BACKGROUND_ID, vis.background.rgb)
                                              : shade(frame, x.payload, uvec2(p));
            lastPayload = x.payload;
        }
        // X-ray's layers over the picture: what they added, and what shows through of it.
        sum += last.color * x.xray.a + x.xray.rgb;
        if (s == 0) {
            id0 = last.id;
            depth0 = x.depth;
        }
    }
    imageStore(ids, p, uvec4(id0));
    imageStore(color, p, vec4(sum / float(vis.samples), 1.0));
    // The pick: the part sample 0 shows, with its depth, as scene.frag's atomicMin leaves it.
    if (uvec2(p) == frame.pickPixel && id0 != BACKGROUND_ID)
        PickRef(frame.pickAddress).pick.current = pickKey(depth0, id0);
}
