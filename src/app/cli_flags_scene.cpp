// cli_flags_scene.cpp - the flags of what is loaded (model, built-in scene, parts, copies,
// levels of detail built), of CAD tessellation, and of the view and its animation.
#include "app/cli_flags.h"

#include <limits>
#include <stdexcept>

#include "app/cli_flag_tables.h"
#include "app/scene_source.h"
#include "scene/camera_path.h"
#include "scene/copies.h"
#include "scene/formats.h"
#include "scene/lod.h"

namespace app::flag_tables {

std::vector<Flag> sceneFlags(const Options& d) {
    return {
        {"--model", "FILE",
         "open a model: " + scene::formatList() +
             "; a part is a glTF primitive, a B-rep face, an STL solid; default: "
             "assets/default.glb; also given as the one argument that is no flag (idview "
             "FILE), and as a file:// URI",
         [](Options& o, auto& v) { o.live.scene.model = modelPath(v); }},
        {"--scene", "SPEC",
         "built-in scene instead of a model: assembly, tiles (the test layout) or "
         "procedural[:preset=small|car-like][,seed=N]",
         [](Options& o, auto& v) {
             try {
                 parseSceneSpec(v);
             } catch (const std::invalid_argument& e) {
                 throw UsageError(std::string("--scene: ") + e.what());
             }
             o.live.scene.builtin = v;
         }},
        {"--parts", "MODE",
         "glTF parts (CAD files: always one per face): primitives (one part per primitive) or "
         "components (one per connected "
         "component, recovers CAD faces merged by an exporter)" +
             byDefault(scene::partModeName(d.live.scene.parts)),
         [](Options& o, auto& v) {
             try {
                 o.live.scene.parts = scene::parsePartMode(v);
             } catch (const std::invalid_argument&) {
                 throw UsageError("--parts expects primitives or components, not '" + v + "'");
             }
         }},
        {"--copies", "N", "replicate the model N times on a grid" + byDefault(d.live.scene.copies),
         [](Options& o, auto& v) { o.live.scene.copies = parseCount("--copies", v, 1, 1000000); }},
        {"--copy-axes", "AXES",
         "axes the copies' grid spans: any of x, y, z, e.g. x, xz or xyz" +
             byDefault(scene::copyAxesName(d.live.scene.copyAxes)),
         [](Options& o, auto& v) {
             try {
                 o.live.scene.copyAxes = scene::parseCopyAxes(v);
             } catch (const std::invalid_argument& e) {
                 throw UsageError(std::string("--copy-axes: ") + e.what());
             }
         }},
        {"--lod-levels", "N",
         "levels of detail to build when the scene loads, full detail included, 1 (none) "
         "to " +
             std::to_string(scene::maxLevels) + byDefault(d.live.scene.lodLevels),
         [](Options& o, auto& v) {
             o.live.scene.lodLevels = parseCount("--lod-levels", v, 1, scene::maxLevels);
         }},
        {"--lod-level", "N",
         "draw every object at level of detail N (0 is full detail; an object with fewer "
         "levels takes its coarsest); needs --lod-levels above N" +
             byDefault(d.live.scene.lodLevel),
         [](Options& o, auto& v) {
             o.live.scene.lodLevel = parseCount("--lod-level", v, 0, scene::maxLevels - 1);
         }},
    };
}

std::vector<Flag> cadFlags(const Options& d) {
    return {
        {"--deflection", "X",
         "CAD files: linear tessellation deflection in model units; 0 picks " +
             percent(scene::kRelativeDeflection) + " of the model's bounding box diagonal" +
             byDefault(d.live.scene.cad.deflection),
         [](Options& o, auto& v) {
             o.live.scene.cad.deflection = parseNumber("--deflection", v, 1e9f, "a length");
         }},
        {"--angular-deflection", "RAD",
         "CAD files: angular tessellation deflection in radians, above 0 up to 3.14" +
             byDefault(d.live.scene.cad.angularDeflection),
         [](Options& o, auto& v) {
             const float radians = parseNumber("--angular-deflection", v, 3.14f, "radians");
             if (radians <= 0.0f)
                 throw UsageError("--angular-deflection expects radians above 0, not '" + v + "'");
             o.live.scene.cad.angularDeflection = radians;
         }},
        {"--max-triangles", "N",
         "CAD files: stop a tessellation as soon as its faces pass N triangles (full detail, "
         "each distinct shape once) and exit 1 naming a --deflection that fits" +
             byDefault(d.live.scene.cad.maxTriangles),
         [](Options& o, auto& v) {
             o.live.scene.cad.maxTriangles =
                 parseCount("--max-triangles", v, 1, std::numeric_limits<uint32_t>::max());
         }},
        {"--load-workers", "N",
         "CAD files: worker processes that read, translate and mesh a file's pieces in "
         "parallel (STEP files are split into them; others are read whole by one); 0 is one "
         "per core" +
             byDefault(d.live.scene.cad.workers),
         [](Options& o, auto& v) {
             o.live.scene.cad.workers = parseCount("--load-workers", v, 0, 256);
         }},
        {"--healing", "auto|on|off",
         "CAD files: Open CASCADE's shape healing after a STEP file's translation, most of its "
         "time: on; off (the file's own flaws stay, faces may not mesh); auto reads each piece "
         "without it and keeps that where every solid meshes whole and consistently oriented, "
         "else reads the piece again healed" +
             byDefault(scene::healingName(d.live.scene.cad.healing)),
         [](Options& o, auto& v) {
             if (v == "auto" || v == "on" || v == "off")
                 o.live.scene.cad.healing = v == "on"    ? scene::Healing::On
                                            : v == "off" ? scene::Healing::Off
                                                         : scene::Healing::Auto;
             else
                 throw UsageError("--healing expects auto, on or off, not '" + v + "'");
         }},
        {"--progress", nullptr,
         "print progress on stderr even when it is no terminal (a pipe, a log): a CAD "
         "load's, from the start (at a terminal once it has taken a second), and the "
         "benchmark's line per row",
         [](Options& o, auto&) { o.live.scene.progress = true; }},
    };
}

std::vector<Flag> viewFlags(const Options& d) {
    return {
        {"--view", "NAME",
         "open on a standard view of the fitted scene, as FreeCAD shows them (front looks "
         "along +Y of a Z-up model): " +
             scene::standardViewNames(),
         [](Options& o, auto& v) {
             o.live.camera.standard = scene::findStandardView(v);
             if (!o.live.camera.standard)
                 throw UsageError("--view expects " + scene::standardViewNames() + ", not '" + v +
                                  "'");
         }},
        {"--ortho", nullptr,
         "orthographic projection, as tall as the perspective view at the target (the "
         "viewer's O switches)",
         [](Options& o, auto&) { o.live.camera.ortho = true; }},
        headless({"--camera-path", "PATH",
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
        {"--explode", "F",
         "the exploded view at F, 0 (at rest) to 1: sub-assemblies move apart from their "
         "assembly's centre, and their parts apart within them, level by level (the viewer's "
         "explode slider)" +
             byDefault(d.live.animation.explode),
         [](Options& o, auto& v) { o.live.animation.explode = parseFraction("--explode", v); }},
        {"--animate", nullptr,
         "exploded-view animation, for benchmarks: the exploded view goes from 0 to 1 and "
         "back every 4 s, the objects' matrices written on the GPU each frame; headless "
         "at --time, else at frame / 60 s",
         [](Options& o, auto&) { o.live.animation.animate = true; }},
        headless({"--time", "SECONDS",
                  "with --animate: the moment of the loop to render (default: frame / 60)",
                  [](Options& o, auto& v) {
                      o.live.animation.time = parseNumber("--time", v, 1e6f, "seconds");
                  }}),
    };
}

} // namespace app::flag_tables
