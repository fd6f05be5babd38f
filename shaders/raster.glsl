// raster.glsl - the rules by which a compute shader rasterizes a triangle into the visibility
// buffer so that it covers exactly the samples the hardware's rasterizer covers (issue 46):
// corners snapped to the device's subpixel grid (round to nearest), a sample covered where
// every edge function of the snapped triangle is above zero, or zero on a top or left edge
// (framebuffer y down: a left edge goes up, a top edge is level with the inside below it),
// and depth from the plane of the snapped triangle. tests/cpu_raster.h holds the same rules on
// the CPU; tests/test_raster_rules.cpp checks both against lavapipe's ID images. Include
// buffers.glsl first (64-bit integers).
//
// Edge functions are 32-bit, relative to the first corner: a triangle may span at most
// RASTER_MAX_SPAN (shared_visibility.h) pixels each way at 8 subpixel bits (products stay
// under 2^31). Larger ones belong to the hardware path.

struct RasterSetup {
    ivec2 corner[3]; // snapped, in subpixels, ordered so that the inside is positive
    int area;        // twice the snapped triangle's area, in subpixels squared; 0: empty
    vec3 depth;      // the corners' depths, in the same order
    uint bits;       // subpixel bits
};

// Round to nearest on the grid of 2^bits subpixels a pixel (floor(x + 0.5), as the CPU's
// llround for the non-negative positions of the framebuffer).
ivec2 snapToGrid(vec2 pixels, uint bits) {
    return ivec2(floor(pixels * float(1u << bits) + 0.5));
}

int edgeFunction(ivec2 a, ivec2 b, ivec2 p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// `corners` in framebuffer pixels (y down), `depths` reversed (nearer is greater).
RasterSetup rasterSetup(vec2 corners[3], vec3 depths, uint bits) {
    RasterSetup s;
    s.bits = bits;
    for (int k = 0; k < 3; ++k) s.corner[k] = snapToGrid(corners[k], bits);
    s.depth = depths;
    s.area = edgeFunction(s.corner[0], s.corner[1], s.corner[2]);
    if (s.area < 0) { // one orientation, so the inside is where every edge is positive
        ivec2 c = s.corner[1];
        s.corner[1] = s.corner[2];
        s.corner[2] = c;
        s.depth = s.depth.xzy;
        s.area = -s.area;
    }
    return s;
}

// A sample on an edge belongs to a left edge (going up) or a top one (level, going right).
bool ownsEdge(ivec2 from, ivec2 to) {
    ivec2 d = to - from;
    return d.y < 0 || (d.y == 0 && d.x > 0);
}

bool edgeCovers(int e, ivec2 from, ivec2 to) {
    return e > 0 || (e == 0 && ownsEdge(from, to));
}

// Whether the triangle covers the sample at `at` (subpixels), and its depth there.
bool rasterCovers(RasterSetup s, ivec2 at, out float depth) {
    depth = 0.0;
    if (s.area == 0) return false;
    // Relative to the first corner, so that the products stay small (RASTER_MAX_SPAN).
    ivec2 p = at - s.corner[0];
    ivec2 c1 = s.corner[1] - s.corner[0], c2 = s.corner[2] - s.corner[0];
    int e01 = edgeFunction(ivec2(0), c1, p);
    int e12 = edgeFunction(c1, c2, p);
    int e20 = edgeFunction(c2, ivec2(0), p);
    if (!edgeCovers(e01, s.corner[0], s.corner[1]) || !edgeCovers(e12, s.corner[1], s.corner[2]) ||
        !edgeCovers(e20, s.corner[2], s.corner[0]))
        return false;
    // Each corner weighs by the edge function of the edge across from it.
    depth = (float(e12) * s.depth.x + float(e20) * s.depth.y + float(e01) * s.depth.z) /
            float(s.area);
    return true;
}

// Where sample `s` of `samples` lies in its pixel: the centre without MSAA, Vulkan's standard
// locations at 4x (the only counts the compute rasterizer runs at: ScenePass checks them).
vec2 sampleOffset(uint samples, uint s) {
    if (samples != 4u) return vec2(0.5);
    const vec2 at4[4] =
        vec2[4](vec2(0.375, 0.125), vec2(0.875, 0.375), vec2(0.125, 0.625), vec2(0.625, 0.875));
    return at4[s];
}

// The visibility buffer's 64-bit sample: depth above, the payload inverted below, so that
// atomicMax keeps the nearest surface (reversed depth: positive floats order as their bits)
// and, where two tie, the smaller payload, the one drawn first.
uint64_t visibilitySample(float depth, uint payload) {
    return (uint64_t(floatBitsToUint(depth)) << 32) | uint64_t(~payload);
}

// The nearer of a hardware sample (depth, payload) and a compute one (`computed`, 0 where the
// compute path covered nothing), by atomicMax's order: the greater depth, then the smaller
// payload. The hardware's background is depth 0 with any payload.
void nearerSample(uint64_t computed, inout float depth, inout uint payload) {
    if (computed == 0ul) return;
    float d = uintBitsToFloat(uint(computed >> 32));
    uint p = ~uint(computed);
    if (d > depth || (d == depth && p < payload)) {
        depth = d;
        payload = p;
    }
}
