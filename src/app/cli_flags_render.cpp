// cli_flags_render.cpp - the flags of how the image is drawn: its size, samples and clear
// path, the part-ID technique and its parameters, culling and levels of detail, shading,
// edges and sections.
#include "app/cli_flags.h"

#include <algorithm>

#include "app/cli_flag_tables.h"
#include "render/culling.h"
#include "render/technique.h"
#include "scene/lod.h"

namespace app::flag_tables {

std::vector<Flag> imageFlags(const Options& d) {
    const render::PipelineKey& key = d.live.render.pipeline;
    return {
        {"--size", "WxH",
         "render size in pixels" +
             byDefault(std::to_string(d.width) + "x" + std::to_string(d.height)),
         [](Options& o, auto& v) { parseSize(v, o); }},
        {"--msaa", "N",
         "samples per pixel: 1, 2, 4 or 8, as the device offers" + byDefault(key.msaa),
         [](Options& o, auto& v) {
             uint32_t& msaa = o.live.render.pipeline.msaa;
             msaa = parseCount("--msaa", v, 1, 8);
             if (msaa & (msaa - 1)) throw UsageError("--msaa expects 1, 2, 4 or 8, not " + v);
         }},
        {"--clear", "PATH",
         "how a frame starts and resolves: pass (the scene pass clears every image and "
         "resolves MSAA), compute (it clears depth alone; a compute pass writes the "
         "background and resolves) or auto, the faster of the two on this device, timed "
         "once and kept beside the pipeline cache" +
             byDefault(render::clearPathName(d.live.render.clear)),
         [](Options& o, auto& v) {
             const auto path = render::findClearPath(v);
             if (!path) throw UsageError("--clear expects auto, pass or compute, not " + v);
             o.live.render.clear = *path;
         }},
    };
}

std::vector<Flag> techniqueFlags(const Options& d) {
    const render::PipelineKey& key = d.live.render.pipeline;
    const render::PipelineKey viewer = viewerDefaults().live.render.pipeline;
    const render::NarySearch& nary = key.nsearch;
    return {
        registryFlag("--renderer", "part-ID technique (see --list-renderers)", key.technique->name,
                     viewer.technique->name, techniqueList, &Options::benchmarkTechniques,
                     &render::PipelineKey::technique),
        registryFlag("--mode", "per-draw parameter mode", key.mode->name, viewer.mode->name,
                     modeList, &Options::benchmarkModes, &render::PipelineKey::mode),
        rangeFlag("--search-batch", "parts per draw of the search techniques",
                  render::searchBatchRange, key.searchBatch,
                  [](Options& o) -> uint32_t& { return o.live.render.pipeline.searchBatch; }),
        rangeFlag("--nsearch-n", "nsearch renderers: offsets read per step",
                  render::nsearchFanOutRange, nary.n,
                  [](Options& o) -> uint32_t& { return o.live.render.pipeline.nsearch.n; }),
        {"--nsearch-guess", "on|off",
         "nsearch renderers: start at the part a uniform part size predicts" + onOff(nary.guess),
         [](Options& o, auto& v) {
             o.live.render.pipeline.nsearch.guess = parseOnOff("--nsearch-guess", v);
         }},
        rangeFlag(
            "--nsearch-linear", "nsearch renderers: scan linearly from N parts left",
            render::nsearchLinearRange, nary.linearBelow,
            [](Options& o) -> uint32_t& { return o.live.render.pipeline.nsearch.linearBelow; }),
        rangeFlag("--nsearch-steps",
                  "nsearch renderers: N-ary steps at most, a linear scan finishes",
                  render::nsearchStepsRange, nary.maxSteps,
                  [](Options& o) -> uint32_t& { return o.live.render.pipeline.nsearch.maxSteps; }),
        {"--gs-ordinary", nullptr,
         "gs renderers: use an ordinary geometry shader even where "
         "VK_NV_geometry_shader_passthrough is offered",
         [](Options& o, auto&) { o.live.render.pipeline.gsPassthrough = false; }},
        {"--no-sort-draws", nullptr,
         "keep draws in scene order instead of by geometry and material",
         [](Options& o, auto&) { o.live.render.draws.sortDraws = false; }},
        {"--visible", "F",
         "draw only the first ceil(F * objects) objects in scene order, 0 to 1" +
             byDefault(d.live.render.draws.visible),
         [](Options& o, auto& v) { o.live.render.draws.visible = parseFraction("--visible", v); }},
        {"--raster-pixels", "PX",
         "visbuffer-compute: rasterize in compute the meshlets whose projected rectangle "
         "holds at most PX pixels per triangle (PX samples with MSAA: PX / 4 pixels at 4x); 0 "
         "draws every one on the hardware" +
             byDefault(d.live.render.raster.trianglePixels),
         [](Options& o, auto& v) {
             o.live.render.raster.trianglePixels =
                 parseNumber("--raster-pixels", v, 1e6f, "pixels");
         }},
        {"--raster-all", nullptr,
         "visbuffer-compute: rasterize in compute every meshlet the compute pass can draw "
         "(all but those that reach in front of the near plane, across a section plane, or "
         "over 62 pixels)",
         [](Options& o, auto&) { o.live.render.raster.all = true; }},
    };
}

std::vector<Flag> cullingFlags(const Options& d) {
    return {
        {"--culling", "MODE",
         "leave out what cannot show, the images unchanged: off, frustum or occlusion "
         "(two-phase: first what passed the last frame's test, then the rest against a depth "
         "pyramid of that)" +
             byDefault(render::cullModeName(d.live.render.culling.mode)) +
             "; what each per-draw mode gets: --list-renderers; with --benchmark a comma "
             "list or all (default)",
         [](Options& o, auto& v) {
             o.benchmarkCulling = cullingList(v);
             o.live.render.culling.mode = o.benchmarkCulling.front()->mode;
         }},
        {"--freeze-culling", nullptr,
         "keep the draw lists of the first culled frame in every later one (what the "
         "panel's freeze culling does), so the camera can move and show what was left out",
         [](Options& o, auto&) { o.live.render.culling.freeze = true; }},
        {"--lod-error", "PX",
         "draw each object at its coarsest level of detail whose error stays under PX "
         "pixels, chosen on the GPU by the cull pass (mdi modes, culling on or off; push mode "
         "draws full detail); 0 is full detail; builds every level unless --lod-levels says "
         "otherwise" +
             byDefault(d.live.render.lod.errorPixels) + "; with --benchmark a comma list",
         [](Options& o, auto& v) {
             o.benchmarkLodErrors.clear();
             for (size_t start = 0; start <= v.size();) {
                 const size_t end = std::min(v.find(',', start), v.size());
                 o.benchmarkLodErrors.push_back(
                     parseNumber("--lod-error", v.substr(start, end - start), 1e6f, "pixels"));
                 start = end + 1;
             }
             o.live.render.lod.errorPixels =
                 *std::max_element(o.benchmarkLodErrors.begin(), o.benchmarkLodErrors.end());
         }},
    };
}

std::vector<Flag> shadingFlags(const Options& d) {
    return {
        {"--part-weight", "F",
         "blend of part colour over material colour, 0 to 1" +
             byDefault(d.live.render.shading.partWeight),
         [](Options& o, auto& v) {
             o.live.render.shading.partWeight = parseFraction("--part-weight", v);
         }},
        {"--colorize-draws", nullptr, "replace material colours by a colour per draw call",
         [](Options& o, auto&) { o.live.render.shading.colorizeDraws = true; }},
        {"--tint-levels", nullptr,
         "replace material colours by a colour per level of detail drawn: grey full "
         "detail, then blue, yellow and red",
         [](Options& o, auto&) { o.live.render.shading.tintLevels = true; }},
        {"--ignore-materials", nullptr,
         "shade every object with one neutral grey, so only part colours show",
         [](Options& o, auto&) { o.live.render.shading.ignoreMaterials = true; }},
        {"--edges", nullptr,
         "draw part edges from the ID image, and outlines of the selected and hovered parts",
         [](Options& o, auto&) { o.live.render.edges.on = true; }},
        rangeFlag("--edge-width", "edge width in pixels (outlines are wider)",
                  render::edgeWidthRange, d.live.render.edges.width,
                  [](Options& o) -> uint32_t& { return o.live.render.edges.width; }),
        {"--edge-color", "RRGGBB",
         "edge colour in hex, as displayed" + byDefault(hexColor(d.live.render.edges.color)),
         [](Options& o, auto& v) { o.live.render.edges.color = parseColor("--edge-color", v); }},
        {"--section", "AXIS,VALUE[,flip]",
         "cut the scene: keep where coordinate AXIS (x, y or z) is at most VALUE (model "
         "units), flip keeps the other side; caps show where a cut opens a solid; up to " +
             std::to_string(scene::maxSectionPlanes) + ", each cutting its side away",
         [](Options& o, auto& v) { addSectionPlane(o.live.render.section, v); }},
        {"--xray", nullptr,
         "X-ray: draw the parts outside the selection translucent, out of the ID image and "
         "picks, so the selected parts inside show (headless: after --select or "
         "--select-rect; with nothing selected it changes nothing)",
         [](Options& o, auto&) { o.live.xray = true; }},
    };
}

} // namespace app::flag_tables
