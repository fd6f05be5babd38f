#version 460
// compose.comp - the picture shown, composed from the scene pass's kept images: its shaded
// colour, the resolved ID image and depth. Parts take their tint by visibility (when set),
// the hovered part blinks, the selection is tinted, and part edges and outlines are drawn
// from the ID image, with no line geometry: they cost the same for every technique and
// follow exactly the parts the ID attachment shows. Because the scene pass leaves its images
// untouched, a viewer at rest runs this pass alone when the hover, the blink, the selection
// or the tint changes, and for a step of the blink only over the tiles of the hovered part
// (shared_id_passes.h has the rules).
#extension GL_KHR_shader_subgroup_vote : require

#include "buffers.glsl"

layout(local_size_x = ID_PASS_TILE, local_size_y = ID_PASS_TILE) in;

layout(set = 0, binding = 0, r32ui) uniform readonly uimage2D ids;
layout(set = 0, binding = 1, rgba8) uniform writeonly image2D color;
layout(set = 0, binding = 2, rgba8) uniform readonly image2D shaded;
#if IDV_COMPOSE_MSAA
layout(set = 0, binding = 3) uniform sampler2DMS depthImage;
#else
layout(set = 0, binding = 3) uniform sampler2D depthImage;
#endif

layout(push_constant, std430) uniform ComposeBlock {
    ComposePush compose;
};

// The widest window (the selection's outline) reaches LO pixels up-left and HI down-right;
// the workgroup loads its tile with that margin once, so each pixel reads the image once.
const int WIDEST = int(EDGE_WIDTH_MAX) + 2;
const int LO = WIDEST / 2;
const int HI = (WIDEST + 1) / 2;
const int SPAN = int(ID_PASS_TILE) + LO + HI;
shared uint tileIds[SPAN * SPAN];
shared bool tileSelected[SPAN * SPAN];

int at(ivec2 p) {
    return p.y * SPAN + p.x;
}

// What the window of width `w` around the tile position `p` holds.
struct Window {
    bool twoIds;        // two different IDs
    bool selectedMixed; // a selected and an unselected ID
    bool hoveredMixed;  // the hovered ID and another one
};

Window look(ivec2 p, int w, uint hovered) {
    const int lo = w / 2, hi = (w + 1) / 2;
    const uint first = tileIds[at(p - ivec2(lo))];
    bool differ = false, selected = false, unselected = false, hover = false, other = false;
    for (int y = -lo; y <= hi; ++y)
        for (int x = -lo; x <= hi; ++x) {
            const int i = at(p + ivec2(x, y));
            const uint id = tileIds[i];
            differ = differ || id != first;
            selected = selected || tileSelected[i];
            unselected = unselected || !tileSelected[i];
            hover = hover || id == hovered;
            other = other || id != hovered;
        }
    return Window(differ, selected && unselected, hover && other);
}

bool isSelected(uint id) {
    return compose.selectedAddress != 0ul && id != BACKGROUND_ID &&
           (UintsRef(compose.selectedAddress).values[id >> 5] & (1u << (id & 31u))) != 0u;
}

// Hovered: the colour turned towards its inverse by the blink's weight. Inverting a mid-grey
// gives the same grey, so where the inverse is too close the highlight goes to black or
// white instead: a highlighted pixel always changes visibly. Selected: a steady amber tint.
vec3 highlightHovered(vec3 color, float weight) {
    vec3 target = vec3(1.0) - color;
    vec3 gap = abs(target - color);
    if (max(gap.r, max(gap.g, gap.b)) < 0.25)
        target = dot(color, vec3(0.299, 0.587, 0.114)) > 0.5 ? vec3(0.0) : vec3(1.0);
    return mix(color, target, weight);
}

vec3 highlightSelected(vec3 color) {
    vec3 amber = vec3(1.0, 0.72, 0.1);
    vec3 tinted = mix(color, amber, 0.65);
    // Amber parts would hardly change: shift them towards deep blue instead.
    if (distance(tinted, color) < 0.2) tinted = mix(color, vec3(0.1, 0.2, 0.9), 0.65);
    return tinted;
}

// The part's tint by visibility: its colour mixed towards the tint by the tint's alpha.
vec3 tintByVisibility(vec3 color, uint id) {
    if (compose.tintAddress == 0ul || id == BACKGROUND_ID) return color;
    const vec4 tint = unpackUnorm4x8(UintsRef(compose.tintAddress).values[id]);
    return mix(color, tint.rgb, tint.a);
}

// The part under the hover pixel and its depth, where sample 0 decides as in the resolve of
// the ID image: the same value the scene pass's pick would atomicMin there (shared.h).
uint64_t hoverValue(uint id) {
    if (id == BACKGROUND_ID) return PICK_NONE;
    // Level 0 of a single-sample image, or sample 0 of a multisampled one.
    float depth = texelFetch(depthImage, ivec2(compose.hoverPixel), 0).r;
    // The compute rasterizer's sample 0 there, where it drew the part shown.
    if (compose.rasterSamplesAddress != 0ul) {
        uint index =
            (compose.hoverPixel.y * compose.extent.x + compose.hoverPixel.x) * compose.samples;
        uint64_t computed = RasterSamplesRef(compose.rasterSamplesAddress).values[index];
        depth = max(depth, uintBitsToFloat(uint(computed >> 32)));
    }
    return pickKey(depth, id);
}

// COMPOSE_WHOLE: one invocation of each subgroup that sees the hovered part adds the tile.
void addToBox(bool hoveredHere, uvec2 tile) {
    if (!subgroupAny(hoveredHere) || !subgroupElect()) return;
    HoverBoxRef ref = HoverBoxRef(compose.boxAddress);
    atomicMin(ref.box.tileMin.x, tile.x);
    atomicMin(ref.box.tileMin.y, tile.y);
    atomicMax(ref.box.tileMax.x, tile.x);
    atomicMax(ref.box.tileMax.y, tile.y);
}

void main() {
    const bool whole = compose.step == COMPOSE_WHOLE;
    const uvec2 tile = gl_WorkGroupID.xy + (whole ? uvec2(0u) : compose.tileOrigin);
    const bool outline = (compose.flags & EDGE_SELECTED) != 0u;
    // Without lines no pixel looks at its neighbours, so the tile is not loaded: a viewer at
    // rest composes the blink of the hovered part a few times a second, on a CPU device too.
    const bool lines = compose.flags != 0u;
    const ivec2 origin = ivec2(tile * ID_PASS_TILE) - ivec2(LO);
    const ivec2 last = ivec2(compose.extent) - 1;
    // Outside the image the border pixel repeats: the image's edge is no part edge. (The
    // flags are the same for the whole dispatch, so the barrier stays in uniform flow.)
    if (lines) {
        for (uint i = gl_LocalInvocationIndex; i < uint(SPAN * SPAN);
             i += ID_PASS_TILE * ID_PASS_TILE) {
            const ivec2 p = clamp(origin + ivec2(int(i) % SPAN, int(i) / SPAN), ivec2(0), last);
            const uint id = imageLoad(ids, p).r;
            tileIds[i] = id;
            tileSelected[i] = outline && isSelected(id);
        }
        barrier();
    }
    const uvec2 pixel = tile * ID_PASS_TILE + gl_LocalInvocationID.xy;
    if (any(greaterThanEqual(pixel, compose.extent))) return;

    const bool hovering = all(lessThan(compose.hoverPixel, compose.extent));
    const uint hovered = hovering ? imageLoad(ids, ivec2(compose.hoverPixel)).r : BACKGROUND_ID;
    if (hovering && pixel == compose.hoverPixel)
        Uint64Ref(compose.hoverAddress).value = hoverValue(hovered);

    const ivec2 p = ivec2(gl_LocalInvocationID.xy) + ivec2(LO);
    const uint id = lines ? tileIds[at(p)] : imageLoad(ids, ivec2(pixel)).r;
    const bool hoveredHere = id == hovered && id != BACKGROUND_ID;
    // The hovered pixel's tile too: it writes what is under the pixel in every step.
    if (whole) addToBox(hoveredHere || pixel == compose.hoverPixel, tile);
    vec3 rgb = tintByVisibility(imageLoad(shaded, ivec2(pixel)).rgb, id);
    if (hoveredHere) rgb = highlightHovered(rgb, compose.blink);
    if (isSelected(id)) rgb = highlightSelected(rgb);
    vec4 result = vec4(rgb, 1.0);
    if (!lines) {
        imageStore(color, ivec2(pixel), result);
        return;
    }
    // The selection's outline first, then the hovered part's, then plain edges.
    const int w = int(clamp(compose.width, 1u, EDGE_WIDTH_MAX));
    const uint outlined = (compose.flags & EDGE_HOVERED) != 0u ? hovered : BACKGROUND_ID;
    if (outline && look(p, w + 2, outlined).selectedMixed)
        result = unpackUnorm4x8(compose.selectColor);
    else if (outlined != BACKGROUND_ID && look(p, w + 1, outlined).hoveredMixed)
        result = unpackUnorm4x8(compose.hoverColor);
    else if ((compose.flags & EDGE_LINES) != 0u && look(p, w, outlined).twoIds)
        result = unpackUnorm4x8(compose.lineColor);
    imageStore(color, ivec2(pixel), result);
}
