// shader_variants.cpp - pipeline keys turned into defines and include aliases.
#include "render/shader_variants.h"

#include <map>
#include <string>

#include "render/xray.h"

namespace render {

std::vector<vk::ShaderRequest> shaderVariants(const PipelineKey& key) {
    const Technique& technique = *key.technique;
    const bool inGeometry = technique.stage == LookupStage::Geometry;
    const bool mesh = technique.usesMeshShader();
    // Every switch the shaders test is defined, 0 or 1: GLSL has no implicit 0 in #if.
    std::vector<std::pair<std::string, std::string>> defines;
    for (const auto& m : drawModes()) defines.push_back({m.define, &m == key.mode ? "1" : "0"});
    defines.push_back({"IDV_LOOKUP_IN_GS", inGeometry ? "1" : "0"});
    defines.push_back({"IDV_LOOKUP_IN_VS", technique.stage == LookupStage::Vertex ? "1" : "0"});
    defines.push_back({"IDV_LOOKUP_IN_MESH", technique.stage == LookupStage::Mesh ? "1" : "0"});
    // mesh-vertex-fs: the mesh shader's part output is per vertex (flat), not per primitive.
    defines.push_back(
        {"IDV_MESH_PART_PER_VERTEX", technique.ids == IdBuffer::MeshletVertexPartIds ? "1" : "0"});
    defines.push_back({"IDV_NO_ID", technique.isFloor() ? "1" : "0"});
    // The visibility buffer: the fragment shader writes the triangle's payload, no colour.
    defines.push_back({"IDV_VISIBILITY", technique.isVisibilityBuffer() ? "1" : "0"});
    defines.push_back({"IDV_COMPUTE_RASTER", technique.computeRaster ? "1" : "0"});
    // Hidden parts: a mesh shader or an ordinary geometry shader drops their triangles before
    // the rasterizer, so early fragment tests stay; otherwise the fragment shader discards.
    const bool dropEarlier = mesh || (inGeometry && !key.gsPassthrough);
    defines.push_back({"IDV_HIDE_PARTS", key.hiding ? "1" : "0"});
    defines.push_back({"IDV_HIDE_IN_FRAGMENT", key.hiding && !dropEarlier ? "1" : "0"});
    defines.push_back({"IDV_SECTION", key.section ? "1" : "0"});
    defines.push_back({"IDV_TRANSLUCENT", key.translucent ? "1" : "0"});
    defines.push_back({"IDV_GS_PASSTHROUGH", key.gsPassthrough ? "1" : "0"});
    defines.push_back({"IDV_TASK_CULLING", key.taskCulling ? "1" : "0"});
    defines.push_back({"IDV_RUN_OFFSET", key.runOffsets ? "1" : "0"});
    // An effective key holds defaults where the technique reads nothing, so the source of
    // other techniques never varies with these.
    defines.push_back({"IDV_SEARCH_COUNT",
                       std::to_string(technique.readsSearchBatch() ? key.searchBatch : 1) + "u"});
    defines.push_back({"IDV_NSEARCH_N", std::to_string(key.nsearch.n) + "u"});
    defines.push_back({"IDV_NSEARCH_GUESS", key.nsearch.guess ? "1" : "0"});
    defines.push_back({"IDV_NSEARCH_LINEAR", std::to_string(key.nsearch.linearBelow) + "u"});
    defines.push_back({"IDV_NSEARCH_STEPS", std::to_string(key.nsearch.maxSteps) + "u"});

    std::map<std::string, std::string> aliases;
    if (technique.lookupFile) aliases["technique.glsl"] = technique.lookupFile;
    std::vector<vk::ShaderRequest> requests;
    if (key.taskCulling)
        requests.push_back({"scene.task", VK_SHADER_STAGE_TASK_BIT_EXT, defines, aliases});
    if (mesh)
        requests.push_back({"scene.mesh", VK_SHADER_STAGE_MESH_BIT_EXT, defines, aliases});
    else
        requests.push_back({"scene.vert", VK_SHADER_STAGE_VERTEX_BIT, defines, aliases});
    if (inGeometry)
        requests.push_back({"scene.geom", VK_SHADER_STAGE_GEOMETRY_BIT, defines, aliases});
    requests.push_back({"scene.frag", VK_SHADER_STAGE_FRAGMENT_BIT, defines, aliases});
    return requests;
}

std::vector<NarySearch> narySearchTestSets() {
    const Range n = nsearchFanOutRange, linear = nsearchLinearRange, steps = nsearchStepsRange;
    return {{},
            {n.min, false, linear.min, steps.min},
            {n.max, true, linear.max, steps.max},
            {n.min + 2, true, linear.min, steps.min + 1},
            {n.max, false, linear.min + 1, steps.max}};
}

std::vector<PipelineKey> allPipelineKeys() {
    std::vector<PipelineKey> keys;
    for (const Technique& technique : techniques())
        for (const DrawMode& mode : drawModes()) {
            // The others ignore the batch: their effective key holds the default.
            const uint32_t fixed = PipelineKey{}.searchBatch;
            const Range batches =
                technique.readsSearchBatch() ? searchBatchRange : Range{fixed, fixed};
            std::vector<NarySearch> sets{NarySearch{}};
            if (technique.narySearch) sets = narySearchTestSets();
            for (uint32_t batch = batches.min; batch <= batches.max; ++batch)
                for (const NarySearch& nary : sets)
                    for (bool passthrough : {false, true}) {
                        PipelineKey key{&technique, &mode, batch, nary, passthrough};
                        key = key.effective(true);
                        if (passthrough && !key.gsPassthrough) continue; // no gs stage
                        keys.push_back(key);
                    }
            // The hiding variant differs only in the fragment shader: once per technique
            // and mode is enough to compile it.
            PipelineKey hiding{&technique, &mode};
            hiding.hiding = true;
            hiding = hiding.effective(true);
            if (hiding.hiding) keys.push_back(hiding);
            // The culling variant, as the renderer asks for it: a task shader for the mesh
            // techniques, run offsets for those that read gl_PrimitiveID in the mdi modes.
            PipelineKey culling{&technique, &mode};
            culling.taskCulling = culling.runOffsets = true;
            culling = culling.effective(true);
            if (culling.taskCulling || culling.runOffsets) keys.push_back(culling);
            // Sections change only the fragment shader; compiled with every other switch on.
            PipelineKey section{&technique, &mode};
            section.section = section.hiding = section.taskCulling = section.runOffsets = true;
            keys.push_back(section.effective(true));
        }
    // X-ray's pass: one pipeline, with the section variant.
    for (bool section : {false, true}) {
        PipelineKey xray = translucentKey(PipelineKey{});
        xray.section = section;
        keys.push_back(xray);
    }
    return keys;
}

std::vector<vk::ShaderRequest> allShaderVariants() {
    std::vector<vk::ShaderRequest> all;
    for (const PipelineKey& key : allPipelineKeys()) {
        auto variants = shaderVariants(key);
        all.insert(all.end(), variants.begin(), variants.end());
    }
    return all;
}

} // namespace render
