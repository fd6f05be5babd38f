// cli_flags.cpp - the flag table: each flag's name, value, help (with the default the
// settings define) and what it writes into Options. Values are read by cli_values.h.
#include "app/cli_flags.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <limits>
#include <sstream>

#include "app/scene_source.h"
#include "render/culling.h"
#include "render/technique.h"
#include "scene/camera_path.h"
#include "scene/copies.h"
#include "scene/lod.h"

namespace app {

namespace {

// " (default 16)", " 1 to 32 (default 16)": help text from the settings' own defaults.
template <typename T>
std::string byDefault(const T& value) {
    std::ostringstream text;
    text << " (default " << value << ")";
    return text.str();
}
std::string within(render::Range range, uint32_t value) {
    return ", " + std::to_string(range.min) + " to " + std::to_string(range.max) + byDefault(value);
}
std::string percent(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, "%g%%", fraction * 100.0);
    return text;
}
std::string onOff(bool value) {
    return byDefault(value ? "on" : "off");
}

// A flag whose value is stored as given in a string of Options.
Flag text(const char* name, const char* value, std::string help, std::string Options::*field) {
    return {name, value, std::move(help),
            [field](Options& o, const std::string& v) { o.*field = v; }};
}

// A switch that sets a bool of Options.
Flag on(const char* name, std::string help, bool Options::*field) {
    return {name, nullptr, std::move(help),
            [field](Options& o, const std::string&) { o.*field = true; }};
}

// A flag only headless runs read.
Flag headless(Flag flag) {
    flag.headlessOnly = true;
    return flag;
}

// --renderer or --mode: one registry entry into the pipeline key, or with --benchmark a list.
template <typename Entry>
Flag registryFlag(const char* name, const char* help, const char* value, const char* viewer,
                  std::vector<const Entry*> (*list)(const std::string&),
                  std::vector<const Entry*> Options::*benchmarkList,
                  const Entry* render::PipelineKey::*field) {
    return {name, "NAME",
            help + byDefault(value) + ", the viewer opens on " + viewer +
                "; with --benchmark a comma list or all (default)",
            [=](Options& o, const std::string& v) {
                o.*benchmarkList = list(v);
                o.render.pipeline.*field = (o.*benchmarkList).front();
            }};
}

// A whole-number flag within `range`, written into the field `field` names.
Flag rangeFlag(const char* name, const char* help, render::Range range, uint32_t value,
               uint32_t& (*field)(Options&)) {
    return {name, "N", help + within(range, value),
            [=](Options& o, const std::string& v) { field(o) = parseRange(name, v, range); }};
}

} // namespace

const std::vector<Flag>& flags() {
    static const std::vector<Flag> table = [] {
        const Options d; // the defaults, as the settings structs define them
        const render::PipelineKey& key = d.render.pipeline;
        const render::PipelineKey viewer = viewerDefaults().render.pipeline;
        const render::NarySearch& nary = key.nsearch;
        return std::vector<Flag>{
            on("--help", "print this text", &Options::help),
            on("--headless", "render offscreen without a window or surface", &Options::headless),
            {"--size", "WxH",
             "render size in pixels" +
                 byDefault(std::to_string(d.width) + "x" + std::to_string(d.height)),
             [](Options& o, auto& v) { parseSize(v, o); }},
            {"--msaa", "N",
             "samples per pixel: 1, 2, 4 or 8, as the device offers" + byDefault(key.msaa),
             [](Options& o, auto& v) {
                 uint32_t& msaa = o.render.pipeline.msaa;
                 msaa = parseCount("--msaa", v, 1, 8);
                 if (msaa & (msaa - 1)) throw UsageError("--msaa expects 1, 2, 4 or 8, not " + v);
             }},
            {"--clear", "PATH",
             "how a frame starts and resolves: pass (the scene pass clears every image and "
             "resolves MSAA), compute (it clears depth alone; a compute pass writes the "
             "background and resolves) or auto, the faster of the two on this device, timed "
             "once and kept beside the pipeline cache" +
                 byDefault(render::clearPathName(d.render.clear)),
             [](Options& o, auto& v) {
                 const auto path = render::findClearPath(v);
                 if (!path) throw UsageError("--clear expects auto, pass or compute, not " + v);
                 o.render.clear = *path;
             }},
            headless(
                {"--frames", "N",
                 "frames to render headless" + byDefault(d.frames) + "; files hold the last one",
                 [](Options& o, auto& v) { o.frames = parseCount("--frames", v, 1, 1000000); }}),
            headless(text("--screenshot", "FILE", "write the last frame's colour image as PNG",
                          &Options::screenshot)),
            headless(text(
                "--id-image", "FILE",
                "write the last frame's part IDs: W*H little-endian uint32, row-major, top row "
                "first, "
                "0xFFFFFFFF where no part is",
                &Options::idImage)),
            {"--model", "FILE",
             "open a glTF model (.gltf, .glb) or a CAD file (.step, .stp, .iges, .igs, .brep; "
             "one part per B-rep face); default: assets/default.glb",
             [](Options& o, auto& v) { o.scene.model = v; }},
            {"--deflection", "X",
             "CAD files: linear tessellation deflection in model units; 0 picks " +
                 percent(scene::kRelativeDeflection) + " of the model's bounding box diagonal" +
                 byDefault(d.scene.cad.deflection),
             [](Options& o, auto& v) {
                 o.scene.cad.deflection = parseNumber("--deflection", v, 1e9f, "a length");
             }},
            {"--angular-deflection", "RAD",
             "CAD files: angular tessellation deflection in radians, above 0 up to 3.14" +
                 byDefault(d.scene.cad.angularDeflection),
             [](Options& o, auto& v) {
                 const float radians = parseNumber("--angular-deflection", v, 3.14f, "radians");
                 if (radians <= 0.0f)
                     throw UsageError("--angular-deflection expects radians above 0, not '" + v +
                                      "'");
                 o.scene.cad.angularDeflection = radians;
             }},
            {"--max-triangles", "N",
             "CAD files: stop a tessellation as soon as its faces pass N triangles (full detail, "
             "each distinct shape once) and exit 1 naming a --deflection that fits" +
                 byDefault(d.scene.cad.maxTriangles),
             [](Options& o, auto& v) {
                 o.scene.cad.maxTriangles =
                     parseCount("--max-triangles", v, 1, std::numeric_limits<uint32_t>::max());
             }},
            {"--no-cache", nullptr,
             "neither read nor write the caches in $XDG_CACHE_HOME/idview (else "
             "~/.cache/idview): CAD files' tessellations, and the driver's compiled pipelines "
             "(then kept in memory only)",
             [](Options& o, auto&) { o.scene.cadCache = false; }},
            {"--progress", nullptr,
             "CAD files: print the load's progress on stderr even when it is no terminal (a "
             "pipe, a log), from the start; at a terminal it shows once a load has taken a "
             "second",
             [](Options& o, auto&) { o.scene.progress = true; }},
            {"--scene", "SPEC",
             "built-in scene instead of a model: assembly, tiles (the test layout) or "
             "procedural[:preset=small|car-like][,seed=N]",
             [](Options& o, auto& v) {
                 try {
                     parseSceneSpec(v);
                 } catch (const std::invalid_argument& e) {
                     throw UsageError(std::string("--scene: ") + e.what());
                 }
                 o.scene.builtin = v;
             }},
            {"--parts", "MODE",
             "glTF parts (CAD files: always one per face): primitives (one part per primitive) or "
             "components (one per connected "
             "component, recovers CAD faces merged by an exporter)" +
                 byDefault(scene::partModeName(d.scene.parts)),
             [](Options& o, auto& v) {
                 try {
                     o.scene.parts = scene::parsePartMode(v);
                 } catch (const std::invalid_argument&) {
                     throw UsageError("--parts expects primitives or components, not '" + v + "'");
                 }
             }},
            {"--copies", "N", "replicate the model N times on a grid" + byDefault(d.scene.copies),
             [](Options& o, auto& v) { o.scene.copies = parseCount("--copies", v, 1, 1000000); }},
            {"--copy-axes", "AXES",
             "axes the copies' grid spans: any of x, y, z, e.g. x, xz or xyz" +
                 byDefault(scene::copyAxesName(d.scene.copyAxes)),
             [](Options& o, auto& v) {
                 try {
                     o.scene.copyAxes = scene::parseCopyAxes(v);
                 } catch (const std::invalid_argument& e) {
                     throw UsageError(std::string("--copy-axes: ") + e.what());
                 }
             }},
            {"--lod-levels", "N",
             "levels of detail to build when the scene loads, full detail included, 1 (none) "
             "to " +
                 std::to_string(scene::maxLevels) + byDefault(d.scene.lodLevels),
             [](Options& o, auto& v) {
                 o.scene.lodLevels = parseCount("--lod-levels", v, 1, scene::maxLevels);
             }},
            {"--lod-level", "N",
             "draw every object at level of detail N (0 is full detail; an object with fewer "
             "levels takes its coarsest); needs --lod-levels above N" +
                 byDefault(d.scene.lodLevel),
             [](Options& o, auto& v) {
                 o.scene.lodLevel = parseCount("--lod-level", v, 0, scene::maxLevels - 1);
             }},
            {"--lod-error", "PX",
             "draw each object at its coarsest level of detail whose error stays under PX "
             "pixels, chosen on the GPU by the cull pass (culling on, mdi modes; elsewhere full "
             "detail); 0 is full detail; builds every level unless --lod-levels says otherwise" +
                 byDefault(d.render.lod.errorPixels) + "; with --benchmark a comma list",
             [](Options& o, auto& v) {
                 o.benchmarkLodErrors.clear();
                 for (size_t start = 0; start <= v.size();) {
                     const size_t end = std::min(v.find(',', start), v.size());
                     o.benchmarkLodErrors.push_back(
                         parseNumber("--lod-error", v.substr(start, end - start), 1e6f, "pixels"));
                     start = end + 1;
                 }
                 o.render.lod.errorPixels =
                     *std::max_element(o.benchmarkLodErrors.begin(), o.benchmarkLodErrors.end());
             }},
            rangeFlag("--search-batch", "parts per draw of the search techniques",
                      render::searchBatchRange, key.searchBatch,
                      [](Options& o) -> uint32_t& { return o.render.pipeline.searchBatch; }),
            rangeFlag("--nsearch-n", "nsearch renderers: offsets read per step",
                      render::nsearchFanOutRange, nary.n,
                      [](Options& o) -> uint32_t& { return o.render.pipeline.nsearch.n; }),
            {"--nsearch-guess", "on|off",
             "nsearch renderers: start at the part a uniform part size predicts" +
                 onOff(nary.guess),
             [](Options& o, auto& v) {
                 o.render.pipeline.nsearch.guess = parseOnOff("--nsearch-guess", v);
             }},
            rangeFlag(
                "--nsearch-linear", "nsearch renderers: scan linearly from N parts left",
                render::nsearchLinearRange, nary.linearBelow,
                [](Options& o) -> uint32_t& { return o.render.pipeline.nsearch.linearBelow; }),
            rangeFlag("--nsearch-steps",
                      "nsearch renderers: N-ary steps at most, a linear scan finishes",
                      render::nsearchStepsRange, nary.maxSteps,
                      [](Options& o) -> uint32_t& { return o.render.pipeline.nsearch.maxSteps; }),
            {"--visible", "F",
             "draw only the first ceil(F * objects) objects in scene order, 0 to 1" +
                 byDefault(d.render.draws.visible),
             [](Options& o, auto& v) { o.render.draws.visible = parseFraction("--visible", v); }},
            {"--ignore-materials", nullptr,
             "shade every object with one neutral grey, so only part colours show",
             [](Options& o, auto&) { o.render.shading.ignoreMaterials = true; }},
            on("--stats",
               "print the scene's statistics as one JSON object (objects, geometries, parts, "
               "triangles, load_ms, ID buffer bytes) and, for the chosen renderer and mode, draws, "
               "pipelines and the bytes of each buffer; then exit. With --headless it renders "
               "first and adds first_frame_ms (from creating the device to the first frame's "
               "fence) and pipeline_cache (hit, miss, off, or rejected: why); null without",
               &Options::stats),
            on("--tree",
               "print the scene's assembly tree as one JSON object, nested "
               "{name,children} down to each object's leaf {name,object,parts:[first unique "
               "part, count]} (STEP/IGES products and instances, glTF nodes, procedural groups, "
               "copies); then exit",
               &Options::tree),
            text("--export", "FILE", "write the scene (after copies) as binary glTF and exit",
                 &Options::exportPath),
            registryFlag("--renderer", "part-ID technique (see --list-renderers)",
                         key.technique->name, viewer.technique->name, techniqueList,
                         &Options::benchmarkTechniques, &render::PipelineKey::technique),
            registryFlag("--mode", "per-draw parameter mode", key.mode->name, viewer.mode->name,
                         modeList, &Options::benchmarkModes, &render::PipelineKey::mode),
            {"--culling", "MODE",
             "leave out what cannot show, the images unchanged: off, frustum or occlusion "
             "(two-phase, against the last ID image and a depth pyramid)" +
                 byDefault(render::cullModeName(d.render.culling.mode)) +
                 "; what each per-draw mode gets: --list-renderers; with --benchmark a comma "
                 "list or all (default)",
             [](Options& o, auto& v) {
                 o.benchmarkCulling = cullingList(v);
                 o.render.culling.mode = o.benchmarkCulling.front()->mode;
             }},
            {"--freeze-culling", nullptr,
             "keep the draw lists of the first culled frame in every later one (what the "
             "panel's freeze culling does), so the camera can move and show what was left out",
             [](Options& o, auto&) { o.render.culling.freeze = true; }},
            headless(
                {"--camera-path", "PATH",
                 "headless and --benchmark: move the camera every frame, orbit (around the scene "
                 "at the fitted distance) or dolly (from the fitted view into the middle of the "
                 "assembly and back), over --frames frames; the images hold the last",
                 [](Options& o, auto& v) {
                     const auto path = scene::findCameraPath(v);
                     if (!path)
                         throw UsageError("--camera-path expects " + scene::cameraPathNames() +
                                          ", not '" + v + "'");
                     o.cameraPath = *path;
                 }}),
            {"--view", "NAME",
             "open on a standard view of the fitted scene, as FreeCAD shows them (front looks "
             "along +Y of a Z-up model): " +
                 scene::standardViewNames(),
             [](Options& o, auto& v) {
                 o.camera.standard = scene::findStandardView(v);
                 if (!o.camera.standard)
                     throw UsageError("--view expects " + scene::standardViewNames() + ", not '" +
                                      v + "'");
             }},
            {"--ortho", nullptr,
             "orthographic projection, as tall as the perspective view at the target (the "
             "viewer's O switches)",
             [](Options& o, auto&) { o.camera.ortho = true; }},
            {"--benchmark", nullptr,
             "headless: time every renderer x mode x culling mode and the floors (no-id, "
             "no-id-mesh with mesh techniques); defaults 2560x1440, "
             "--msaa 4, --copies 3, --frames 200 (each flag overrides)",
             [](Options& o, auto&) { o.benchmark = o.headless = true; }},
            headless(text("--benchmark-out", "FILE",
                          "write the benchmark as JSON (CSV when FILE ends in .csv)",
                          &Options::benchmarkOut)),
            {"--part-weight", "F",
             "blend of part colour over material colour, 0 to 1" +
                 byDefault(d.render.shading.partWeight),
             [](Options& o, auto& v) {
                 o.render.shading.partWeight = parseFraction("--part-weight", v);
             }},
            {"--colorize-draws", nullptr, "replace material colours by a colour per draw call",
             [](Options& o, auto&) { o.render.shading.colorizeDraws = true; }},
            {"--tint-levels", nullptr,
             "replace material colours by a colour per level of detail drawn: grey full "
             "detail, then blue, yellow and red",
             [](Options& o, auto&) { o.render.shading.tintLevels = true; }},
            {"--no-sort-draws", nullptr,
             "keep draws in scene order instead of by geometry and material",
             [](Options& o, auto&) { o.render.draws.sortDraws = false; }},
            {"--gs-ordinary", nullptr,
             "gs renderers: use an ordinary geometry shader even where "
             "VK_NV_geometry_shader_passthrough is offered",
             [](Options& o, auto&) { o.render.pipeline.gsPassthrough = false; }},
            headless(
                {"--pick", "X,Y",
                 "headless: pick the part at pixel X,Y (top-left origin) and print one JSON line "
                 "{x,y,part,object,local_part,name,path,depth} (name: the object's, path: its node "
                 "path from the root; all but x,y null on background; CAD files add face, the "
                 "part's B-rep face); repeatable; the last point "
                 "stays hovered in the images",
                 [](Options& o, auto& v) { o.picks.push_back(parsePixel("--pick", v)); }}),
            headless({"--select", "X,Y",
                      "headless: select the part at pixel X,Y as a click there would",
                      [](Options& o, auto& v) { o.selects = {parsePixel("--select", v)}; }}),
            headless(
                {"--select-rect", "X0,Y0,X1,Y1",
                 "headless: select every part visible in the pixel rectangle (corners included) "
                 "as a box selection would, and print one JSON line {rect,parts,count}",
                 [](Options& o, auto& v) { o.selectRect = parseRect("--select-rect", v); }}),
            headless(
                {"--measure", "X0,Y0,X1,Y1",
                 "headless: pick both pixels and print one JSON line "
                 "{p0,p1,distance,delta,parts}: the world points under them (from the depth the "
                 "pick reads), their distance and dX,dY,dZ, and the unique part at each; null "
                 "where a pixel shows no part",
                 [](Options& o, auto& v) { o.measure = parseMeasure(v); }}),
            headless(
                {"--face-info", "X,Y",
                 "headless: pick the pixel and print one JSON line of its part's face "
                 "{part,object,face,surface,area,...,bbox}: for CAD files the B-rep surface type "
                 "(plane, cylinder, cone, sphere, torus, bspline, bezier, revolution, extrusion, "
                 "offset, other) and exact area, with normal and d for planes, radius and axis for "
                 "cylinders, radius and center for spheres; for other parts surface mesh and the "
                 "area of its triangles; {\"part\":null} on background; repeatable",
                 [](Options& o, auto& v) { o.faceInfos.push_back(parsePixel("--face-info", v)); }}),
            {"--distance", "A,B",
             "print one JSON line {distance,p0,p1,source,...,unit}: the minimum distance between "
             "unique parts A and B and its closest points, exact from the B-rep for CAD files "
             "(source brep), from the triangles otherwise (mesh); where both are circles or "
             "cylinders also center_distance, axis_angle (degrees) and, for parallel axes, "
             "axis_distance; where one is a plane, point_to_plane (the other's centre, signed "
             "along the plane's outward normal); without --headless nothing is rendered and idview "
             "exits",
             [](Options& o, auto& v) { o.distance = parseDistance(v); }},
            {"--properties", "OBJECT|all",
             "print one JSON line {object,volume,area,center,bbox:{min,max,size},closed,unit} of "
             "the object (a solid of a CAD file: exact, from the B-rep; meshes: from triangles, "
             "volume 0 unless they close); all: one line per object and their sum "
             "{object:\"all\",objects,...}; without --headless nothing is rendered and idview "
             "exits",
             [](Options& o, auto& v) {
                 o.propertiesAll = v == "all";
                 if (!o.propertiesAll)
                     o.propertiesObject = parseCount("--properties", v, 0, 0xFFFFFFFEu);
             }},
            headless(
                {"--edge-info", "X,Y",
                 "headless: pick the pixel and print one JSON line of the B-rep edge of its "
                 "part's face drawn nearest it, within a few pixels: {x,y,part,object,edge,curve,"
                 "length,...,start,end,closed} with curve line, circle, ellipse, bspline or other, "
                 "its exact length, radius, diameter, center and axis for circles, direction for "
                 "lines; \"edge\":null away from every edge, on background or without a B-rep; "
                 "repeatable",
                 [](Options& o, auto& v) { o.edgeInfos.push_back(parsePixel("--edge-info", v)); }}),
            headless({"--hide", "ID,...",
                      "headless: do not draw these unique parts (nor pick them)",
                      [](Options& o, auto& v) { o.hide = parseIds("--hide", v); }}),
            headless({"--isolate", "ID,...", "headless: draw only these unique parts",
                      [](Options& o, auto& v) { o.isolate = parseIds("--isolate", v); }}),
            on("--xray",
               "X-ray: draw the parts outside the selection translucent, out of the ID image and "
               "picks, so the selected parts inside show (headless: after --select or "
               "--select-rect; with nothing selected it changes nothing)",
               &Options::xray),
            headless(
                on("--visible-parts",
                   "headless: print one JSON line {count,parts} of the unique parts the last frame "
                   "shows, counted on the GPU; with --benchmark every frame counts them",
                   &Options::visibleParts)),
            {"--section", "AXIS,VALUE[,flip]",
             "cut the scene: keep where coordinate AXIS (x, y or z) is at most VALUE (model "
             "units), flip keeps the other side; caps show where a cut opens a solid; up to " +
                 std::to_string(scene::maxSectionPlanes) + ", each cutting its side away",
             [](Options& o, auto& v) { addSectionPlane(o.render.section, v); }},
            {"--edges", nullptr,
             "draw part edges from the ID image, and outlines of the selected and hovered parts",
             [](Options& o, auto&) { o.render.edges.on = true; }},
            rangeFlag("--edge-width", "edge width in pixels (outlines are wider)",
                      render::edgeWidthRange, d.render.edges.width,
                      [](Options& o) -> uint32_t& { return o.render.edges.width; }),
            {"--edge-color", "RRGGBB",
             "edge colour in hex, as displayed" + byDefault(hexColor(d.render.edges.color)),
             [](Options& o, auto& v) { o.render.edges.color = parseColor("--edge-color", v); }},
            {"--explode", "F",
             "the exploded view at F, 0 (at rest) to 1: sub-assemblies move apart from their "
             "assembly's centre, and their parts apart within them, level by level (the viewer's "
             "explode slider)" +
                 byDefault(d.animation.explode),
             [](Options& o, auto& v) { o.animation.explode = parseFraction("--explode", v); }},
            {"--animate", nullptr,
             "exploded-view animation, for benchmarks: the exploded view goes from 0 to 1 and "
             "back every 4 s, the objects' matrices written on the GPU each frame; headless "
             "at --time, else at frame / 60 s",
             [](Options& o, auto&) { o.animation.animate = true; }},
            headless({"--time", "SECONDS",
                      "with --animate: the moment of the loop to render (default: frame / 60)",
                      [](Options& o, auto& v) {
                          o.animation.time = parseNumber("--time", v, 1e6f, "seconds");
                      }}),
            on("--list-renderers", "print the renderers and modes, then exit",
               &Options::listRenderers),
            on("--validation", "enable the Khronos validation layer; messages make exit 3",
               &Options::validation),
            {"--sync-validation", nullptr,
             "--validation plus the layer's synchronization validation (slower; for testing)",
             [](Options& o, auto&) { o.validation = o.syncValidation = true; }},
            text("--device", "INDEX|NAME",
                 "Vulkan device by index or name substring (default: best)", &Options::device),
            on("--list-devices", "print the Vulkan devices and whether idview runs there",
               &Options::listDevices),
            text("--shader-dir", "DIR", "read shaders from DIR instead of the built-in location",
                 &Options::shaderDir),
            text(
                "--script", "FILE",
                "viewer: run scripted input, lines '<seconds> <command> [args]' (key, move, click, "
                "drag, scroll, resize, renderer, mode, msaa, sort, defaults, copies, explode, "
                "frames, "
                "screenshot, drop, quit)",
                &Options::script),
            on("--print-events",
               "viewer: print one 'idview: ...' line on stdout per event (title, selection, opened "
               "model, screenshot, shader reload), for scripts and tests; quiet otherwise",
               &Options::printEvents),
            {"--window-pos", "X,Y",
             "viewer: the window's top left corner on the screen, kept between runs with "
             "--size; pulled onto the screen's work area if it lies off it",
             [](Options& o, auto& v) { o.windowPos = parseWindowPos(v); }},
            {"--no-saved-settings", nullptr,
             "viewer: open on the defaults, neither reading nor writing the settings kept "
             "between runs ($XDG_CONFIG_HOME/idview/viewer.conf, else "
             "~/.config/idview/viewer.conf)",
             [](Options& o, auto&) { o.savedSettings = false; }},
        };
    }();
    return table;
}

} // namespace app
