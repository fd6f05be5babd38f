// test_input_script.cpp - the viewer's --script format: every kind of line parses (input,
// waits, and the command table's rows by name), bad lines name file and line, and the player
// hands lines out in time order.
#include <gtest/gtest.h>

#include "app/viewer/commands/commands.h"
#include "app/viewer/commands/script.h"
#include "render/technique.h"
#include "scene/standard_view.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace {

std::string errorOf(const std::string& text) {
    try {
        app::parseScript(text, "s.txt");
    } catch (const app::ScriptError& e) {
        return e.what();
    }
    return "(no error)";
}

app::Command command(app::CommandId id, app::Argument argument = {}) {
    return {id, std::move(argument)};
}

} // namespace

TEST(InputScript, ParsesEveryKindOfLine) {
    const std::string technique = render::techniques().back().name;
    const auto commands = app::parseScript("# a comment\n"
                                           "0.5 key V\n"
                                           "\n"
                                           "1 move 10 20\n"
                                           "1.5 click 30.5 40\n"
                                           "2 drag 1 2 3 4\n"
                                           "2.5 scroll -2\n"
                                           "3 resize 800 600\r\n"
                                           "3.5 renderer " +
                                               technique +
                                               "\n"
                                               "4 mode mdi-attribute\n"
                                               "4.5 msaa 4\n"
                                               "5 screenshot out.png\n"
                                               "  6 key esc\n"
                                               "6.5 drop m.glb\n"
                                               "7 quit\n",
                                           "s.txt");
    ASSERT_EQ(commands.size(), 13u);
    EXPECT_EQ(commands[0].op, app::ScriptOp::Key);
    EXPECT_EQ(commands[0].key, GLFW_KEY_V);
    EXPECT_DOUBLE_EQ(commands[0].seconds, 0.5);
    EXPECT_EQ(commands[0].where, "s.txt:2");
    EXPECT_EQ(commands[1].op, app::ScriptOp::Move);
    EXPECT_DOUBLE_EQ(commands[1].values[1], 20.0);
    EXPECT_DOUBLE_EQ(commands[2].values[0], 30.5);
    EXPECT_EQ(commands[3].op, app::ScriptOp::Drag);
    EXPECT_DOUBLE_EQ(commands[3].values[3], 4.0);
    EXPECT_DOUBLE_EQ(commands[4].values[0], -2.0);
    EXPECT_EQ(commands[5].op, app::ScriptOp::Resize);
    EXPECT_EQ(commands[6].op, app::ScriptOp::Command);
    EXPECT_EQ(commands[6].command,
              command(app::CommandId::Renderer, render::findTechnique(technique)));
    EXPECT_EQ(commands[7].command,
              command(app::CommandId::Mode, render::findDrawMode("mdi-attribute")));
    EXPECT_EQ(commands[8].command, command(app::CommandId::Msaa, 4u));
    EXPECT_EQ(commands[9].command, command(app::CommandId::Screenshot, std::string("out.png")));
    EXPECT_EQ(commands[10].key, GLFW_KEY_ESCAPE);
    EXPECT_EQ(commands[10].where, "s.txt:13");
    EXPECT_EQ(commands[11].op, app::ScriptOp::Drop);
    EXPECT_EQ(commands[11].text, "m.glb");
    EXPECT_EQ(commands[12].command, command(app::CommandId::Quit));
}

// The panel's Cancel as a script line: no arguments.
TEST(InputScript, Cancel) {
    const auto commands = app::parseScript("1 drop m.step\n2 cancel\n", "s.txt");
    ASSERT_EQ(commands.size(), 2u);
    EXPECT_EQ(commands[1].command, command(app::CommandId::Cancel));
    EXPECT_THROW(app::parseScript("1 cancel now\n", "s.txt"), app::ScriptError);
}

TEST(InputScript, BoxObjectAndModifiers) {
    const auto commands = app::parseScript("1 box 10 20 300 200\n"
                                           "2 box 1 2 3 4 add\n"
                                           "3 box 1 2 3 4 remove\n"
                                           "4 object  bolt M10 #12 \n"
                                           "5 key shift+h\n"
                                           "6 key CTRL+alt+E\n"
                                           "7 loaded\n",
                                           "s.txt");
    ASSERT_EQ(commands.size(), 7u);
    EXPECT_EQ(commands[6].op, app::ScriptOp::Loaded);
    EXPECT_EQ(commands[0].op, app::ScriptOp::Box);
    EXPECT_DOUBLE_EQ(commands[0].values[2], 300.0);
    EXPECT_EQ(commands[0].mods, GLFW_MOD_SHIFT); // a plain box replaces, as Shift+drag does
    EXPECT_EQ(commands[1].mods, GLFW_MOD_CONTROL);
    EXPECT_EQ(commands[2].mods, GLFW_MOD_ALT);
    // The rest of the line, spaces inside kept.
    EXPECT_EQ(commands[3].command, command(app::CommandId::Object, std::string("bolt M10 #12")));
    EXPECT_EQ(commands[4].key, GLFW_KEY_H);
    EXPECT_EQ(commands[4].mods, GLFW_MOD_SHIFT);
    EXPECT_EQ(commands[5].key, GLFW_KEY_E);
    EXPECT_EQ(commands[5].mods, GLFW_MOD_CONTROL | GLFW_MOD_ALT);
    for (const char* bad : {"1 box 1 2 3\n", "1 box 1 2 3 4 toggle\n", "1 object\n",
                            "1 key super+H\n", "1 key shift+\n", "1 box -1 2 3 4\n"})
        EXPECT_THROW(app::parseScript(bad, "s.txt"), app::ScriptError) << bad;
}

// A Ctrl+click (thing B of the Inspect panel): the click holds Ctrl; a plain click nothing.
TEST(InputScript, ClickWithCtrl) {
    const auto commands = app::parseScript("1 click 10 20 ctrl\n2 click 10 20\n", "s.txt");
    ASSERT_EQ(commands.size(), 2u);
    EXPECT_EQ(commands[0].op, app::ScriptOp::Click);
    EXPECT_DOUBLE_EQ(commands[0].values[1], 20.0);
    EXPECT_EQ(commands[0].mods, GLFW_MOD_CONTROL);
    EXPECT_EQ(commands[1].mods, 0);
    for (const char* bad : {"1 click 1 2 shift\n", "1 click 1 2 ctrl x\n", "1 click 1\n"})
        EXPECT_THROW(app::parseScript(bad, "s.txt"), app::ScriptError) << bad;
}

TEST(InputScript, KeyNames) {
    EXPECT_EQ(app::scriptKeyCode("f"), GLFW_KEY_F);
    EXPECT_EQ(app::scriptKeyCode("F1"), GLFW_KEY_F1);
    EXPECT_EQ(app::scriptKeyCode("f12"), GLFW_KEY_F12);
    EXPECT_EQ(app::scriptKeyCode("7"), GLFW_KEY_7);
    EXPECT_EQ(app::scriptKeyCode("Escape"), GLFW_KEY_ESCAPE);
    EXPECT_FALSE(app::scriptKeyCode("F13").has_value());
    EXPECT_FALSE(app::scriptKeyCode("FOO").has_value());
    EXPECT_FALSE(app::scriptKeyCode("").has_value());
}

TEST(InputScript, BadLinesNameFileAndLine) {
    EXPECT_EQ(errorOf("1 quit\nsoon quit\n"),
              "s.txt:2: expected '<seconds> <command> [args]', and 'soon' is not a time in "
              "seconds (0 or more)");
    EXPECT_EQ(errorOf("-1 quit"), "s.txt:1: expected '<seconds> <command> [args]', and '-1' is "
                                  "not a time in seconds (0 or more)");
    EXPECT_EQ(errorOf("1\n"), "s.txt:1: a command must follow the time");
    EXPECT_NE(errorOf("\n\n1 jump\n").find("s.txt:3: unknown command 'jump'"), std::string::npos);
    EXPECT_EQ(errorOf("1 move 10\n"), "s.txt:1: 'move' takes: move X Y");
    EXPECT_EQ(errorOf("1 click 1 2 3 4\n"), "s.txt:1: 'click' takes: click X Y [ctrl]");
    EXPECT_EQ(errorOf("1 click 1 2 3\n"), "s.txt:1: a click holds ctrl or nothing, not '3'");
    EXPECT_EQ(errorOf("1 move ten 20\n"), "s.txt:1: 'ten' is not a number (move X Y)");
    EXPECT_EQ(errorOf("1 move -1 20\n"), "s.txt:1: window coordinates cannot be negative");
    EXPECT_EQ(errorOf("1 resize 0 20\n"),
              "s.txt:1: window size must be whole numbers from 1 to 16384");
    EXPECT_EQ(errorOf("1 msaa 3\n"), "s.txt:1: msaa takes 1, 2, 4 or 8");
    EXPECT_EQ(errorOf("1 clear fast\n"),
              "s.txt:1: 'clear' takes auto, pass or compute, not 'fast'");
    EXPECT_NE(errorOf("1 key HYPER\n").find("s.txt:1: unknown key 'HYPER'"), std::string::npos);
    EXPECT_NE(errorOf("1 renderer fastest\n").find("s.txt:1: unknown renderer 'fastest'"),
              std::string::npos);
    // Every technique of the registry is a renderer the viewer can switch to, no-id included.
    for (const auto& t : render::techniques())
        EXPECT_EQ(errorOf("1 renderer " + std::string(t.name) + "\n"), "(no error)") << t.name;
    EXPECT_NE(errorOf("1 mode pull\n").find("s.txt:1: unknown mode 'pull'"), std::string::npos);
    EXPECT_EQ(errorOf("1 quit now\n"), "s.txt:1: 'quit' takes: quit");
    EXPECT_EQ(errorOf("1 screenshot\n"), "(no error)"); // F12's: in the Pictures folder
    EXPECT_EQ(errorOf("1 section y,0,flip\n2 section off\n3 section x,-2.5\n"), "(no error)");
    EXPECT_NE(errorOf("1 section w,0\n").find("s.txt:1: 'section' expects AXIS,VALUE"),
              std::string::npos);
    EXPECT_NE(errorOf("1 section on\n").find(", or off"), std::string::npos);
    EXPECT_EQ(errorOf("1 dblclick 3 4\n2 level solid\n3 level assembly\n4 level face\n"),
              "(no error)");
    EXPECT_EQ(errorOf("1 level body\n"),
              "s.txt:1: 'level' takes face, solid or assembly, not 'body'");
    EXPECT_EQ(errorOf("1 dblclick -1 4\n"), "s.txt:1: window coordinates cannot be negative");
    EXPECT_EQ(errorOf("1 node hide\n2 node select a/b c\n"), "(no error)");
    EXPECT_EQ(app::parseScript("1 node add a/b c \n", "s.txt")[0].command,
              command(app::CommandId::Node, app::NodeTarget{app::NodeAction::Add, "a/b c", 0}));
    EXPECT_NE(errorOf("1 node drop a\n").find("not 'drop'"), std::string::npos);
}

TEST(InputScript, MissingFileIsAnError) {
    EXPECT_THROW(app::loadScript("/nonexistent/script.txt"), app::ScriptError);
}

TEST(InputScript, PlayerHandsOutCommandsInTimeOrder) {
    app::ScriptPlayer player(app::parseScript("2 key A\n1 key B\n1 key C\n3 quit\n", "s"));
    EXPECT_EQ(player.nextTime(), 1.0);
    EXPECT_TRUE(player.due(0.5).empty());
    const auto first = player.due(1.0);
    ASSERT_EQ(first.size(), 2u); // equal times keep the file's order
    EXPECT_EQ(first[0].text, "B");
    EXPECT_EQ(first[1].text, "C");
    const auto rest = player.due(10.0);
    ASSERT_EQ(rest.size(), 2u);
    EXPECT_EQ(rest[0].text, "A");
    EXPECT_EQ(rest[1].command, command(app::CommandId::Quit));
    EXPECT_TRUE(player.finished());
    EXPECT_FALSE(player.nextTime().has_value());
}

TEST(InputScript, FramesWaitsAWholeNumberOfFrames) {
    const auto commands = app::parseScript("1 frames 6\n", "s.txt");
    ASSERT_EQ(commands.size(), 1u);
    EXPECT_EQ(commands[0].op, app::ScriptOp::Frames);
    EXPECT_EQ(commands[0].values[0], 6.0);
    EXPECT_THROW(app::parseScript("1 frames 0\n", "s.txt"), app::ScriptError);
    EXPECT_THROW(app::parseScript("1 frames 2.5\n", "s.txt"), app::ScriptError);
}

// `solids N` waits for a model loading to show N solids; the stop command is a row too.
TEST(InputScript, SolidsWaitsAWholeCountAndStopIsACommand) {
    const auto commands = app::parseScript("1 solids 7\n2 stop\n", "s.txt");
    ASSERT_EQ(commands.size(), 2u);
    EXPECT_EQ(commands[0].op, app::ScriptOp::Solids);
    EXPECT_EQ(commands[0].values[0], 7.0);
    ASSERT_TRUE(commands[1].command.has_value());
    EXPECT_EQ(commands[1].command->id, app::CommandId::Stop);
    EXPECT_THROW(app::parseScript("1 solids 0\n", "s.txt"), app::ScriptError);
    EXPECT_THROW(app::parseScript("1 solids 1.5\n", "s.txt"), app::ScriptError);
}

// `view NAME` takes every standard view the registry lists, and nothing else; `ortho` takes
// on or off.
// The panel's sort draws once and Reset to defaults as script lines.
TEST(InputScript, SortAndDefaults) {
    const auto commands = app::parseScript("1 sort off\n2 sort on\n3 defaults\n", "s.txt");
    ASSERT_EQ(commands.size(), 3u);
    EXPECT_EQ(commands[0].command, command(app::CommandId::Sort, app::Switch::Off));
    EXPECT_EQ(commands[1].command, command(app::CommandId::Sort, app::Switch::On));
    EXPECT_EQ(commands[2].command, command(app::CommandId::Defaults));
    EXPECT_EQ(errorOf("1 sort maybe\n"), "s.txt:1: 'sort' takes on or off, not 'maybe'");
    EXPECT_THROW(app::parseScript("1 defaults now\n", "s.txt"), app::ScriptError);
}

// The two workers a script holds, releases and waits for: pipeline builds and Inspect's.
TEST(InputScript, PipelineAndInspectHoldReleaseAndWait) {
    for (const auto& [word, op] : {std::pair{std::string("pipeline"), app::ScriptOp::Pipeline},
                                   std::pair{std::string("inspect"), app::ScriptOp::Inspect}}) {
        const auto commands = app::parseScript(
            "1 " + word + " hold\n2 " + word + " release\n3 " + word + " ready\n", "s.txt");
        ASSERT_EQ(commands.size(), 3u);
        EXPECT_EQ(commands[0].op, op);
        EXPECT_EQ(commands[0].text, "hold");
        EXPECT_EQ(commands[1].text, "release");
        EXPECT_EQ(commands[2].text, "ready");
        EXPECT_EQ(errorOf("1 " + word + " now\n"),
                  "s.txt:1: '" + word + "' takes hold, release or ready, not 'now'");
        EXPECT_EQ(errorOf("1 " + word + "\n"),
                  "s.txt:1: '" + word + "' takes: " + word + " hold|release|ready");
    }
}

TEST(InputScript, ViewAndOrthoTakeTheRegistrysNames) {
    for (const scene::StandardView& view : scene::standardViews()) {
        const auto commands = app::parseScript("1 view " + std::string(view.name) + "\n", "s.txt");
        ASSERT_EQ(commands.size(), 1u);
        EXPECT_EQ(commands[0].command, command(app::CommandId::View, &view));
    }
    EXPECT_EQ(errorOf("1 view sideways\n"),
              "s.txt:1: unknown view 'sideways' (known: " + scene::standardViewNames() + ")");
    EXPECT_EQ(errorOf("1 view\n"), "s.txt:1: 'view' takes: view NAME");
    // The switches: on and off, nothing else; without a word they toggle, as their keys do.
    for (const auto& [word, id] : {std::pair{std::string("ortho"), app::CommandId::Ortho},
                                   std::pair{std::string("xray"), app::CommandId::Xray}}) {
        const auto on =
            app::parseScript("1 " + word + " on\n2 " + word + " off\n3 " + word + "\n", "s.txt");
        ASSERT_EQ(on.size(), 3u) << word;
        EXPECT_EQ(on[0].command, command(id, app::Switch::On));
        EXPECT_EQ(on[1].command, command(id, app::Switch::Off));
        EXPECT_EQ(on[2].command, command(id, app::Switch::Toggle));
        EXPECT_EQ(errorOf("1 " + word + " yes\n"),
                  "s.txt:1: '" + word + "' takes on or off, not 'yes'");
        EXPECT_EQ(errorOf("1 " + word + " on off\n"),
                  "s.txt:1: '" + word + "' takes: " + word + " [on|off]");
    }
    // The unknown-command message lists the input lines and the commands, these among them.
    const std::string unknown = errorOf("1 jump\n");
    for (const char* name : {" key,", " pipeline,", " view,", " ortho,", " copies)"})
        EXPECT_NE(unknown.find(name), std::string::npos) << name << " in " << unknown;
}

// `explode F`, the panel's slider: 0 to 1.
TEST(InputScript, ExplodeTakesZeroToOne) {
    const auto commands = app::parseScript("1 explode 0.6\n2 explode 0\n", "s.txt");
    ASSERT_EQ(commands.size(), 2u);
    EXPECT_EQ(commands[0].command, command(app::CommandId::Explode, 0.6f));
    EXPECT_EQ(commands[1].command, command(app::CommandId::Explode, 0.0f));
    EXPECT_EQ(errorOf("1 explode 1.5\n"), "s.txt:1: explode takes a number from 0 to 1");
    EXPECT_EQ(errorOf("1 explode -1\n"), "s.txt:1: explode takes a number from 0 to 1");
    EXPECT_EQ(errorOf("1 explode wide\n"), "s.txt:1: 'wide' is not a number (explode F (0 to 1))");
}

TEST(InputScript, TypeTakesTheRestOfTheLine) {
    const auto commands = app::parseScript("1 type /tmp/a model.glb \n2 key ctrl+O\n", "s.txt");
    ASSERT_EQ(commands.size(), 2u);
    EXPECT_EQ(commands[0].op, app::ScriptOp::Type);
    EXPECT_EQ(commands[0].text, "/tmp/a model.glb");
    EXPECT_EQ(commands[1].key, GLFW_KEY_O);
    EXPECT_THROW(app::parseScript("1 type\n", "s.txt"), app::ScriptError);
}
