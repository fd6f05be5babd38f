// test_shaders.cpp - every shader variant the program can request compiles, and compile
// errors point at file:line, also inside included files.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <unistd.h>

#include "render/shader_variants.h"
#include "render/xray.h"
#include "vk/shader_compiler.h"

namespace fs = std::filesystem;

namespace {

// A copy of shaders/ in a fresh temporary folder, for breaking files on purpose.
fs::path copyShaders(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / ("idview-" + name + "-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::copy(IDVIEW_SOURCE_SHADER_DIR, dir, fs::copy_options::recursive);
    return dir;
}

// Replaces the first `from` and returns its 1-based line number (0 if it is not there).
int replaceInFile(const fs::path& path, const std::string& from, const std::string& to) {
    std::ifstream in(path);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    auto at = text.find(from);
    if (at == std::string::npos) return 0;
    text.replace(at, from.size(), to);
    std::ofstream(path) << text;
    return 1 + int(std::count(text.begin(), text.begin() + long(at), '\n'));
}

std::string compileError(const vk::ShaderCompiler& compiler, const vk::ShaderRequest& request) {
    try {
        compiler.compile(request);
    } catch (const vk::ShaderError& e) {
        return e.what();
    }
    return "";
}

} // namespace

// The keys cover what the flags and the panel can ask for, checked entry by entry against the
// registry and the ranges rather than by a count: every technique in every mode, every search
// batch of the range for the techniques that read it, each N-ary test set for those that
// read it, both geometry shader forms where there is a geometry stage; nothing twice.
TEST(Shaders, VariantKeysCoverEveryChoice) {
    const auto keys = render::allPipelineKeys();
    auto has = [&](const render::PipelineKey& wanted) {
        return std::count(keys.begin(), keys.end(), wanted);
    };
    const auto sets = render::narySearchTestSets();
    ASSERT_GE(sets.size(), 4u); // the default and the corners of the flags' ranges
    size_t expected = 0;
    for (const auto& t : render::techniques())
        for (const auto& m : render::drawModes()) {
            const render::Range batches = t.readsSearchBatch()
                                              ? render::searchBatchRange
                                              : render::Range{render::PipelineKey{}.searchBatch,
                                                              render::PipelineKey{}.searchBatch};
            for (uint32_t batch = batches.min; batch <= batches.max; ++batch)
                for (const auto& nary : t.narySearch ? sets : std::vector<render::NarySearch>{{}})
                    for (bool passthrough : {false, true}) {
                        if (passthrough && t.stage != render::LookupStage::Geometry) continue;
                        const render::PipelineKey key{&t, &m, batch, nary, passthrough};
                        EXPECT_EQ(has(key), 1) << t.name << " + " << m.name << " batch " << batch
                                               << " passthrough " << passthrough;
                        ++expected;
                    }
            // The culling variant: a task shader for the mesh techniques and their floor, run
            // offsets for the techniques that read gl_PrimitiveID in the mdi modes.
            render::PipelineKey culling{&t, &m};
            culling.taskCulling = culling.runOffsets = true;
            if (t.usesMeshShader() || (t.readsPrimitiveId() && m.indirect)) {
                EXPECT_EQ(has(culling.effective(true)), 1)
                    << t.name << " + " << m.name << " culling";
                ++expected;
            }
            // The section variant, with every other switch on, once per technique and mode.
            render::PipelineKey section{&t, &m};
            section.section = section.hiding = section.taskCulling = section.runOffsets = true;
            EXPECT_EQ(has(section.effective(true)), 1) << t.name << " + " << m.name << " section";
            ++expected;
            // The hiding variant, once per technique and mode with part IDs.
            render::PipelineKey hiding{&t, &m};
            hiding.hiding = true;
            if (t.isFloor()) continue;
            EXPECT_EQ(has(hiding.effective(true)), 1) << t.name << " + " << m.name << " hiding";
            ++expected;
        }
    // X-ray's translucent pass, with and without the section.
    for (bool section : {false, true}) {
        render::PipelineKey xray = render::translucentKey({});
        xray.section = section;
        EXPECT_EQ(has(xray), 1) << "x-ray, section " << section;
        ++expected;
    }
    EXPECT_EQ(keys.size(), expected); // nothing else
}

TEST(Shaders, EveryVariantCompiles) {
    vk::ShaderCompiler compiler(IDVIEW_SOURCE_SHADER_DIR);
    const auto variants = render::allShaderVariants();
    // Vertex (or mesh) and fragment for each key, geometry where the technique looks up
    // there, task where it culls meshlets.
    size_t stages = 0;
    for (const auto& key : render::allPipelineKeys())
        stages += (key.technique->stage == render::LookupStage::Geometry ? 3 : 2) +
                  (key.taskCulling ? 1 : 0);
    ASSERT_EQ(variants.size(), stages);
    for (const auto& request : variants) {
        std::vector<uint32_t> spirv;
        ASSERT_NO_THROW(spirv = compiler.compile(request)) << request.label();
        ASSERT_GT(spirv.size(), 5u) << request.label();
        EXPECT_EQ(spirv[0], 0x07230203u) << request.label(); // SPIR-V magic number
    }
    // Distinct requests compile once each: the vertex stage is shared by many keys.
    std::set<std::string> distinct;
    for (const auto& request : variants) distinct.insert(request.key());
    EXPECT_EQ(compiler.compilations(), distinct.size());
    EXPECT_EQ(compiler.remembered(), variants.size() - distinct.size());
}

TEST(Shaders, ErrorNamesFileAndLine) {
    fs::path dir = copyShaders("error");
    const int line = replaceInFile(dir / "scene.vert", "outWorldPos = world.xyz;",
                                   "outWorldPos = undeclaredThing;");
    ASSERT_GT(line, 0);
    vk::ShaderCompiler compiler(dir);
    const auto request = render::shaderVariants(render::PipelineKey{})[0];
    const std::string error = compileError(compiler, request);
    EXPECT_NE(error.find((dir / "scene.vert").string() + ":" + std::to_string(line) + ": error:"),
              std::string::npos)
        << error;
    EXPECT_NE(error.find("undeclaredThing"), std::string::npos) << error;
    fs::remove_all(dir);
}

TEST(Shaders, ErrorInsideAnIncludeNamesTheIncludedFile) {
    fs::path dir = copyShaders("include-error");
    const int line =
        replaceInFile(dir / "shading.glsl", "uint h = hashId(id);", "uint h = hashId(id) +;");
    ASSERT_GT(line, 0);
    vk::ShaderCompiler compiler(dir);
    const auto request = render::shaderVariants(render::PipelineKey{})[1];
    const std::string error = compileError(compiler, request);
    EXPECT_NE(error.find((dir / "shading.glsl").string() + ":" + std::to_string(line) + ": error:"),
              std::string::npos)
        << error;
    fs::remove_all(dir);
}

TEST(Shaders, MissingFilesAreReported) {
    vk::ShaderCompiler compiler(IDVIEW_SOURCE_SHADER_DIR);
    vk::ShaderRequest missing{"nope.frag", VK_SHADER_STAGE_FRAGMENT_BIT, {}, {}};
    EXPECT_NE(compileError(compiler, missing).find("cannot read shader"), std::string::npos);
    vk::ShaderRequest badAlias{"scene.frag",
                               VK_SHADER_STAGE_FRAGMENT_BIT,
                               {},
                               {{"technique.glsl", "techniques/none.glsl"}}};
    EXPECT_NE(compileError(compiler, badAlias).find("technique.glsl"), std::string::npos);
}

TEST(Shaders, DefinesReachTheSource) {
    fs::path dir = copyShaders("defines");
    // The default technique's own file, which the fragment stage includes.
    const render::PipelineKey key;
    ASSERT_NE(key.technique->lookupFile, nullptr);
    std::ofstream(dir / key.technique->lookupFile, std::ios::app)
        << "\nconst uint extraOffset = EXTRA_OFFSET;\n";
    vk::ShaderCompiler compiler(dir);
    auto request = render::shaderVariants(key).back();
    EXPECT_NE(compileError(compiler, request).find("EXTRA_OFFSET"), std::string::npos);
    request.defines.push_back({"EXTRA_OFFSET", "1u"});
    EXPECT_NO_THROW(compiler.compile(request));
    fs::remove_all(dir);
}
