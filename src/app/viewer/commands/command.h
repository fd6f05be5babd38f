// command.h - a viewer action as a value: which command, and its argument where it has one
// (a view, a renderer, a sample count, on or off). A key press, a panel widget and a script
// line each make one, and commands.h's execute() carries every one out, so the three ways to
// ask for an action cannot drift apart.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include "render/settings.h"
#include "scene/section.h"

namespace render {
struct Technique;
struct DrawMode;
} // namespace render
namespace scene {
struct StandardView;
}

namespace app {

// One per row of the command table (commands.cpp), in its groups.
enum class CommandId : uint8_t {
    // The window, files and kept settings.
    Help,
    Escape,
    Quit,
    Open,
    TypePath,
    Screenshot,
    Panel,
    Vsync,
    ReloadShaders,
    Cancel,
    Stop,
    ClearRecent,
    Defaults,
    // The camera.
    Fit,
    ResetView,
    Ortho,
    View,
    Explode,
    // The parts.
    Hide,
    ShowAll,
    Isolate,
    Undo,
    Redo,
    Xray,
    Measure,
    Level,
    Object,
    Node,
    Section,
    Census,
    // Rendering.
    Edges,
    Renderer,
    Mode,
    Culling,
    Freeze,
    Sort,
    Msaa,
    Clear,
    Copies,
};
inline constexpr size_t commandCount = size_t(CommandId::Copies) + 1;

// The argument of a command that turns something on or off. Keys toggle; the panel's
// checkboxes and a script say which. The executor settles a toggle against the state it
// finds, so what runs (and its event line) is always on or off.
enum class Switch : uint8_t { Off, On, Toggle };

// A node of the assembly tree, as its row's click (select, Ctrl: add) and checkbox (hide,
// show) act on it. Two objects of one path are two rows: `occurrence` says which (a script
// names the first).
enum class NodeAction : uint8_t { Select, Add, Hide, Show };
struct NodeTarget {
    NodeAction action = NodeAction::Select;
    std::string path; // names below the root joined by '/'; "" is the root
    uint32_t occurrence = 0;
    bool operator==(const NodeTarget&) const = default;
};

// The Visibility section's census (census_state.h): run one of `views` x `size`, cancel it,
// act on the parts it never saw (select, hide, isolate: hide all others), or count the parts
// of the window's picture (here); Part selects one part, as a row of here's list does; Tint
// turns the tint by visibility on or off; Export writes what it saw to `path` (.glb, .step).
enum class CensusAction : uint8_t { Run, Cancel, Select, Hide, Isolate, Here, Part, Tint, Export };
struct CensusAsk {
    CensusAction action = CensusAction::Run;
    uint32_t views = 0, size = 0; // Run's
    uint32_t part = 0;            // Part's
    bool on = false;              // Tint's
    std::string path{};           // Export's
    bool operator==(const CensusAsk&) const = default;
};

// What a command takes (commands.h's ArgumentKind says which alternative): nothing, on/off,
// a number (samples, copies, the selection level), the explode fraction, a file or object
// name, a registry entry, a section plane (nullopt: all off), a tree node or a census ask.
using Argument =
    std::variant<std::monostate, Switch, uint32_t, float, std::string, const scene::StandardView*,
                 const render::Technique*, const render::DrawMode*, render::CullMode,
                 render::ClearPath, std::optional<scene::SectionPlane>, NodeTarget, CensusAsk>;

struct Command {
    CommandId id = CommandId::Help;
    Argument argument{};
    bool operator==(const Command&) const = default;
};

} // namespace app
