// test_cli_desktop.cpp - the command line as the desktop calls it: the model as the one
// argument that is no flag (the launcher's `idview %f`), file:// URIs (Nautilus' %u, a
// thumbnailer's %i), and --thumbnail's flags. (Beside test_cli.cpp, which is near its 500 lines.)
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/cli.h"

using app::Options;
using app::parseArgs;
using app::UsageError;
using Args = std::vector<std::string>;

// The message of the UsageError `args` throws, or "" when they parse.
static std::string refusal(const Args& args) {
    try {
        parseArgs(args);
    } catch (const UsageError& e) {
        return e.what();
    }
    return "";
}

TEST(CliDesktop, TheArgumentThatIsNoFlagIsTheModel) {
    const Options positional = parseArgs(Args{"part.step", "--edges"});
    EXPECT_EQ(positional.live.scene.model, "part.step");
    EXPECT_EQ(positional.live.scene, parseArgs(Args{"--edges", "--model", "part.step"}).live.scene);
    EXPECT_EQ(parseArgs(Args{"--headless", "/tmp/a b.glb"}).live.scene.model, "/tmp/a b.glb");
    // Anywhere on the line, flags' values never taken for it.
    EXPECT_EQ(parseArgs(Args{"--frames", "3", "x.iges"}).live.scene.model, "x.iges");
}

TEST(CliDesktop, OneModelAndTyposAreRefusedInOneLine) {
    EXPECT_EQ(refusal({"a.step", "b.step"}), "one model at a time: 'b.step' after 'a.step'");
    EXPECT_EQ(refusal({"--model", "a.step", "b.step"}),
              "one model at a time: 'b.step' after 'a.step'");
    EXPECT_EQ(refusal({"a.step", "--model", "b.step"}),
              "one model at a time: --model after 'a.step'");
    EXPECT_EQ(refusal({"-model", "a.step"}), "unknown option '-model'");
    EXPECT_EQ(refusal({"a.step", "--edgse"}), "unknown option '--edgse'");
}

TEST(CliDesktop, FileUrisAreDecodedToPaths) {
    EXPECT_EQ(parseArgs(Args{"file:///home/me/my%20part%2B1.step"}).live.scene.model,
              "/home/me/my part+1.step");
    EXPECT_EQ(parseArgs(Args{"--model", "file://localhost/tmp/x.glb"}).live.scene.model,
              "/tmp/x.glb");
    EXPECT_EQ(parseArgs(Args{"file:///a/100%.stl"}).live.scene.model, "/a/100%.stl");
    EXPECT_EQ(refusal({"file://server/share/a.step"}),
              "'file://server/share/a.step' is not a local file URI (file:///path)");
}

TEST(CliDesktop, ThumbnailIsOneSquareFrameHeadless) {
    const Options o = parseArgs(
        Args{"--thumbnail", "128", "--screenshot", "out.png", "--size", "64x32", "m.step"});
    EXPECT_TRUE(o.headless);
    EXPECT_EQ(o.thumbnail.size, 128u);
    EXPECT_EQ(o.width, 128u);
    EXPECT_EQ(o.height, 128u);
    EXPECT_EQ(o.frames, 1u);
    EXPECT_FLOAT_EQ(o.thumbnail.seconds, 10.0f);
    EXPECT_EQ(o.thumbnail.memoryMib, 4096u);
    const Options bounded = parseArgs(Args{"--thumbnail=256", "--screenshot=o.png",
                                           "--thumbnail-timeout", "0.5", "--thumbnail-memory=512"});
    EXPECT_FLOAT_EQ(bounded.thumbnail.seconds, 0.5f);
    EXPECT_EQ(bounded.thumbnail.memoryMib, 512u);
    EXPECT_EQ(parseArgs(Args{}).thumbnail.size, 0u);
    EXPECT_EQ(refusal({"--thumbnail", "128", "m.step"}),
              "--thumbnail needs --screenshot FILE, where the PNG goes");
    EXPECT_NE(refusal({"--thumbnail", "0", "--screenshot", "o.png"}), "");
    EXPECT_NE(refusal({"--thumbnail", "8", "--screenshot", "o.png", "--thumbnail-timeout", "0"}),
              "");
    EXPECT_NE(refusal({"--thumbnail", "8", "--screenshot", "o.png", "--thumbnail-memory", "8"}),
              "");
}
