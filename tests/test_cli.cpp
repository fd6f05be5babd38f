// test_cli.cpp - command-line parsing: every flag, both value spellings, and every refusal.
#include <gtest/gtest.h>

#include "app/benchmark.h"
#include "app/cli.h"

using app::Options;
using app::parseArgs;
using app::UsageError;

TEST(Cli, DefaultsWithoutArguments) {
    Options o = parseArgs(std::vector<std::string>{});
    EXPECT_FALSE(o.headless);
    EXPECT_FALSE(o.validation);
    EXPECT_EQ(o.width, 1280u);
    EXPECT_EQ(o.height, 720u);
    EXPECT_EQ(o.scene, ""); // the default model
    EXPECT_EQ(o.model, "");
    EXPECT_EQ(o.parts, "primitives");
    EXPECT_EQ(o.copies, 1u);
    EXPECT_EQ(o.searchBatch, 16u);
    EXPECT_FALSE(o.stats);
    EXPECT_EQ(o.renderer, "per-draw");
    EXPECT_EQ(o.mode, "push");
    EXPECT_FLOAT_EQ(o.partWeight, 0.5f);
}

TEST(Cli, EveryFlagIsApplied) {
    Options o = parseArgs({"--headless",
                           "--size",
                           "320x200",
                           "--frames",
                           "7",
                           "--screenshot",
                           "a.png",
                           "--id-image=a.ids",
                           "--scene",
                           "tiles",
                           "--renderer",
                           "per-draw",
                           "--mode=push",
                           "--part-weight",
                           "0.25",
                           "--colorize-draws",
                           "--validation",
                           "--device",
                           "llvm",
                           "--shader-dir",
                           "/x"});
    EXPECT_TRUE(o.headless);
    EXPECT_EQ(o.width, 320u);
    EXPECT_EQ(o.height, 200u);
    EXPECT_EQ(o.frames, 7u);
    EXPECT_EQ(o.screenshot, "a.png");
    EXPECT_EQ(o.idImage, "a.ids");
    EXPECT_EQ(o.scene, "tiles");
    EXPECT_FLOAT_EQ(o.partWeight, 0.25f);
    EXPECT_TRUE(o.colorizeDraws);
    EXPECT_TRUE(o.validation);
    EXPECT_EQ(o.device, "llvm");
    EXPECT_EQ(o.shaderDir, "/x");
    EXPECT_TRUE(parseArgs({"--list-devices"}).listDevices);
    EXPECT_TRUE(parseArgs({"--list-renderers"}).listRenderers);
    EXPECT_TRUE(parseArgs({"--help"}).help);
    Options m = parseArgs({"--model", "a.glb", "--parts", "components", "--copies", "3", "--stats",
                           "--search-batch", "8", "--export", "out.glb"});
    EXPECT_EQ(m.model, "a.glb");
    EXPECT_EQ(m.parts, "components");
    EXPECT_EQ(m.copies, 3u);
    EXPECT_EQ(m.searchBatch, 8u);
    EXPECT_TRUE(m.stats);
    EXPECT_EQ(m.exportPath, "out.glb");
    EXPECT_EQ(parseArgs({"--scene", "procedural:preset=car-like,seed=42"}).scene,
              "procedural:preset=car-like,seed=42");
    EXPECT_EQ(parseArgs({"--scene=procedural"}).scene, "procedural");
}

TEST(Cli, RefusesBadCommandLines) {
    const std::vector<std::vector<std::string>> bad = {
        {"--bogus"},
        {"headless"},
        {"--size"},
        {"--size", "320"},
        {"--size", "0x200"},
        {"--size", "320x"},
        {"--size", "99999x10"},
        {"--frames", "-1"},
        {"--frames", "3x"},
        {"--frames", "0"},
        {"--part-weight", "1.5"},
        {"--part-weight", "abc"},
        {"--renderer", "nope"},
        {"--mode", "nope"},
        {"--scene", "nope"},
        {"--headless=yes"},
        {"--screenshot"},
        {"--scene", "procedural:preset=huge"},
        {"--scene", "procedural:seed=x"},
        {"--scene", "procedural:colour=red"},
        {"--scene", "tiles:seed=3"},
        {"--parts", "faces"},
        {"--copies", "0"},
        {"--search-batch", "33"},
        {"--stats=1"},
    };
    for (const auto& args : bad) {
        std::string joined;
        for (const auto& a : args) joined += a + " ";
        EXPECT_THROW(parseArgs(args), UsageError) << joined;
    }
}

TEST(Cli, UsageListsEveryFlag) {
    const std::string text = app::usage();
    for (const char* flag :
         {"--headless",    "--size",           "--frames",       "--screenshot", "--id-image",
          "--validation",  "--device",         "--list-devices", "--renderer",   "--mode",
          "--part-weight", "--colorize-draws", "--scene",        "--shader-dir", "--model",
          "--parts",       "--copies",         "--stats",        "--export",     "--search-batch"})
        EXPECT_NE(text.find(flag), std::string::npos) << flag;
}

TEST(Cli, BenchmarkDefaultsFollowTheSeedTableAndYieldToFlags) {
    app::Options o = app::parseArgs(std::vector<std::string>{"--benchmark"});
    EXPECT_TRUE(o.benchmark && o.headless);
    EXPECT_EQ(o.width, 2560u);
    EXPECT_EQ(o.height, 1440u);
    EXPECT_EQ(o.msaa, 4u);
    EXPECT_EQ(o.copies, 3u);
    EXPECT_EQ(o.frames, 200u);
    EXPECT_EQ(o.searchBatch, 16u);
    EXPECT_EQ(o.renderer, "all");
    o = app::parseArgs(std::vector<std::string>{"--size", "64x48", "--benchmark", "--msaa", "1",
                                                "--renderer", "tri-fs,per-draw"});
    EXPECT_EQ(o.width, 64u);
    EXPECT_EQ(o.msaa, 1u);
    EXPECT_EQ(o.copies, 3u);
    EXPECT_EQ(app::rendererList(o.renderer), (std::vector<std::string>{"tri-fs", "per-draw"}));
    EXPECT_EQ(app::modeList("all").size(), 3u);
    EXPECT_THROW(app::parseArgs(std::vector<std::string>{"--mode", "push,mdi-attribute"}),
                 app::UsageError); // lists only with --benchmark
    EXPECT_THROW(app::rendererList("tri-fs,"), app::UsageError);
}

TEST(Cli, PickAndMsaaFlags) {
    auto o = app::parseArgs(std::vector<std::string>{"--size", "100x50", "--pick", "3,4", "--pick",
                                                     "99,49", "--select", "0,0", "--msaa", "8"});
    ASSERT_EQ(o.picks.size(), 2u);
    EXPECT_EQ(o.picks[1], (app::Options::Pixel{99, 49}));
    EXPECT_EQ(o.selects.size(), 1u);
    EXPECT_EQ(o.msaa, 8u);
    EXPECT_THROW(app::parseArgs(std::vector<std::string>{"--size", "100x50", "--pick", "100,0"}),
                 app::UsageError);
    EXPECT_THROW(app::parseArgs(std::vector<std::string>{"--pick", "3"}), app::UsageError);
    EXPECT_THROW(app::parseArgs(std::vector<std::string>{"--msaa", "3"}), app::UsageError);
}

TEST(Benchmark, PercentileIsNearestRank) {
    EXPECT_EQ(app::percentile({}, 0.5), 0.0);
    EXPECT_EQ(app::percentile({3, 1, 2}, 0.5), 2.0);
    EXPECT_EQ(app::percentile({5, 1, 4, 2, 3, 6, 7, 8, 9, 10}, 0.9), 9.0);
    EXPECT_EQ(app::percentile({1, 2}, 1.0), 2.0);
}

TEST(Cli, NarySearchVisibleMaterialsAndCopyAxes) {
    Options d = parseArgs(std::vector<std::string>{});
    EXPECT_EQ(d.nsearchN, 3u);
    EXPECT_FALSE(d.nsearchGuess);
    EXPECT_EQ(d.nsearchLinear, 8u);
    EXPECT_EQ(d.nsearchSteps, 16u);
    EXPECT_FLOAT_EQ(d.visible, 1.0f);
    EXPECT_FALSE(d.ignoreMaterials);
    EXPECT_EQ(d.copyAxes, "xy");
    Options o = parseArgs({"--renderer", "nsearch-fs", "--nsearch-n", "5", "--nsearch-guess=on",
                           "--nsearch-linear", "0", "--nsearch-steps", "64", "--visible", "0.25",
                           "--ignore-materials", "--copy-axes", "zx"});
    EXPECT_EQ(o.renderer, "nsearch-fs");
    EXPECT_EQ(o.nsearchN, 5u);
    EXPECT_TRUE(o.nsearchGuess);
    EXPECT_EQ(o.nsearchLinear, 0u);
    EXPECT_EQ(o.nsearchSteps, 64u);
    EXPECT_FLOAT_EQ(o.visible, 0.25f);
    EXPECT_TRUE(o.ignoreMaterials);
    EXPECT_EQ(o.copyAxes, "zx");
    EXPECT_TRUE(parseArgs({"--nsearch-guess", "on"}).nsearchGuess);
    EXPECT_EQ(parseArgs({"--nsearch-n", "16", "--nsearch-linear", "64"}).nsearchN, 16u);
    EXPECT_EQ(parseArgs({"--renderer", "nsearch-gs"}).renderer, "nsearch-gs");
    const std::vector<std::vector<std::string>> bad = {
        {"--nsearch-n", "2"},       {"--nsearch-n", "17"},    {"--nsearch-guess", "yes"},
        {"--nsearch-linear", "65"}, {"--nsearch-steps", "0"}, {"--nsearch-steps", "65"},
        {"--visible", "1.5"},       {"--visible", "-0.1"},    {"--copy-axes", ""},
        {"--copy-axes", "xw"},      {"--copy-axes", "xx"},    {"--ignore-materials=1"}};
    for (const auto& args : bad) EXPECT_THROW(parseArgs(args), UsageError) << args[0];
}
