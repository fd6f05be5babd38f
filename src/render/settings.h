// settings.h - what the user chooses about rendering, one plain struct per concern, each field
// and default defined here once. The command line writes into them, headless rendering, the
// benchmark and the viewer hold them, the panel edits them in place and the renderer reads
// them as they are.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include <glm/glm.hpp>

#include "render/technique.h"
#include "scene/section.h"

namespace render {

// An inclusive range of a whole-number setting: the flag, the panel's slider and the shader
// variants the tests compile all take it from here.
struct Range {
    uint32_t min, max;
    constexpr bool contains(uint32_t value) const { return value >= min && value <= max; }
};

// The search techniques unroll their loop over this many parts, so it bounds the batch.
constexpr Range searchBatchRange{1, 32};
constexpr Range nsearchFanOutRange{3, 16};
constexpr Range nsearchLinearRange{0, 64};
constexpr Range nsearchStepsRange{1, 64};

// How a frame's images start and how multisampled ones become the single-sampled images
// that everything after the scene pass reads (render/resolve.h). The rasterizer needs only
// depth cleared: which samples no triangle covered is known from depth, so the background's
// colour and ID can be written by the pass that resolves.
// - Pass: the scene pass clears colour, IDs and depth and resolves MSAA at its end (fast
//   where clears are nearly free);
// - Compute: the pass clears depth alone and a compute pass writes the background and
//   resolves (fast where the rasterizer writes memory slowly: the H100);
// - Auto: the faster of the two on this device, timed once (render/clear_choice.h).
// Both give the same ID image byte for byte and colour within 1 per channel.
enum class ClearPath { Auto, Pass, Compute };
const char* clearPathName(ClearPath path); // "auto", "pass", "compute"
std::optional<ClearPath> findClearPath(std::string_view name);

// What selects a pipeline. Fields the technique does not read are ignored: the pipeline
// cache keys on PipelineKey::effective(), so switching them costs nothing.
struct PipelineKey {
    const Technique* technique = &defaultTechnique();
    const DrawMode* mode = &defaultDrawMode();
    uint32_t searchBatch = 16; // search-*: parts per draw (the unrolled loop length)
    NarySearch nsearch{};      // nsearch-*: compiled in, so each set is its own pipeline
    // gs techniques: VK_NV_geometry_shader_passthrough where the device offers it.
    bool gsPassthrough = true;
    uint32_t msaa = 1; // samples per pixel of the scene pass: 1, 2, 4 or 8
    // Not a choice of the user's: the renderer sets it while any part is hidden, for the
    // variant that discards hidden parts (see gpu::FrameData::hiddenAddress).
    bool hiding = false;
    // Nor this: CullPlan::taskShader, for the mesh techniques with culling on or lists
    // written by cull.comp, whose pipeline has a task shader that culls meshlets or names
    // each listed draw (shaders/scene.task).
    bool taskCulling = false;
    // Nor this: CullPlan::clusterRuns, for the techniques that read gl_PrimitiveID, whose
    // lists with culling on in the mdi modes are cluster runs: the vertex shader hands on each
    // run's offset in its draw (IDV_RUN_OFFSET); otherwise the technique's own shaders.
    bool runOffsets = false;
    // Nor this: set while a section plane is on (RenderSettings::section), for the variant
    // that cuts fragments away and draws caps (IDV_SECTION; late fragment tests, like hiding).
    bool section = false;
    // Nor this: the X-ray pass's pipeline (render/xray.h), the floor's shaders drawing
    // translucent (IDV_TRANSLUCENT): blended colour, no depth or ID written.
    bool translucent = false;
    // Nor this: X-ray's pass beside the visibility buffer, whose picture is shaded after the
    // pass: the translucent colour adds up over black, and what shows through of the picture
    // (the product of one minus each layer's alpha) in alpha, for the shading pass to put
    // the picture under (render/visibility.h).
    bool overVisibility = false;
    // Nor this: the clear path the renderer draws with (never Auto). With MSAA the compute
    // path's scene pass resolves nothing, which makes it another render pass for pipelines;
    // at 1x the two are compatible and effective() drops it.
    ClearPath clear = ClearPath::Pass;

    // The same key with what the technique ignores set to defaults, and passthrough only
    // where the technique has a geometry stage and the device offers it.
    PipelineKey effective(bool devicePassthrough) const;
    bool operator==(const PipelineKey&) const = default;
};

// Which draws are issued.
struct DrawSettings {
    bool sortDraws = true; // by geometry, then material, so consecutive draws share state
    // Draw the first ceil(visible * objects) objects in scene order (visibleObjectCount):
    // load can be dialled without changing the scene or its unique part IDs.
    float visible = 1.0f;
    bool operator==(const DrawSettings&) const = default;
};

// How fragments are shaded; changes nothing but per-frame constants.
struct Shading {
    float partWeight = 0.5f; // blend of the part colour over the material colour, 0..1
    bool colorizeDraws = false;
    bool tintLevels = false;      // a colour per level of detail drawn (shading.glsl's levelTint)
    bool ignoreMaterials = false; // one neutral grey for every object: only part colours show
    bool operator==(const Shading&) const = default;
};

// Lines drawn from the ID image after the scene pass (render/id_passes.h): part edges, and
// outlines of the selected and the hovered parts. Colours are as displayed (sRGB), 0..1.
struct EdgeSettings {
    bool on = false;
    uint32_t width = 1; // pixels, edgeWidthRange; outlines are wider
    // Whole steps of 1/255, so that the 8-bit colour image holds them exactly.
    glm::vec3 color = glm::vec3(16, 16, 20) / 255.0f;
    glm::vec3 selectColor = glm::vec3(255, 184, 26) / 255.0f; // the selection's amber
    glm::vec3 hoverColor = glm::vec3(51, 217, 255) / 255.0f;
    bool operator==(const EdgeSettings&) const = default;
};
constexpr Range edgeWidthRange{1, gpu::EDGE_WIDTH_MAX}; // compose.comp's tile margin holds it

// What is left out before the scene pass draws (render/culling.h). Every mode leaves the
// images exactly as without it; what a technique and per-draw mode get of it is
// cullingPlan() (GPU-built draw lists in the mdi modes and for mesh tasks, the CPU's frustum
// test per object in push mode).
enum class CullMode { Off, Frustum, Occlusion };
struct CullSettings {
    CullMode mode = CullMode::Occlusion;
    // Keep drawing what the last culled frame chose while the camera moves on, so a user can
    // fly around and see what was left out.
    bool freeze = false;
    bool operator==(const CullSettings&) const = default;
};

// Levels of detail chosen on the GPU (scene/lod.h builds them when the scene loads): above 0,
// the draw list holds every level and the cull pass draws each object at its coarsest level
// whose error, projected at the object, stays under this many pixels. Only where cull.comp
// lists the draws (mdi modes, culling on or off: levelsChosenIn); push mode, and 0, draw full
// detail.
struct LodSettings {
    float errorPixels = 0.0f;
    bool operator==(const LodSettings&) const = default;
};

// The compute rasterizer (the visbuffer-compute technique, render/compute_raster.h): which
// meshlets its task shader sends to the compute pass instead of the mesh shader.
struct RasterSettings {
    // Those whose projected rectangle holds at most this many pixels per triangle at 1x; with
    // MSAA this many samples (pixels times samples), as the compute pass's work grows with
    // them. 32: the best of 2, 8, 32 and every meshlet at 1x, and 8 px (32 samples) the best
    // of 8 and every meshlet at 4x, on the H200 (docs/benchmarks.md).
    float trianglePixels = 32.0f;
    bool all = false; // every meshlet the compute pass can draw (tests, the benchmark)
    bool operator==(const RasterSettings&) const = default;
};

struct RenderSettings {
    PipelineKey pipeline;
    ClearPath clear = ClearPath::Auto;
    DrawSettings draws;
    Shading shading;
    EdgeSettings edges;
    CullSettings culling;
    LodSettings lod;
    RasterSettings raster;
    // Cuts through the scene (scene/section.h). Every technique honours them, and so does
    // everything read from the ID image: picks, box selection, edges, the visible parts.
    scene::Section section;
    bool operator==(const RenderSettings&) const = default;
};

} // namespace render
