// script.h - scripted input for the viewer (`--script FILE`), so tests can drive the
// real window: one line per step, `<seconds> <what> [args]`, run when that many seconds
// have passed since the model given at start showed (whole, or the first partial picture of
// a big CAD file). A line is either input as a hand gives it (keys, the pointer, the window)
// or a wait of the test's own, played into the same handlers as real input; or it is a
// command of the viewer by its name (commands.h): the same Command a key or the panel makes,
// run by the same executor. Parsing is plain C++ and unit-tested.
//
// Input and waits:
//   0.5 key V               press and release a key (A-Z, 0-9, F1-F12, ESC, SPACE, ENTER, TAB,
//                           HOME, /), with modifiers as in shift+H, ctrl+A or alt+X (held
//                           as their own keys around it, as a hand does): the keys of the
//                           command table, ctrl+Z undoes, ctrl+Q quits
//   0.6 type /tmp/a b.glb   characters typed into the panel's focused field (the rest of the
//                           line, ASCII), as GLFW hands them over
//   1   move 320 200        cursor to window coordinates (top-left origin)
//   1.1 leave               the pointer leaves the window (GLFW's cursor-leave event)
//   1.1 unfocus             the window loses the keyboard focus (another window took it)
//   1.2 click 320 200       move there, press and release the left button; `click ... ctrl`
//                           holds Ctrl (thing B of the Inspect panel, things.h)
//   1.3 dblclick 320 200    move there and click twice at once (a double-click)
//   1.5 drag 100 100 300 120  left-button drag (orbit) from the first point to the second
//   1.6 box 10 10 200 150   box selection: Shift + left drag between the corners; `box ... add`
//                           holds Ctrl (adds), `box ... remove` Alt (removes)
//   2   scroll 2            wheel steps, positive zooms in
//   2.5 resize 800 500      window size
//   4.5 drop model.glb      a file dropped on the window
//   4.6 loaded              wait until every dropped model has loaded (they load while
//                           frames go on), however long that takes
//   4.7 solids 3            wait until the model loading shows 3 solids (a big CAD file
//                           shown as it loads), or is no longer loading
//   4.8 frames 5            let 5 frames pass before the next line (results of a pick
//                           arrive a frame or two later, however slow the frames are)
//   4.85 redraw             the next frame draws everything anew (with what follows at the
//                           same time, in the same frame)
//   4.87 blink strong       the hovered part's blink held at its strong or weak step, or
//                           back on the clock (`blink clock`)
//   4.9 rest 4              leave the viewer alone for 4 seconds from when the line runs:
//                           what follows waits, and nothing scripted asks for a frame
//                           meanwhile (however late the line ran on a slow machine)
//   4.9 pipeline hold       pipeline builds wait on their worker until `pipeline release`, so
//                           a test holds "a build is pending" as long as it likes; `pipeline
//                           ready` waits until none is being built or awaited (never while
//                           held)
//   4.95 inspect hold       the Inspect panel's questions wait on their worker until `inspect
//                           release` (the panel says "computing..." meanwhile); `inspect
//                           ready` waits until the answer is in (never while held)
//   5   census-done         wait until the census running (`census 12x128`) has finished or
//                           was cancelled, a `census here` has counted, and a `census
//                           export` has been written or refused
//
// Commands, each by its row's name with the argument it takes (F1 in the viewer lists them
// all with their keys); a switch takes on or off, and without either toggles as its key does:
//   1.4 level solid         what a click selects: face, solid or assembly (the panel's radio
//                           buttons; face is a part of any model, solid its object)
//   1.7 object bolt M10 #3  select the parts of the objects with this name (the rest of the line)
//   1.8 node hide car/wheel front left  a node of the panel's assembly tree by its path
//                           (names below the root joined by '/'; nothing after the word is
//                           the root): select (as a row click), add (Ctrl+click), hide or
//                           show (its checkbox)
//   3   renderer tri-fs     switch technique (no-id too), as the panel's combo box does
//   3   mode push           switch per-draw mode; `culling off|frustum|occlusion`, `freeze
//                           on|off` and `clear auto|pass|compute` as the panel's widgets
//   3.5 msaa 4              samples per pixel
//   3.5 sort off            draws in scene order (on: sorted once), as the panel's checkbox
//   3.5 defaults            the panel's Reset to defaults: the kept settings back to defaults
//   3.6 copies 3            model copies, as the panel's field does
//   3.65 census 12x128      the Visibility section's census (docs/viewer.md): VIEWSxSIZE runs
//                           one; `census cancel`, `census select|hide|isolate` (its
//                           never-seen parts), `census here` (the window's parts by pixels),
//                           `census export PATH` (Export seen...: .glb or .step)
//   3.7 section y,0,flip    a section plane as --section gives it, in the first free slot of
//                           the panel's three (a fourth replaces the third); `section off`
//                           turns them all off
//   3.8 view top            a standard view (scene/standard_view.h), as the keys 1, 3, 7, 0 do
//   3.9 ortho on            orthographic projection (off: perspective; `ortho` alone: as O)
//   3.9 xray on             X-ray on (off: off), as X and the panel's checkbox do
//   3.95 explode 0.5        the exploded view, 0 (at rest) to 1, as the panel's slider
//   3.97 hide               hide the selected parts, as H and the panel's button do; so
//                           `show-all`, `isolate`, `fit`, `reset-view`, `undo`, `redo`,
//                           `escape` (Esc), `help`, `panel`, `edges`, `vsync`, `measure`,
//                           `type-path`, `reload-shaders`
//   4   screenshot out.png  the presented image, panel included (without a file: F12's, in
//                           the Pictures folder)
//   4.4 open model.glb      open a file as the panel's open field does (without: Ctrl+O's
//                           file chooser)
//   4.7 cancel              the panel's Cancel: stop the model loading and those queued; the
//                           model shown before it comes back (`stop`: the panel's Stop here,
//                           what the load shows stays, marked incomplete)
//   4.75 clear-recent       the recent files' "clear list" entry
//   5   quit
//
// Blank lines and lines starting with '#' are ignored.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "app/viewer/commands/command.h"

namespace app {

// What a line asks for: input or a wait (above), or a command.
enum class ScriptOp {
    Key,
    Type,
    Move,
    Click,
    DoubleClick,
    Drag,
    Box,
    Scroll,
    Leave,
    Unfocus,
    Resize,
    Drop,
    Loaded,
    Solids,
    Frames,
    Redraw,
    Blink,
    Rest,
    Pipeline,
    Inspect,
    CensusDone,
    Command,
};

struct ScriptLine {
    double seconds = 0.0;
    ScriptOp op = ScriptOp::Frames;
    std::string text;               // Key: its name; Type: the text; Drop: the file; Blink,
                                    // Pipeline, Inspect: the word
    int key = 0;                    // Key: the GLFW key code
    int mods = 0;                   // Key, Box, Click: GLFW modifier bits held
    std::array<double, 4> values{}; // coordinates, wheel steps, window size, frames, seconds,
                                    // solids
    std::optional<Command> command; // Command: what it asks for
    std::string where;              // "file:line", for messages while it runs
};

// A script that cannot run; what() is "file:line: what is wrong".
struct ScriptError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// `name` is the file name used in messages. Throws ScriptError at the first bad line.
std::vector<ScriptLine> parseScript(const std::string& text, const std::string& name);
// Reads and parses a file; throws ScriptError (also when it cannot be read).
std::vector<ScriptLine> loadScript(const std::string& path);

// Which of `words` `word` is, for a line named `name` that takes one of them; throws
// std::invalid_argument "'NAME' takes a, b or c, not 'x'" when none.
size_t oneOfWords(const char* name, const std::string& word, std::span<const char* const> words);
// A number as scripts write it: the whole word, finite.
bool parseNumber(const std::string& text, double& value);
// The GLFW key code of a key name as scripts spell it (case-insensitive); nullopt if unknown.
std::optional<int> scriptKeyCode(const std::string& name);
// "shift+ctrl+H": the key code and the GLFW modifier bits; nullopt if either is unknown.
std::optional<std::pair<int, int>> scriptKeyChord(const std::string& name);

// Hands out lines in time order as their time comes.
class ScriptPlayer {
  public:
    ScriptPlayer() = default;
    // Lines with equal times keep their order in the file.
    explicit ScriptPlayer(std::vector<ScriptLine> lines);

    // The lines due at `seconds` (the script's clock) that were not handed out yet.
    std::vector<ScriptLine> due(double seconds);
    // The time of the next line, so an idle (minimised) viewer knows when to wake up.
    std::optional<double> nextTime() const;
    bool finished() const { return next_ >= lines_.size(); }

  private:
    std::vector<ScriptLine> lines_;
    size_t next_ = 0;
};

} // namespace app
