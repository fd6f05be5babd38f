// test_cli.cpp - command-line parsing: every flag, both value spellings, and every refusal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <set>

#include "app/benchmark.h"
#include "app/cli.h"
#include "app/cli_flags.h"
#include "app/headless.h"
#include "app/version.h"
#include "render/technique.h"
#include "scene/lod.h"
#include "scene/mesh_builder.h"

using app::Options;
using app::parseArgs;
using app::UsageError;

TEST(Cli, DefaultsWithoutArguments) {
    Options o = parseArgs(std::vector<std::string>{});
    EXPECT_FALSE(o.headless);
    EXPECT_FALSE(o.validation);
    EXPECT_EQ(o.width, 1280u);
    EXPECT_EQ(o.height, 720u);
    EXPECT_EQ(o.live.scene.builtin, ""); // the default model
    EXPECT_EQ(o.live.scene.model, "");
    EXPECT_EQ(o.live.scene.parts, scene::PartMode::Primitives);
    EXPECT_EQ(o.live.scene.copies, 1u);
    EXPECT_EQ(o.live.render.pipeline.searchBatch, 16u);
    EXPECT_FALSE(o.stats);
    EXPECT_EQ(o.live.render.pipeline.technique, &render::defaultTechnique());
    EXPECT_EQ(o.live.render.pipeline.mode, &render::defaultDrawMode());
    EXPECT_FLOAT_EQ(o.live.render.shading.partWeight, 0.5f);
    // The defaults are the settings structs' own, untouched by parsing.
    EXPECT_EQ(o.live.render, render::RenderSettings{});
    EXPECT_EQ(o.live.scene, app::SceneSettings{});
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
    EXPECT_EQ(o.live.scene.builtin, "tiles");
    EXPECT_FLOAT_EQ(o.live.render.shading.partWeight, 0.25f);
    EXPECT_TRUE(o.live.render.shading.colorizeDraws);
    EXPECT_TRUE(o.validation);
    EXPECT_EQ(o.device, "llvm");
    EXPECT_EQ(o.shaderDir, "/x");
    EXPECT_TRUE(parseArgs({"--list-devices"}).listDevices);
    EXPECT_TRUE(parseArgs({"--list-renderers"}).listRenderers);
    EXPECT_TRUE(parseArgs({"--help"}).help);
    Options m = parseArgs({"--model", "a.glb", "--parts", "components", "--copies", "3", "--stats",
                           "--search-batch", "8", "--export", "out.glb"});
    EXPECT_EQ(m.live.scene.model, "a.glb");
    EXPECT_EQ(m.live.scene.parts, scene::PartMode::Components);
    EXPECT_EQ(m.live.scene.copies, 3u);
    EXPECT_EQ(m.live.render.pipeline.searchBatch, 8u);
    EXPECT_TRUE(m.stats);
    EXPECT_EQ(m.exportPath, "out.glb");
    EXPECT_EQ(parseArgs({"--scene", "procedural:preset=car-like,seed=42"}).live.scene.builtin,
              "procedural:preset=car-like,seed=42");
    EXPECT_EQ(parseArgs({"--scene=procedural"}).live.scene.builtin, "procedural");
    // Section planes fill the slots in order.
    const scene::Section cut =
        parseArgs({"--section", "z,-2,flip", "--section", "x,1"}).live.render.section;
    EXPECT_EQ(cut.planes[0], scene::axisPlane(2, -2.0f, true));
    EXPECT_EQ(cut.planes[1], scene::axisPlane(0, 1.0f));
    EXPECT_FALSE(cut.planes[2].on);
}

TEST(Cli, RefusesBadCommandLines) {
    const std::vector<std::vector<std::string>> bad = {
        {"--bogus"},
        {"a.step", "headless"}, // a second model (the first is the model)
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
        {"--lod-levels", "0"},
        {"--lod-levels", "5"},
        {"--lod-level", "1"},
        {"--lod-levels", "2", "--lod-level", "2"},
        {"--lod-error", "-1"},
        {"--lod-error", "x"},
        {"--lod-error", "1,"},
        {"--lod-error", "0,1"}, // a list only with --benchmark
        {"--lod-levels", "1", "--lod-error", "1"},
        {"--lod-levels", "4", "--lod-level", "1", "--lod-error", "1"},
        {"--section", "w,1"},
        {"--section", "x,1,keep"},
        {"--section", "x,1", "--section", "y,1", "--section", "z,1", "--section", "x,2"},
    };
    for (const auto& args : bad) {
        std::string joined;
        for (const auto& a : args) joined += a + " ";
        EXPECT_THROW(parseArgs(args), UsageError) << joined;
    }
}

// --version: "idview VERSION (COMMIT)", COMMIT the source's HEAD at build time (the test runs
// after the build, from the same tree) or "unknown" where the source is not a git checkout.
TEST(Cli, VersionNamesTheCommit) {
    EXPECT_TRUE(parseArgs({"--version"}).version);
    EXPECT_FALSE(parseArgs({}).version);
    const std::string line = app::versionLine();
    const std::string start = std::string("idview ") + IDVIEW_VERSION + " (";
    ASSERT_EQ(line.rfind(start, 0), 0u) << line;
    ASSERT_EQ(line.back(), ')') << line;
    const std::string commit = line.substr(start.size(), line.size() - start.size() - 1);
    std::string head;
    const std::string ask =
        std::string("git -C '") + IDVIEW_SOURCE_SHADER_DIR + "/..' rev-parse HEAD 2>/dev/null";
    if (FILE* git = popen(ask.c_str(), "r")) {
        char text[64] = {};
        if (std::fgets(text, sizeof text, git)) head = text;
        pclose(git);
    }
    if (head.size() < 12) {
        EXPECT_EQ(commit, "unknown");
    } else {
        // git describe: the abbreviated hash alone, or TAG-N-gHASH; "-dirty" with local edits.
        EXPECT_NE(commit.find(head.substr(0, 12)), std::string::npos) << line << " HEAD " << head;
    }
}

// --help lists every flag of the table once, with its value, under its group's heading, and
// no two flags share a name (the parser would take the last).
TEST(Cli, UsageListsEveryFlag) {
    const std::string text = app::usage();
    const std::vector<app::FlagGroup>& groups = app::flagGroups();
    std::vector<size_t> headings;
    for (const app::FlagGroup& group : groups) {
        const std::string heading = std::string("\n").append(group.title).append(":\n");
        headings.push_back(text.find(heading));
        ASSERT_NE(headings.back(), std::string::npos) << group.title;
        if (headings.size() > 1) {
            EXPECT_GT(headings.back(), headings[headings.size() - 2]);
        }
    }
    headings.push_back(text.find("\nExit codes:"));
    std::set<std::string> names;
    size_t flagCount = 0;
    for (size_t g = 0; g < groups.size(); ++g) {
        EXPECT_FALSE(groups[g].flags.empty()) << groups[g].title;
        for (const app::Flag& flag : groups[g].flags) {
            ++flagCount;
            EXPECT_TRUE(names.insert(flag.name).second) << flag.name << " twice";
            // "  --name VALUE" then its help, on the line or (long names) the next.
            std::string line = std::string("\n  ").append(flag.name);
            if (flag.value) line.append(" ").append(flag.value);
            const size_t at = std::min(text.find(line + " "), text.find(line + "\n"));
            EXPECT_TRUE(at > headings[g] && at < headings[g + 1])
                << line << " is not under " << groups[g].title;
        }
    }
    EXPECT_EQ(app::flags().size(), flagCount);
    // Counted apart from the table: every line of the help that starts "  --" is a flag's.
    size_t lines = 0;
    for (size_t at = text.find("\n  --"); at != std::string::npos; at = text.find("\n  --", at + 1))
        ++lines;
    EXPECT_EQ(lines, flagCount);
    for (const char* flag :
         {"--headless",    "--size",           "--frames",       "--screenshot", "--id-image",
          "--validation",  "--device",         "--list-devices", "--renderer",   "--mode",
          "--part-weight", "--colorize-draws", "--scene",        "--shader-dir", "--model",
          "--parts",       "--copies",         "--stats",        "--export",     "--search-batch"})
        EXPECT_TRUE(names.count(flag)) << flag;
}

TEST(Cli, BenchmarkDefaultsFollowTheSeedTableAndYieldToFlags) {
    app::Options o = app::parseArgs(std::vector<std::string>{"--benchmark"});
    EXPECT_TRUE(o.benchmark && o.headless);
    EXPECT_EQ(o.width, 2560u);
    EXPECT_EQ(o.height, 1440u);
    EXPECT_EQ(o.live.render.pipeline.msaa, 4u);
    EXPECT_EQ(o.live.scene.copies, 3u);
    EXPECT_EQ(o.frames, 200u);
    EXPECT_EQ(o.live.render.pipeline.searchBatch, 16u);
    // Every part-ID technique of the registry and every mode; the floor is the benchmark's own.
    EXPECT_EQ(o.benchmarkTechniques, render::partIdTechniques());
    EXPECT_EQ(o.benchmarkModes.size(), render::drawModes().size());
    const auto ids = render::partIdTechniques();
    o = app::parseArgs(std::vector<std::string>{
        "--size", "64x48", "--benchmark", "--msaa", "1", "--renderer",
        std::string(ids[1]->name) + "," + ids[0]->name, "--colorize-draws"});
    EXPECT_EQ(o.width, 64u);
    EXPECT_EQ(o.live.render.pipeline.msaa, 1u);
    EXPECT_EQ(o.live.scene.copies, 3u);
    EXPECT_TRUE(o.live.render.shading.colorizeDraws);
    EXPECT_EQ(o.benchmarkTechniques, (std::vector<const render::Technique*>{ids[1], ids[0]}));
    EXPECT_EQ(app::modeList("all").size(), render::drawModes().size());
    EXPECT_THROW(app::parseArgs(std::vector<std::string>{"--mode", "push,mdi-attribute"}),
                 app::UsageError); // lists only with --benchmark
    EXPECT_THROW(app::parseArgs(std::vector<std::string>{"--renderer", "all"}), app::UsageError);
    EXPECT_THROW(app::techniqueList(std::string(ids[0]->name) + ","), app::UsageError);
}

TEST(Cli, LevelsOfDetail) {
    const Options o = parseArgs({"--lod-levels", "4", "--lod-level", "3"});
    EXPECT_EQ(o.live.scene.lodLevels, 4u);
    EXPECT_EQ(o.live.scene.lodLevel, 3u);
    const Options none = parseArgs({});
    EXPECT_EQ(none.live.scene.lodLevels, 1u);
    EXPECT_EQ(none.live.scene.lodLevel, 0u);
    EXPECT_EQ(none.live.render.lod.errorPixels, 0.0f);
    // An error builds every level unless told how many.
    const Options chosen = parseArgs({"--lod-error", "1.5"});
    EXPECT_EQ(chosen.live.render.lod.errorPixels, 1.5f);
    EXPECT_EQ(chosen.live.scene.lodLevels, scene::maxLevels);
    EXPECT_EQ(parseArgs({"--lod-error", "2", "--lod-levels", "2"}).live.scene.lodLevels, 2u);
    // The benchmark takes a list: its rows, and the largest for the levels built.
    const Options bench = parseArgs({"--benchmark", "--lod-error", "0,1,0.5"});
    EXPECT_EQ(bench.benchmarkLodErrors, (std::vector<float>{0.0f, 1.0f, 0.5f}));
    EXPECT_EQ(bench.live.render.lod.errorPixels, 1.0f);
    EXPECT_EQ(parseArgs({"--benchmark"}).benchmarkLodErrors, std::vector<float>{0.0f});
}

TEST(Cli, PickAndMsaaFlags) {
    auto o = app::parseArgs(std::vector<std::string>{"--size", "100x50", "--pick", "3,4", "--pick",
                                                     "99,49", "--select", "0,0", "--msaa", "8"});
    ASSERT_EQ(o.picks.size(), 2u);
    EXPECT_EQ(o.picks[1], (app::Options::Pixel{99, 49}));
    EXPECT_EQ(o.selects.size(), 1u);
    EXPECT_EQ(o.live.render.pipeline.msaa, 8u);
    EXPECT_THROW(app::parseArgs(std::vector<std::string>{"--size", "100x50", "--pick", "100,0"}),
                 app::UsageError);
    EXPECT_THROW(app::parseArgs(std::vector<std::string>{"--pick", "3"}), app::UsageError);
    EXPECT_THROW(app::parseArgs(std::vector<std::string>{"--msaa", "3"}), app::UsageError);
    // --measure keeps its two points in the order given, inside the image.
    const auto m =
        app::parseArgs(std::vector<std::string>{"--size", "100x50", "--measure", "90,4,2,49"});
    ASSERT_TRUE(m.measure.has_value());
    EXPECT_EQ((*m.measure)[0], (app::Options::Pixel{90, 4}));
    EXPECT_EQ((*m.measure)[1], (app::Options::Pixel{2, 49}));
    EXPECT_FALSE(app::parseArgs(std::vector<std::string>{}).measure.has_value());
    for (const char* bad : {"1,2,3", "1,2,3,4,5", "a,b,c,d"})
        EXPECT_THROW(app::parseArgs(std::vector<std::string>{"--measure", bad}), app::UsageError)
            << bad;
    EXPECT_THROW(
        app::parseArgs(std::vector<std::string>{"--size", "100x50", "--measure", "0,0,3,50"}),
        app::UsageError);
}

TEST(Benchmark, PercentileIsNearestRank) {
    EXPECT_EQ(app::percentile({}, 0.5), 0.0);
    EXPECT_EQ(app::percentile({3, 1, 2}, 0.5), 2.0);
    EXPECT_EQ(app::percentile({5, 1, 4, 2, 3, 6, 7, 8, 9, 10}, 0.9), 9.0);
    EXPECT_EQ(app::percentile({1, 2}, 1.0), 2.0);
}

TEST(Cli, NarySearchVisibleMaterialsAndCopyAxes) {
    Options d = parseArgs(std::vector<std::string>{});
    EXPECT_EQ(d.live.render.pipeline.nsearch, render::NarySearch{});
    EXPECT_FLOAT_EQ(d.live.render.draws.visible, 1.0f);
    EXPECT_FALSE(d.live.render.shading.ignoreMaterials);
    EXPECT_EQ(d.live.scene.copyAxes, scene::COPY_XY);
    const render::Technique* nary = nullptr;
    for (const auto& t : render::techniques())
        if (t.narySearch && !nary) nary = &t;
    ASSERT_NE(nary, nullptr);
    Options o = parseArgs({"--renderer", nary->name, "--nsearch-n", "5", "--nsearch-guess=on",
                           "--nsearch-linear", "0", "--nsearch-steps", "64", "--visible", "0.25",
                           "--ignore-materials", "--copy-axes", "zx"});
    EXPECT_EQ(o.live.render.pipeline.technique, nary);
    EXPECT_EQ(o.live.render.pipeline.nsearch, (render::NarySearch{5, true, 0, 64}));
    EXPECT_FLOAT_EQ(o.live.render.draws.visible, 0.25f);
    EXPECT_TRUE(o.live.render.shading.ignoreMaterials);
    EXPECT_EQ(o.live.scene.copyAxes, scene::COPY_X | scene::COPY_Z);
    EXPECT_TRUE(parseArgs({"--nsearch-guess", "on"}).live.render.pipeline.nsearch.guess);
    EXPECT_EQ(
        parseArgs({"--nsearch-n", "16", "--nsearch-linear", "64"}).live.render.pipeline.nsearch.n,
        16u);
    // Every technique of the registry is a valid --renderer, the no-id floor included.
    for (const auto& t : render::techniques())
        EXPECT_EQ(parseArgs({"--renderer", t.name}).live.render.pipeline.technique, &t) << t.name;
    const std::vector<std::vector<std::string>> bad = {
        {"--nsearch-n", "2"},       {"--nsearch-n", "17"},    {"--nsearch-guess", "yes"},
        {"--nsearch-linear", "65"}, {"--nsearch-steps", "0"}, {"--nsearch-steps", "65"},
        {"--visible", "1.5"},       {"--visible", "-0.1"},    {"--copy-axes", ""},
        {"--copy-axes", "xw"},      {"--copy-axes", "xx"},    {"--ignore-materials=1"}};
    for (const auto& args : bad) EXPECT_THROW(parseArgs(args), UsageError) << args[0];
}

TEST(PickJson, NameAndPathFollowLocalPartAndAreEscaped) {
    scene::Scene s;
    scene::MeshBuilder mb;
    mb.addBox({0, 0, 0}, {1, 1, 1});
    scene::addMaterial(s, "m", {1, 1, 1, 1});
    scene::addObject(s, mb.finish(s, "box"), 0, glm::mat4(1), "lid \"A\"", "box\\1/lid\t\"A\"");
    render::PickReading hit{0, {3, 4}, 5u, 0.5f};
    EXPECT_EQ(app::pickJson(s, hit),
              R"({"x":3,"y":4,"part":5,"object":0,"local_part":5,"name":"lid \"A\"",)"
              R"("path":"box\\1/lid\u0009\"A\"","depth":0.5})");
    render::PickReading background{0, {7, 8}, std::nullopt, 1.0f};
    EXPECT_EQ(app::pickJson(s, background),
              R"({"x":7,"y":8,"part":null,"object":null,"local_part":null,"name":null,)"
              R"("path":null,"depth":null})");
}

TEST(Cli, PartFlags) {
    auto o = app::parseArgs(std::vector<std::string>{
        "--size", "100x50", "--select-rect", "90,40,10,5", "--hide", "3,1,4", "--visible-parts",
        "--edges", "--edge-width", "3", "--edge-color", "FF8000"});
    ASSERT_TRUE(o.selectRect.has_value());
    // The corners in any order: the rectangle between them.
    EXPECT_EQ(*o.selectRect, (render::PartSetQuery{{10, 5}, {90, 40}}));
    EXPECT_EQ(o.hide, (std::vector<uint32_t>{3, 1, 4}));
    EXPECT_TRUE(o.visibleParts);
    EXPECT_TRUE(o.live.render.edges.on);
    EXPECT_EQ(o.live.render.edges.width, 3u);
    EXPECT_EQ(o.live.render.edges.color, glm::vec3(1.0f, 128.0f / 255.0f, 0.0f));
    EXPECT_EQ(app::parseArgs(std::vector<std::string>{"--isolate", "7"}).isolate,
              std::vector<uint32_t>{7});
    EXPECT_TRUE(app::parseArgs(std::vector<std::string>{"--xray"}).live.xray);
    const app::Options d;
    EXPECT_FALSE(d.live.render.edges.on);
    EXPECT_FALSE(d.live.xray);
    EXPECT_NE(app::usage().find("(default 101014)"), std::string::npos); // the edge colour's
    for (const auto& bad : std::vector<std::vector<std::string>>{
             {"--size", "100x50", "--select-rect", "0,0,100,10"}, // outside the image
             {"--select-rect", "1,2,3"},
             {"--hide", "1,,2"},
             {"--hide", "x"},
             {"--hide", "1", "--isolate", "2"},
             {"--edge-width", "4"},
             {"--edge-width", "0"},
             {"--edge-color", "12345"},
             {"--edge-color", "GG0000"}})
        EXPECT_THROW(app::parseArgs(bad), app::UsageError) << bad[0] << " " << bad[1];
}

// --distance takes two unique part IDs, --properties an object index or all.
TEST(Cli, InspectionFlags) {
    const auto o =
        app::parseArgs(std::vector<std::string>{"--distance", "12,3", "--properties", "4"});
    EXPECT_EQ(o.distance, (std::array<uint32_t, 2>{12, 3}));
    EXPECT_EQ(o.propertiesObject, 4u);
    EXPECT_FALSE(o.propertiesAll);
    const auto all = app::parseArgs(std::vector<std::string>{"--properties", "all"});
    EXPECT_TRUE(all.propertiesAll);
    EXPECT_FALSE(all.propertiesObject);
    EXPECT_FALSE(all.distance);
    for (const auto& bad : std::vector<std::vector<std::string>>{{"--distance", "1"},
                                                                 {"--distance", "1,2,3"},
                                                                 {"--distance", "1,x"},
                                                                 {"--properties", "some"},
                                                                 {"--properties", "-1"}})
        EXPECT_THROW(app::parseArgs(bad), app::UsageError) << bad[0] << " " << bad[1];
}

TEST(Cli, CadCacheAndTriangleLimitFlags) {
    const app::Options d;
    EXPECT_TRUE(d.live.scene.cadCache);
    EXPECT_EQ(d.live.scene.cad.maxTriangles, scene::kDefaultMaxTriangles);
    const auto o = app::parseArgs(std::vector<std::string>{"--no-cache", "--max-triangles=5000"});
    EXPECT_FALSE(o.live.scene.cadCache);
    EXPECT_EQ(o.live.scene.cad.maxTriangles, 5000u);
    const std::string text = app::usage();
    for (const std::string& needle : std::vector<std::string>{
             "--no-cache", "--max-triangles N", std::to_string(scene::kDefaultMaxTriangles)})
        EXPECT_NE(text.find(needle), std::string::npos) << needle;
    for (const char* bad : {"0", "lots", "-3", "1e6"})
        EXPECT_THROW(app::parseArgs(std::vector<std::string>{"--max-triangles", bad}),
                     app::UsageError)
            << bad;
}

TEST(Cli, CadTessellationFlags) {
    const app::Options d;
    EXPECT_EQ(d.live.scene.cad.deflection, 0.0);
    EXPECT_EQ(d.live.scene.cad.angularDeflection, 0.5);
    auto o = app::parseArgs(std::vector<std::string>{"--model", "part.STEP", "--deflection", "0.25",
                                                     "--angular-deflection=0.3"});
    EXPECT_EQ(o.live.scene.model, "part.STEP");
    EXPECT_FLOAT_EQ(float(o.live.scene.cad.deflection), 0.25f);
    EXPECT_FLOAT_EQ(float(o.live.scene.cad.angularDeflection), 0.3f);
    const std::string text = app::usage();
    for (const char* needle : {"--deflection", "--angular-deflection", ".step", "0.1%"})
        EXPECT_NE(text.find(needle), std::string::npos) << needle;
    for (const auto& bad : std::vector<std::vector<std::string>>{{"--deflection", "-1"},
                                                                 {"--deflection", "fine"},
                                                                 {"--angular-deflection", "0"},
                                                                 {"--angular-deflection", "4"}})
        EXPECT_THROW(app::parseArgs(bad), app::UsageError) << bad[0] << " " << bad[1];
}

// --view takes every name of the standard views' registry, refuses others in one line that
// lists them; --ortho switches the projection. Neither is set by default.
TEST(Cli, ViewAndOrthoFlags) {
    const Options none = parseArgs(std::vector<std::string>{});
    EXPECT_EQ(none.live.camera.standard, nullptr);
    EXPECT_FALSE(none.live.camera.ortho);
    for (const scene::StandardView& view : scene::standardViews()) {
        const Options o = parseArgs({"--view", view.name});
        EXPECT_EQ(o.live.camera.standard, &view) << view.name;
        EXPECT_FALSE(o.live.camera.ortho);
        EXPECT_EQ(parseArgs({"--view=" + std::string(view.name), "--ortho"}).live.camera.standard,
                  &view);
    }
    EXPECT_TRUE(parseArgs({"--ortho"}).live.camera.ortho);
    try {
        parseArgs({"--view", "sideways"});
        ADD_FAILURE() << "--view sideways was accepted";
    } catch (const UsageError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "--view expects " + scene::standardViewNames() + ", not 'sideways'");
    }
    EXPECT_THROW(parseArgs({"--view"}), UsageError);
    EXPECT_THROW(parseArgs({"--ortho=yes"}), UsageError);
    const std::string text = app::usage();
    EXPECT_NE(text.find("--view NAME"), std::string::npos);
    EXPECT_NE(text.find("--ortho"), std::string::npos);
}

// --edge-info takes pixels as --pick does: repeatable, and refused outside the image with the
// same words.
TEST(Cli, EdgeInfoPixels) {
    const auto o = app::parseArgs(
        std::vector<std::string>{"--size", "100x50", "--edge-info", "3,4", "--edge-info", "99,49"});
    EXPECT_EQ(o.edgeInfos, (std::vector<app::Options::Pixel>{{3, 4}, {99, 49}}));
    try {
        app::parseArgs(std::vector<std::string>{"--size", "100x50", "--edge-info", "100,4"});
        ADD_FAILURE() << "a pixel outside the image was taken";
    } catch (const app::UsageError& e) {
        EXPECT_EQ(std::string(e.what()), "pixel 100,4 is outside the 100x50 image");
    }
    EXPECT_THROW(app::parseArgs(std::vector<std::string>{"--edge-info", "1"}), app::UsageError);
}
