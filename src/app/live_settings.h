// live_settings.h - the settings the viewer changes while it runs and keeps between runs: what
// is drawn, how, and from where. The command line fills them (cli.h's Options::live); headless
// runs and the benchmark read them there, and the viewer is handed them alone to edit in place.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "render/settings.h"
#include "scene/cad/cad_loader.h"
#include "scene/copies.h"
#include "scene/gltf/gltf_loader.h"
#include "scene/standard_view.h"

namespace app {

// Where the scene comes from, and how many times it is placed.
struct SceneSettings {
    std::string model;   // glTF or CAD file; with `builtin` empty too, the default model
    std::string builtin; // built-in or procedural scene spec (scene_source.h)
    scene::PartMode parts = scene::PartMode::Primitives; // glTF: what one part is
    scene::CadOptions cad;                               // STEP, IGES, BREP: the tessellation
    // STEP, IGES, BREP: read and write the tessellation cache (scene/cad/cad_cache.h).
    bool cadCache = true;
    // --progress: progress lines on stderr even where it is no terminal: a CAD load's
    // (app/progress_lines.h), and the benchmark's line per row, which reads it from here.
    bool progress = false;
    uint32_t copies = 1;
    uint32_t copyAxes = scene::COPY_XY; // the axes the copies' grid spans
    // Levels of detail built at load, full detail included (scene/lod.h; 1 builds none), and
    // the level every object is drawn at (0, full detail, unless forced for the whole scene).
    uint32_t lodLevels = 1;
    uint32_t lodLevel = 0;
    bool operator==(const SceneSettings&) const = default;
};

// The exploded view (scene/explode.h): at `explode`, 0 (at rest) to 1, as --explode and the
// viewer's slider set it; with `animate` (the benchmark's motion) it follows
// scene::explodeLoop instead, headless at `time` seconds or at frame / 60 without it.
struct Animation {
    bool animate = false;
    std::optional<float> time;
    float explode = 0.0f;
};

// The opening view: one of the standard views (scene/standard_view.h) instead of the
// three-quarter one, at the same fitted distance, and the projection. The viewer starts from
// it and then changes it with its keys (1, 3, 7, 0, O).
struct CameraSettings {
    const scene::StandardView* standard = nullptr; // nullptr: the three-quarter view
    bool ortho = false;
};

struct LiveSettings {
    SceneSettings scene;
    render::RenderSettings render;
    Animation animation;
    CameraSettings camera;
    // X-ray (render/xray.h): the parts outside the selection drawn translucent, left out of
    // the ID image and picks. Headless: from the frames after --select / --select-rect on;
    // the viewer opens with it on (X toggles it).
    bool xray = false;
};

// The viewer's window: its size and where it opens (its top left corner), as --size and
// --window-pos give them (cli.h's windowPlace). Read once at start and taken from the window
// as it closes, both kept between runs (saved_settings.h); nothing edits them in between.
struct WindowPlace {
    uint32_t width = 0;
    uint32_t height = 0;
    std::optional<std::array<int, 2>> position;
};

} // namespace app
