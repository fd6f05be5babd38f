#version 460
// edges.comp - part edges and outlines drawn from the resolved ID image into the colour
// image, after the scene pass: no line geometry, so they cost the same for every technique
// and follow exactly the parts the ID attachment shows. The rule is in shared.h (EdgePush).
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_buffer_reference : require

#include "shared.h"

layout(local_size_x = ID_PASS_TILE, local_size_y = ID_PASS_TILE) in;

layout(set = 0, binding = 0, r32ui) uniform readonly uimage2D ids;
layout(set = 0, binding = 1, rgba8) uniform writeonly image2D color;

layout(push_constant, std430) uniform EdgeBlock {
    EdgePush edge;
};

layout(buffer_reference, std430, buffer_reference_align = 4) readonly buffer PartBits {
    uint words[];
};
layout(buffer_reference, std430, buffer_reference_align = 8) readonly buffer PickLast {
    PickData pick;
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

void main() {
    const bool outlineSelected = (edge.flags & EDGE_SELECTED) != 0u && edge.selectedAddress != 0ul;
    const ivec2 origin = ivec2(gl_WorkGroupID.xy * ID_PASS_TILE) - ivec2(LO);
    const ivec2 last = ivec2(edge.extent) - 1;
    // Outside the image the border pixel repeats: the image's edge is no part edge.
    for (uint i = gl_LocalInvocationIndex; i < uint(SPAN * SPAN);
         i += ID_PASS_TILE * ID_PASS_TILE) {
        const ivec2 p = clamp(origin + ivec2(int(i) % SPAN, int(i) / SPAN), ivec2(0), last);
        const uint id = imageLoad(ids, p).r;
        tileIds[i] = id;
        tileSelected[i] =
            outlineSelected && id != BACKGROUND_ID &&
            (PartBits(edge.selectedAddress).words[id >> 5] & (1u << (id & 31u))) != 0u;
    }
    barrier();
    const uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, edge.extent))) return;

    const ivec2 p = ivec2(gl_LocalInvocationID.xy) + ivec2(LO);
    const int w = int(clamp(edge.width, 1u, EDGE_WIDTH_MAX));
    uint hovered = BACKGROUND_ID;
    if ((edge.flags & EDGE_HOVERED) != 0u && edge.pickAddress != 0ul)
        hovered = uint(PickLast(edge.pickAddress).pick.last); // PICK_NONE: the background's
    // The selection's outline first, then the hovered part's, then plain edges.
    if (outlineSelected && look(p, w + 2, hovered).selectedMixed)
        imageStore(color, ivec2(pixel), edge.selectColor);
    else if (hovered != BACKGROUND_ID && look(p, w + 1, hovered).hoveredMixed)
        imageStore(color, ivec2(pixel), edge.hoverColor);
    else if ((edge.flags & EDGE_LINES) != 0u && look(p, w, hovered).twoIds)
        imageStore(color, ivec2(pixel), edge.lineColor);
}
