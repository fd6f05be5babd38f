// shared_id_passes.h - the passes over the resolved ID image, recorded after the scene pass
// (render/id_passes.h), and the compute clear path's resolve (render/resolve.h). Part of
// shared.h's family (include shared.h). All run in 16x16 workgroups, one invocation per pixel.
#ifndef IDVIEW_SHARED_ID_PASSES_H
#define IDVIEW_SHARED_ID_PASSES_H

IDV_CONST ID_PASS_TILE = 16;
// compose.comp writes the picture shown from the scene pass's shaded colour, its ID image
// and its depth, which the pass leaves as they are:
// - each part is mixed towards its tint by visibility (tintAddress, when not 0), then the
//   hovered part (the ID at hoverPixel) is turned towards its inverted colour by `blink`
//   (0: not at all), then the selected parts are tinted;
// - edges (EDGE_LINES): a pixel is drawn in a line colour when the square window of `width`
//   pixels starting width/2 pixels up-left of it and ending (width+1)/2 down-right holds two
//   different IDs (the background is an ID too). The selection's outline (EDGE_SELECTED)
//   takes width + 2 and a window holding selected and unselected IDs; the hovered part's
//   (EDGE_HOVERED) width + 1. The tile it reads holds the largest window's margin:
//   EDGE_WIDTH_MAX + 2 wide;
// - the part and depth at hoverPixel go to hoverAddress, encoded as the scene pass's pick
//   (PickData), so a viewer at rest learns what the cursor is over without a scene pass.
IDV_CONST EDGE_WIDTH_MAX = 3;
IDV_CONST EDGE_LINES = 1u;    // ComposePush::flags: draw part edges
IDV_CONST EDGE_SELECTED = 2u; // outline the selected parts
IDV_CONST EDGE_HOVERED = 4u;  // outline the hovered part
// ComposePush::step. Between two steps of the blink only the hovered part's pixels change,
// so a viewer at rest composes again just the tiles that hold them:
// - COMPOSE_WHOLE: every tile; those holding the hovered part or the hovered pixel go into
//   the HoverBox at boxAddress (reset before);
// - COMPOSE_TILES: the tiles from tileOrigin on, one workgroup each (the box, once the host
//   has read it), computed exactly as in COMPOSE_WHOLE.
IDV_CONST COMPOSE_WHOLE = 0u;
IDV_CONST COMPOSE_TILES = 1u;
// The line colours are display-encoded RGBA8 (packUnorm4x8 on both sides): the colour image
// is 8-bit UNORM, so a byte reaches it exactly as the float it stood for did.
struct ComposePush {
    uint lineColor;           // written where an edge is
    uint selectColor;         // the selection's outline
    uint hoverColor;          // the hovered part's outline
    uint width;               // 1 to EDGE_WIDTH_MAX
    uint64_t selectedAddress; // bitset, or 0
    uint64_t hoverAddress;    // uint64_t written: the part and depth at hoverPixel
    uint64_t boxAddress;      // HoverBox, COMPOSE_WHOLE
    // Per unique part, a display-encoded RGBA8 its pixels are mixed towards by its alpha
    // (0: untouched); the Visibility section's tint by visibility. 0: no tint at all.
    uint64_t tintAddress;
    // The compute rasterizer's 64-bit samples (shared_visibility.h), which hold the depth of
    // what it drew; 0 for the other techniques.
    uint64_t rasterSamplesAddress;
    uvec2 extent;
    uvec2 hoverPixel; // x NO_PICK (or outside the image): nothing hovered
    uvec2 tileOrigin; // COMPOSE_TILES: the first tile
    uint flags;
    float blink;  // the hovered part's highlight weight, 0..1 (render/blink.h)
    uint step;    // COMPOSE_WHOLE or COMPOSE_TILES
    uint samples; // per pixel, of rasterSamplesAddress's
};
// The tiles (ID_PASS_TILE pixels square) holding the hovered part and pixel, inclusive:
// reset to tileMin 0xffffffff and tileMax 0, so an empty box has tileMin > tileMax.
struct HoverBox {
    uvec2 tileMin;
    uvec2 tileMax;
};

// part_set.comp: every unique part ID in an inclusive pixel rectangle of the ID image goes
// into a bitset, and each bit set for the first time counts once: PartSetResult::count.
struct PartSetPush {
    uint64_t resultAddress; // PartSetResult
    uvec2 rectMin;          // inclusive, pixels
    uvec2 rectMax;          // inclusive
    uint words;             // bitset words: ceil(unique parts / 32)
    uint unused;            // pads to 8 bytes
};
struct PartSetResult {
    uint count;
    uint unused[3];
    // followed by `words` uints of bitset
};

// resolve.comp, the compute clear path's end of the scene pass (render/resolve.h): the pass
// cleared depth alone, so a sample whose depth is still the clear value (0, reversed depth)
// was covered by no triangle, and its colour and ID are whatever the images held. Per pixel:
// the ID is sample 0's where sample 0 is covered, else BACKGROUND_ID (integer IDs resolve to
// sample 0, as the pass path's resolve does); the colour is the average of the samples, each
// uncovered one counted as `background`. At 1x the images are the pass's own and only
// uncovered pixels are written.
IDV_CONST RESOLVE_KEEP_COLOR = 1u; // the pass cleared colour (X-ray blends over it): average it
IDV_CONST RESOLVE_NO_IDS = 2u;     // the pipeline wrote no IDs (the floors): all background
struct ResolvePush {
    vec4 background; // the clear colour, linear as the colour image stores it
    uvec2 extent;
    uint samples;
    uint flags;
};

#ifdef __cplusplus
static_assert(sizeof(ResolvePush) == 32);
// Within the 128 bytes of push constants every device has.
static_assert(sizeof(ComposePush) == 96 && offsetof(ComposePush, selectedAddress) == 16);
static_assert(offsetof(ComposePush, tintAddress) == 40 && offsetof(ComposePush, blink) == 84);
static_assert(sizeof(HoverBox) == 16);
static_assert(sizeof(PartSetPush) == 32);
static_assert(sizeof(PartSetResult) == 16);
#endif

#endif
