// shader_variants.cpp - technique and mode choices turned into defines and include aliases.
#include "render/shader_variants.h"

#include <map>
#include <string>

namespace render {

std::vector<vk::ShaderRequest> shaderVariants(const Technique& technique, const DrawMode& mode,
                                              const VariantOptions& options) {
    const bool inGeometry = technique.stage == LookupStage::Geometry;
    // Every switch the shaders test is defined, 0 or 1: GLSL has no implicit 0 in #if.
    std::vector<std::pair<std::string, std::string>> defines;
    for (const auto& m : drawModes()) defines.push_back({m.define, &m == &mode ? "1" : "0"});
    defines.push_back({"IDV_LOOKUP_IN_GS", inGeometry ? "1" : "0"});
    defines.push_back({"IDV_NO_ID", technique.stage == LookupStage::None ? "1" : "0"});
    defines.push_back({"IDV_GS_PASSTHROUGH", inGeometry && options.gsPassthrough ? "1" : "0"});
    const bool searches = technique.ids == IdBuffer::PartTriangleCounts;
    defines.push_back(
        {"IDV_SEARCH_COUNT", std::to_string(searches ? options.searchCount : 1) + "u"});
    // Other techniques get the defaults, so their source never varies with these.
    const NarySearch nary = technique.narySearch ? options.nsearch : NarySearch{};
    defines.push_back({"IDV_NSEARCH_N", std::to_string(nary.n) + "u"});
    defines.push_back({"IDV_NSEARCH_GUESS", nary.guess ? "1" : "0"});
    defines.push_back({"IDV_NSEARCH_LINEAR", std::to_string(nary.linearBelow) + "u"});
    defines.push_back({"IDV_NSEARCH_STEPS", std::to_string(nary.maxSteps) + "u"});

    std::map<std::string, std::string> aliases;
    if (technique.lookupFile) aliases["technique.glsl"] = technique.lookupFile;
    std::vector<vk::ShaderRequest> requests;
    requests.push_back({"scene.vert", VK_SHADER_STAGE_VERTEX_BIT, defines, aliases});
    if (inGeometry)
        requests.push_back({"scene.geom", VK_SHADER_STAGE_GEOMETRY_BIT, defines, aliases});
    requests.push_back({"scene.frag", VK_SHADER_STAGE_FRAGMENT_BIT, defines, aliases});
    return requests;
}

std::vector<NarySearch> narySearchTestSets() {
    return {{}, {3, false, 0, 1}, {16, true, 64, 64}, {5, true, 0, 2}, {16, false, 1, 64}};
}

std::vector<vk::ShaderRequest> allShaderVariants() {
    std::vector<vk::ShaderRequest> all;
    auto add = [&](const Technique& t, const DrawMode& m, VariantOptions o) {
        auto variants = shaderVariants(t, m, o);
        all.insert(all.end(), variants.begin(), variants.end());
    };
    for (const auto& technique : techniques())
        for (const auto& mode : drawModes()) {
            const bool searches = technique.ids == IdBuffer::PartTriangleCounts;
            std::vector<NarySearch> sets{NarySearch{}};
            if (technique.narySearch) sets = narySearchTestSets();
            for (uint32_t count = 1; count <= (searches ? 32u : 1u); ++count)
                for (const NarySearch& nary : sets) {
                    add(technique, mode, {count, false, nary});
                    if (technique.stage == LookupStage::Geometry)
                        add(technique, mode, {count, true, nary});
                }
        }
    for (const auto& mode : drawModes()) add(noIdTechnique(), mode, {1, false});
    return all;
}

} // namespace render
