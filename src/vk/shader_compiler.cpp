// shader_compiler.cpp - glslang front end: includes, defines, error messages with file:line.
#include "vk/shader_compiler.h"

#include <fstream>
#include <memory>
#include <mutex>
#include <regex>
#include <sstream>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include "util/program_paths.h"

namespace vk {
namespace {

// glslang's process-wide state is set up once per process while any compiler exists.
std::mutex processMutex;
int processUsers = 0;

bool readFile(const std::filesystem::path& path, std::string& text) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream buffer;
    buffer << in.rdbuf();
    text = buffer.str();
    return true;
}

EShLanguage language(VkShaderStageFlagBits stage) {
    switch (stage) {
    case VK_SHADER_STAGE_VERTEX_BIT:
        return EShLangVertex;
    case VK_SHADER_STAGE_GEOMETRY_BIT:
        return EShLangGeometry;
    case VK_SHADER_STAGE_FRAGMENT_BIT:
        return EShLangFragment;
    case VK_SHADER_STAGE_COMPUTE_BIT:
        return EShLangCompute;
    case VK_SHADER_STAGE_MESH_BIT_EXT:
        return EShLangMesh;
    case VK_SHADER_STAGE_TASK_BIT_EXT:
        return EShLangTask;
    default:
        throw Error("shader stage not supported by idview's compiler");
    }
}

// Resolves `#include "name"`: an alias of the request first, then relative to the including
// file, then relative to the shader folder. Names in messages stay relative to that folder.
class Includer : public glslang::TShader::Includer {
  public:
    Includer(const std::filesystem::path& root, const std::map<std::string, std::string>& aliases)
        : root_(root), aliases_(aliases) {}

    IncludeResult* includeLocal(const char* header, const char* includer, size_t) override {
        std::string name = header;
        if (auto alias = aliases_.find(name); alias != aliases_.end()) name = alias->second;
        std::filesystem::path besideIncluder = std::filesystem::path(includer).parent_path() / name;
        for (const auto& candidate : {besideIncluder, std::filesystem::path(name)}) {
            auto text = std::make_unique<std::string>();
            if (readFile(root_ / candidate, *text)) {
                auto* result = new IncludeResult(candidate.lexically_normal().string(),
                                                 text->data(), text->size(), text.get());
                text.release();
                return result;
            }
        }
        static const char notFound[] = "file not found in the shader folder";
        return new IncludeResult("", notFound, sizeof notFound - 1, nullptr);
    }

    IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override {
        return includeLocal(header, includer, depth);
    }

    void releaseInclude(IncludeResult* result) override {
        if (!result) return;
        delete static_cast<std::string*>(result->userData);
        delete result;
    }

  private:
    std::filesystem::path root_;
    const std::map<std::string, std::string>& aliases_;
};

// Turns glslang's "ERROR: scene.frag:12: msg" into "<dir>/scene.frag:12: error: msg" so the
// location opens in an editor from the terminal.
std::string formatLog(const std::filesystem::path& dir, const std::string& log) {
    static const std::regex located(R"(^(ERROR|WARNING): ([^:]+):(\d+): (.*)$)");
    std::istringstream in(log);
    std::string line, out;
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_match(line, m, located)) {
            std::string severity = m[1] == "ERROR" ? "error" : "warning";
            out += (dir / m[2].str()).string() + ":" + m[3].str() + ": " + severity + ": " +
                   m[4].str() + "\n";
        } else if (!line.empty() && line.find("compilation terminated") == std::string::npos &&
                   line.find("compilation errors") == std::string::npos) {
            out += line + "\n";
        }
    }
    if (!out.empty() && out.back() == '\n') out.pop_back();
    return out;
}

} // namespace

std::string ShaderRequest::label() const {
    std::string text = file;
    if (auto alias = includeAliases.find("technique.glsl"); alias != includeAliases.end())
        text += " with " + alias->second;
    for (const auto& [key, value] : defines) text += " " + key + "=" + value;
    return text;
}

ShaderCompiler::ShaderCompiler(std::filesystem::path shaderDir) : dir_(std::move(shaderDir)) {
    std::lock_guard lock(processMutex);
    if (processUsers++ == 0) glslang::InitializeProcess();
}

ShaderCompiler::~ShaderCompiler() {
    std::lock_guard lock(processMutex);
    if (--processUsers == 0) glslang::FinalizeProcess();
}

std::string ShaderRequest::key() const {
    std::string text = file + "|" + std::to_string(int(stage));
    for (const auto& [name, value] : defines) text += "|" + name + "=" + value;
    for (const auto& [name, target] : includeAliases) text += "|" + name + ">" + target;
    return text;
}

std::vector<uint32_t> ShaderCompiler::compile(const ShaderRequest& request) const {
    faultPoint("shader compile");
    const std::string key = request.key();
    std::lock_guard lock(mutex_);
    if (auto found = memo_.find(key); found != memo_.end()) {
        ++remembered_;
        return found->second;
    }
    std::vector<uint32_t> spirv = compileNow(request);
    ++compilations_;
    memo_.emplace(key, spirv);
    return spirv;
}

void ShaderCompiler::forget() const {
    std::lock_guard lock(mutex_);
    memo_.clear();
}

std::vector<uint32_t> ShaderCompiler::compileNow(const ShaderRequest& request) const {
    std::string source;
    if (!readFile(dir_ / request.file, source))
        throw ShaderError("cannot read shader " + (dir_ / request.file).string());

    std::string preamble = "#extension GL_GOOGLE_include_directive : require\n";
    for (const auto& [key, value] : request.defines)
        preamble += "#define " + key + " " + value + "\n";

    const EShLanguage stage = language(request.stage);
    glslang::TShader shader(stage);
    const char* text = source.c_str();
    const int length = static_cast<int>(source.size());
    const char* name = request.file.c_str();
    shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
    shader.setPreamble(preamble.c_str());
    shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);

    const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
    Includer includer(dir_, request.includeAliases);
    if (!shader.parse(GetDefaultResources(), 460, false, messages, includer))
        throw ShaderError("shader " + request.label() + " does not compile:\n" +
                          formatLog(dir_, shader.getInfoLog()));

    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages))
        throw ShaderError("shader " + request.label() + " does not link:\n" +
                          formatLog(dir_, program.getInfoLog()));

    std::vector<uint32_t> spirv;
    glslang::SpvOptions options;
    options.disableOptimizer = false;
    glslang::GlslangToSpv(*program.getIntermediate(stage), spirv, &options);
    return spirv;
}

std::filesystem::path ShaderCompiler::locate(const std::string& overrideDir) {
    if (!overrideDir.empty()) return overrideDir;
    return util::dataPath("shaders/shared.h").parent_path();
}

Handle<VkShaderModule> createShaderModule(const Device& device, const std::vector<uint32_t>& spirv,
                                          const std::string& name) {
    auto info = vk::init<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    info.codeSize = spirv.size() * sizeof(uint32_t);
    info.pCode = spirv.data();
    return make(device, vkCreateShaderModule, info, name);
}

} // namespace vk
