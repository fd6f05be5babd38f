// test_shaders.cpp - every shader variant the program can request compiles, and compile
// errors point at file:line, also inside included files.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "render/shader_variants.h"
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

TEST(Shaders, EveryVariantCompiles) {
    vk::ShaderCompiler compiler(IDVIEW_SOURCE_SHADER_DIR);
    const auto variants = render::allShaderVariants();
    // Per mode: per-draw, tri-fs, bsearch-fs (2 stages); tri-gs in two forms (3 stages each);
    // search-fs at 32 batch sizes (2 stages); search-gs at 32 sizes in two forms (3 stages);
    // nsearch-fs at each test parameter set (2 stages); nsearch-gs at each set in two forms
    // (3 stages); the no-id reference (2 stages).
    const size_t sets = render::narySearchTestSets().size();
    ASSERT_GE(sets, 4u); // the default and the corners of the flags' ranges
    const size_t perMode = 3 * 2 + 2 * 3 + 32 * 2 + 32 * 2 * 3 + sets * 2 + sets * 2 * 3 + 2;
    ASSERT_EQ(variants.size(), perMode * render::drawModes().size());
    for (const auto& request : variants) {
        std::vector<uint32_t> spirv;
        ASSERT_NO_THROW(spirv = compiler.compile(request)) << request.label();
        ASSERT_GT(spirv.size(), 5u) << request.label();
        EXPECT_EQ(spirv[0], 0x07230203u) << request.label(); // SPIR-V magic number
    }
}

TEST(Shaders, ErrorNamesFileAndLine) {
    fs::path dir = copyShaders("error");
    const int line = replaceInFile(dir / "scene.vert", "outWorldPos = world.xyz;",
                                   "outWorldPos = undeclaredThing;");
    ASSERT_GT(line, 0);
    vk::ShaderCompiler compiler(dir);
    const auto request =
        render::shaderVariants(render::techniques()[0], render::drawModes()[0], {})[0];
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
    const auto request =
        render::shaderVariants(render::techniques()[0], render::drawModes()[0], {})[1];
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
    ASSERT_GT(replaceInFile(dir / "techniques/per_draw.glsl", "return draw.firstPart;",
                            "return draw.firstPart + EXTRA_OFFSET;"),
              0);
    vk::ShaderCompiler compiler(dir);
    auto request = render::shaderVariants(render::techniques()[0], render::drawModes()[0], {})[1];
    EXPECT_NE(compileError(compiler, request).find("EXTRA_OFFSET"), std::string::npos);
    request.defines.push_back({"EXTRA_OFFSET", "1u"});
    EXPECT_NO_THROW(compiler.compile(request));
    fs::remove_all(dir);
}
