// commands.cpp - the viewer's command table, a function per group of rows, and the one
// executor: what keys, the panel and the script ask for runs here.
#include "app/viewer/commands/commands.h"

#include "app/viewer/commands/command_target.h"

#include <stdexcept>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "scene/assembly_tree.h"
#include "scene/standard_view.h"

namespace app {
namespace {

constexpr int shift = GLFW_MOD_SHIFT, ctrl = GLFW_MOD_CONTROL;
using Kind = ArgumentKind;

// The number row's key and the keypad's, so both keyboards' habits work.
std::vector<Chord> digit(int n, int mods = 0) {
    return {{GLFW_KEY_0 + n, mods}, {GLFW_KEY_KP_0 + n, mods}};
}
std::vector<Chord> join(std::vector<Chord> a, const std::vector<Chord>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}
// Keys that run a command with no argument, and those that toggle a switch.
std::vector<KeyBinding> keys(std::vector<Chord> chords) {
    return {{std::move(chords), std::monostate{}}};
}
std::vector<KeyBinding> toggles(std::vector<Chord> chords) {
    return {{std::move(chords), Switch::Toggle}};
}

bool on(const Argument& argument) {
    return std::get<Switch>(argument) == Switch::On;
}
template <typename T>
const T& arg(const Argument& argument) {
    return std::get<T>(argument);
}

void hide(CommandTarget& viewer, const Argument&) {
    viewer.document().hideSelected();
    viewer.selectionChanged(); // hidden parts are not selected
    viewer.partsChanged();
}

void isolate(CommandTarget& viewer, const Argument&) {
    viewer.document().isolateSelected();
    viewer.partsChanged();
}

void showAll(CommandTarget& viewer, const Argument&) {
    viewer.document().showAll();
    viewer.partsChanged();
}

bool anySelected(const CommandTarget& viewer) {
    return !viewer.document().selection().selected().empty();
}

// A file to open (the panel's open field, a recent file) opens as a dropped one does; none:
// the desktop's file chooser.
void open(CommandTarget& viewer, const Argument& argument) {
    if (const auto* path = std::get_if<std::string>(&argument))
        viewer.open(*path);
    else
        viewer.chooseFile();
}

// A script's file is written as it is, without a notice over the view (tests compare what
// the window shows); F12's goes to the Pictures folder and says where.
void screenshot(CommandTarget& viewer, const Argument& argument) {
    if (const auto* path = std::get_if<std::string>(&argument))
        viewer.screenshot(*path);
    else
        viewer.screenshotToPictures();
}

void panel(CommandTarget& viewer, const Argument& argument) {
    viewer.view().panelVisible = on(argument);
    viewer.events().say("panel", [&](util::JsonWriter& j) { j.member("shown", on(argument)); });
}

void escape(CommandTarget& viewer, const Argument&) {
    if (const auto what = cancelOne(viewer))
        viewer.events().say("cancel", [&](util::JsonWriter& j) { j.member("what", *what); });
}

std::vector<CommandDef> windowCommands() {
    return {
        {CommandId::Help, "help", Kind::Switch,
         "show or hide this list of keys, mouse actions and commands",
         toggles({{GLFW_KEY_F1, 0}, {GLFW_KEY_SLASH, shift}}),
         [](CommandTarget& v, const Argument& a) {
             if (on(a) != v.helpOpen()) v.toggleHelp();
         },
         [](const CommandTarget& v) { return v.helpOpen(); }},
        {CommandId::Escape, "escape", Kind::None,
         "cancel: the help, a box drag, a model loading (cancel where a model was shown "
         "before it, else stop), a census, measure mode, then the selection and things A and B "
         "(never "
         "quits)",
         keys({{GLFW_KEY_ESCAPE, 0}}), escape},
        {CommandId::Quit, "quit", Kind::None, "quit idview (or close the window)",
         keys({{GLFW_KEY_Q, ctrl}}), [](CommandTarget& v, const Argument&) { v.quit(); }},
        {CommandId::Open, "open", Kind::OptionalText,
         "Open...: choose a model file in the desktop's file chooser; with a FILE (the panel's "
         "open field, a recent file), open that one",
         keys({{GLFW_KEY_O, ctrl}}), open},
        {CommandId::TypePath, "type-path", Kind::None,
         "type a model's path in the panel's open field", keys({{GLFW_KEY_L, ctrl}}),
         [](CommandTarget& v, const Argument&) { v.focusOpenField(); }},
        {CommandId::Screenshot, "screenshot", Kind::OptionalText,
         "save a PNG of the window in the Pictures folder (idview-DATE-TIME.png), or as FILE",
         keys({{GLFW_KEY_F12, 0}}), screenshot},
        {CommandId::Panel, "panel", Kind::Switch, "show or hide the panel",
         toggles({{GLFW_KEY_F9, 0}}), panel,
         [](const CommandTarget& v) { return v.view().panelVisible; }},
        {CommandId::Vsync, "vsync", Kind::Switch,
         "vsync on or off (off: frames as fast as they go)", toggles({{GLFW_KEY_V, 0}}),
         [](CommandTarget& v, const Argument& a) { v.view().vsync = on(a); },
         [](const CommandTarget& v) { return v.view().vsync; }},
        {CommandId::ReloadShaders, "reload-shaders", Kind::None,
         "reload the shaders from their folder", keys({{GLFW_KEY_R, 0}}),
         [](CommandTarget& v, const Argument&) { v.reloadShaders(); }},
        {CommandId::Cancel,
         "cancel",
         Kind::None,
         "stop the model loading and forget those queued; the model shown before it comes "
         "back (the panel's Cancel)",
         {},
         [](CommandTarget& v, const Argument&) { v.cancelLoads(); },
         nullptr,
         [](const CommandTarget& v) { return v.loading(); }},
        {CommandId::Stop,
         "stop",
         Kind::None,
         "stop the model loading here: what it shows stays, marked incomplete, and those "
         "queued are forgotten (the panel's Stop here)",
         {},
         [](CommandTarget& v, const Argument&) { v.stopLoads(); },
         nullptr,
         [](const CommandTarget& v) { return v.loading(); }},
        {CommandId::ClearRecent,
         "clear-recent",
         Kind::None,
         "empty the list of recent files",
         {},
         [](CommandTarget& v, const Argument&) { v.view().recentFiles.clear(); },
         nullptr,
         [](const CommandTarget& v) { return !v.view().recentFiles.empty(); }},
        {CommandId::Defaults,
         "defaults",
         Kind::None,
         "the settings kept between runs back to the defaults (the panel's Reset to defaults)",
         {},
         [](CommandTarget& v, const Argument&) { v.resetSettings(); }},
    };
}

std::vector<KeyBinding> viewKeys() {
    // The views follow the numpad habit Blender made common (1 front, 3 right, 7 top, with
    // Ctrl the opposite side, 0 isometric) and FreeCAD's own 2 top, 4 back, 5 bottom, 6 left.
    auto view = [](const char* name, std::vector<Chord> chords, const char* description) {
        return KeyBinding{std::move(chords), scene::findStandardView(name), description};
    };
    return {view("front", digit(1), "front view"),
            view("back", join(digit(1, ctrl), digit(4)), "back view"),
            view("right", digit(3), "right view"),
            view("left", join(digit(3, ctrl), digit(6)), "left view"),
            view("top", join(digit(7), digit(2)), "top view"),
            view("bottom", join(digit(7, ctrl), digit(5)), "bottom view"),
            view("isometric", digit(0), "isometric view")};
}

std::vector<CommandDef> cameraCommands() {
    return {
        {CommandId::Fit, "fit", Kind::None, "fit the selection, else the shown parts, in view",
         keys({{GLFW_KEY_F, 0}}), [](CommandTarget& v, const Argument&) { v.fitView(); }},
        {CommandId::ResetView, "reset-view", Kind::None, "back to the model's opening view",
         keys({{GLFW_KEY_HOME, 0}}),
         [](CommandTarget& v, const Argument&) { v.camera().resetView(); }},
        {CommandId::Ortho, "ortho", Kind::Switch, "orthographic projection (off: perspective)",
         toggles({{GLFW_KEY_O, 0}}), [](CommandTarget& v, const Argument& a) { v.setOrtho(on(a)); },
         [](const CommandTarget& v) { return v.settings().camera.ortho; }},
        {CommandId::View, "view", Kind::View, "a standard view, at the same distance", viewKeys(),
         [](CommandTarget& v, const Argument& a) {
             v.turnTo(*arg<const scene::StandardView*>(a));
         }},
        {CommandId::Explode,
         "explode",
         Kind::Explode,
         "move the parts apart by assembly level, from 0 (at rest) to 1",
         {},
         [](CommandTarget& v, const Argument& a) { v.document().setExplode(arg<float>(a)); }},
    };
}

std::vector<CommandDef> partCommands() {
    return {
        {CommandId::Hide, "hide", Kind::None, "hide the selected parts", keys({{GLFW_KEY_H, 0}}),
         hide, nullptr, anySelected},
        {CommandId::ShowAll, "show-all", Kind::None, "show every hidden part",
         keys({{GLFW_KEY_H, shift}}), showAll, nullptr,
         [](const CommandTarget& v) { return !v.document().selection().hidden().empty(); }},
        {CommandId::Isolate, "isolate", Kind::None, "show only the selected parts",
         keys({{GLFW_KEY_I, 0}}), isolate, nullptr, anySelected},
        {CommandId::Undo, "undo", Kind::None, "undo a hide, show or section change",
         keys({{GLFW_KEY_Z, ctrl}}), [](CommandTarget& v, const Argument&) { v.undo(); }},
        {CommandId::Redo, "redo", Kind::None, "redo what undo took back",
         keys({{GLFW_KEY_Z, ctrl | shift}, {GLFW_KEY_Y, ctrl}}),
         [](CommandTarget& v, const Argument&) { v.redo(); }},
        {CommandId::Xray, "xray", Kind::Switch,
         "X-ray: the parts outside the selection translucent, not picked (nothing selected: "
         "no change)",
         toggles({{GLFW_KEY_X, 0}}), [](CommandTarget& v, const Argument& a) { v.setXray(on(a)); },
         [](const CommandTarget& v) { return v.document().xray(); }},
        {CommandId::Measure, "measure", Kind::Switch,
         "measure mode: clicks place points (distance, angle) instead of selecting",
         toggles({{GLFW_KEY_M, 0}}),
         [](CommandTarget& v, const Argument& a) {
             if (on(a) != v.document().measure().on()) v.toggleMeasure();
         },
         [](const CommandTarget& v) { return v.document().measure().on(); }},
        {CommandId::Level,
         "level",
         Kind::Level,
         "what a click selects: the face (a part), its solid (object) or the assembly above",
         {},
         [](CommandTarget& v, const Argument& a) { v.view().selectLevel = arg<uint32_t>(a); }},
        {CommandId::Object,
         "object",
         Kind::Text,
         "select the parts of the objects of this name",
         {},
         [](CommandTarget& v, const Argument& a) {
             v.selectObjects(arg<std::string>(a), SelectMode::Replace);
         }},
        {CommandId::Node,
         "node",
         Kind::Node,
         "a node of the assembly tree, as its row does: select (a click), add (Ctrl+click), "
         "hide or show (its checkbox)",
         {},
         [](CommandTarget& v, const Argument& a) {
             const NodeTarget& node = arg<NodeTarget>(a);
             if (!v.actOnNode(node))
                 throw CommandError("no node of the assembly tree has the path '" + node.path +
                                    "'");
         }},
        {CommandId::Section,
         "section",
         Kind::Section,
         "a section plane in the first free slot of the panel's three (a fourth replaces the "
         "third); off: every plane off",
         {},
         [](CommandTarget& v, const Argument& a) {
             scene::Section section = v.document().section();
             const auto& plane = arg<std::optional<scene::SectionPlane>>(a);
             if (!plane)
                 section = {};
             else if (!section.add(*plane))
                 section.planes.back() = *plane;
             v.document().setSection(section, false);
         }},
        {CommandId::Census,
         "census",
         Kind::Census,
         "visibility census: VIEWSxSIZE runs one (views over a sphere, each SIZE pixels "
         "square); cancel stops it; select, hide or isolate its never-seen parts; here lists "
         "the parts of the window's picture by pixels; part ID selects that part; tint on|off "
         "colours each part by how much the last census saw it; export PATH writes what it saw "
         "(.glb: the seen parts; .step: the solids with a seen face, CAD models only)",
         {},
         [](CommandTarget& v, const Argument& a) { v.census(arg<CensusAsk>(a)); }},
    };
}

std::vector<CommandDef> renderCommands() {
    return {
        {CommandId::Edges, "edges", Kind::Switch, "edges on or off", toggles({{GLFW_KEY_E, 0}}),
         [](CommandTarget& v, const Argument& a) { v.settings().render.edges.on = on(a); },
         [](const CommandTarget& v) { return v.settings().render.edges.on; }},
        {CommandId::Renderer,
         "renderer",
         Kind::Technique,
         "switch the technique that draws (no-id too)",
         {},
         [](CommandTarget& v, const Argument& a) {
             v.settings().render.pipeline.technique = arg<const render::Technique*>(a);
         }},
        {CommandId::Mode,
         "mode",
         Kind::DrawMode,
         "switch the per-draw mode",
         {},
         [](CommandTarget& v, const Argument& a) {
             v.settings().render.pipeline.mode = arg<const render::DrawMode*>(a);
         }},
        {CommandId::Culling,
         "culling",
         Kind::CullMode,
         "culling off, by the frustum, or occlusion",
         {},
         [](CommandTarget& v, const Argument& a) {
             v.settings().render.culling.mode = arg<render::CullMode>(a);
         }},
        {CommandId::Freeze,
         "freeze",
         Kind::Switch,
         "keep drawing what the last culled frame chose while the camera moves",
         {},
         [](CommandTarget& v, const Argument& a) { v.settings().render.culling.freeze = on(a); },
         [](const CommandTarget& v) { return v.settings().render.culling.freeze; },
         [](const CommandTarget& v) {
             return v.settings().render.culling.mode != render::CullMode::Off;
         }},
        {CommandId::Sort,
         "sort",
         Kind::Switch,
         "sort the draw list once, by geometry then material (off: scene order)",
         {},
         [](CommandTarget& v, const Argument& a) { v.settings().render.draws.sortDraws = on(a); },
         [](const CommandTarget& v) { return v.settings().render.draws.sortDraws; }},
        {CommandId::Msaa,
         "msaa",
         Kind::Msaa,
         "samples per pixel",
         {},
         [](CommandTarget& v, const Argument& a) {
             v.settings().render.pipeline.msaa = arg<uint32_t>(a);
         }},
        {CommandId::Clear,
         "clear",
         Kind::ClearPath,
         "how frames clear and resolve: the scene pass, a compute pass, or the faster",
         {},
         [](CommandTarget& v, const Argument& a) {
             v.settings().render.clear = arg<render::ClearPath>(a);
         }},
        {CommandId::Copies,
         "copies",
         Kind::Copies,
         "model copies",
         {},
         [](CommandTarget& v, const Argument& a) { v.settings().scene.copies = arg<uint32_t>(a); }},
    };
}

std::vector<CommandDef> table() {
    std::vector<CommandDef> rows;
    for (auto group : {windowCommands, cameraCommands, partCommands, renderCommands})
        for (CommandDef& row : group()) rows.push_back(std::move(row));
    return rows;
}

} // namespace

const std::vector<CommandDef>& commands() {
    static const std::vector<CommandDef> rows = table();
    return rows;
}

const CommandDef& definition(CommandId id) {
    for (const CommandDef& row : commands())
        if (row.id == id) return row;
    throw std::logic_error("a command without a row in the command table");
}

const CommandDef* findCommand(std::string_view name) {
    for (const CommandDef& row : commands())
        if (name == row.name) return &row;
    return nullptr;
}

std::optional<Command> commandOfKey(int key, int mods) {
    const Chord pressed{key, mods & (GLFW_MOD_SHIFT | GLFW_MOD_CONTROL | GLFW_MOD_ALT)};
    for (const CommandDef& row : commands())
        for (const KeyBinding& binding : row.keys)
            for (const Chord& chord : binding.chords)
                if (chord == pressed) return Command{row.id, binding.argument};
    return std::nullopt;
}

void execute(Command command, CommandTarget& viewer) {
    const CommandDef& row = definition(command.id);
    if (auto* s = std::get_if<Switch>(&command.argument); s && *s == Switch::Toggle)
        *s = row.isOn(viewer) ? Switch::Off : Switch::On;
    viewer.events().say("command",
                        [&](util::JsonWriter& j) { j.member("command", commandWords(command)); });
    row.run(viewer, command.argument);
}

NodeTarget nodeOfRow(const std::vector<scene::TreeRow>& rows, size_t i, NodeAction action) {
    NodeTarget node{action, rows[i].path, 0};
    for (size_t j = 0; j < i; ++j) node.occurrence += rows[j].path == rows[i].path;
    return node;
}

std::optional<size_t> rowOfNode(const std::vector<scene::TreeRow>& rows, const NodeTarget& node) {
    uint32_t seen = 0;
    for (size_t i = 0; i < rows.size(); ++i)
        if (rows[i].path == node.path && seen++ == node.occurrence) return i;
    return std::nullopt;
}

bool enabled(CommandId id, const CommandTarget& viewer) {
    const CommandDef& row = definition(id);
    return !row.enabled || row.enabled(viewer);
}

std::optional<std::string> cancelOne(CommandTarget& viewer) {
    if (viewer.helpOpen()) {
        viewer.toggleHelp();
        return "help";
    }
    if (viewer.cancelBox()) return "box";
    if (viewer.view().browser) { // the panel's file browser (its filter takes Esc itself)
        viewer.view().browser.reset();
        return "file browser";
    }
    // A model loading: back to the model before it, or where there was none, what it shows
    // kept (a first model cancelled would leave nothing open).
    if (const auto load = viewer.modelLoading(); load && !load->stopping) {
        execute({load->modelBefore ? CommandId::Cancel : CommandId::Stop}, viewer);
        return "load";
    }
    if (viewer.censusRunning()) {
        execute({CommandId::Census, CensusAsk{CensusAction::Cancel}}, viewer);
        return "census";
    }
    if (viewer.document().measure().on()) {
        viewer.toggleMeasure();
        return "measure";
    }
    // The selection and things A and B (things.h) go together: A's and B's parts are selected.
    if (viewer.document().escape()) {
        viewer.selectionChanged();
        return "selection";
    }
    return std::nullopt;
}

} // namespace app
