// technique.cpp - the registry of techniques and per-draw modes.
#include "render/technique.h"

#include "vk/device_select.h"

namespace render {
namespace {

template <typename Entry>
std::string namesOf(const std::vector<Entry>& entries) {
    std::string text;
    for (const auto& entry : entries) text += (text.empty() ? "" : ", ") + std::string(entry.name);
    return text;
}

template <typename Entry>
const Entry* findByName(const std::vector<Entry>& entries, const std::string& name) {
    for (const auto& entry : entries)
        if (name == entry.name) return &entry;
    return nullptr;
}

} // namespace

const std::vector<Technique>& techniques() {
    using enum LookupStage;
    static const std::vector<Technique> list = {
        {"per-draw", "one draw per part; the draw carries the part index",
         "techniques/per_draw.glsl", Fragment, IdBuffer::None, DrawSplit::PerPart},
        {"tri-fs", "one draw per object; part index per triangle, read in the fragment shader",
         "techniques/packed_ids.glsl", Fragment, IdBuffer::TrianglePartIds, DrawSplit::PerObject},
        {"tri-gs", "one draw per object; part index per triangle, read in a geometry shader",
         "techniques/packed_ids.glsl", Geometry, IdBuffer::TrianglePartIds, DrawSplit::PerObject},
        {"search-fs",
         "draws of up to search-batch parts; fragment shader searches their triangle counts",
         "techniques/batch_search.glsl", Fragment, IdBuffer::PartTriangleCounts,
         DrawSplit::PerBatch},
        {"search-gs",
         "draws of up to search-batch parts; geometry shader searches their triangle counts",
         "techniques/batch_search.glsl", Geometry, IdBuffer::PartTriangleCounts,
         DrawSplit::PerBatch},
        {"bsearch-fs",
         "one draw per object; fragment shader binary-searches running triangle offsets",
         "techniques/binary_search.glsl", Fragment, IdBuffer::PartTriangleOffsets,
         DrawSplit::PerObject},
        {"nsearch-fs",
         "one draw per object; fragment shader N-ary-searches running triangle offsets",
         "techniques/nary_search.glsl", Fragment, IdBuffer::PartTriangleOffsets,
         DrawSplit::PerObject, Primitives::SceneIndices, true},
        {"nsearch-gs",
         "one draw per object; geometry shader N-ary-searches running triangle offsets",
         "techniques/nary_search.glsl", Geometry, IdBuffer::PartTriangleOffsets,
         DrawSplit::PerObject, Primitives::SceneIndices, true},
        {"vertex-fs",
         "one draw per object; triangles rotated so their first vertex carries the part, "
         "read by gl_VertexIndex from 8/16/32-bit arrays and handed on flat",
         "techniques/packed_ids.glsl", Vertex, IdBuffer::VertexPartIds, DrawSplit::PerObject,
         Primitives::PartVertices},
        {"mesh-fs",
         "one mesh-tasks draw per object over meshoptimizer meshlets; the mesh shader writes "
         "each triangle's part as a per-primitive output",
         "techniques/packed_ids.glsl", Mesh, IdBuffer::MeshletTrianglePartIds, DrawSplit::PerObject,
         Primitives::Meshlets},
        {"mesh-vertex-fs",
         "mesh-fs over vertex-fs's part vertices: the mesh shader writes the part per vertex, "
         "the fragment shader reads it flat from each triangle's first (provoking) vertex",
         "techniques/packed_ids.glsl", Mesh, IdBuffer::MeshletVertexPartIds, DrawSplit::PerObject,
         Primitives::Meshlets},
        {"visbuffer",
         "visibility buffer: mesh-fs's meshlets write each sample's triangle (a per-primitive "
         "payload) and no colour; a compute pass finds the part from the part per meshlet "
         "triangle, shades and resolves",
         "techniques/packed_ids.glsl", Shade, IdBuffer::MeshletTrianglePartIds,
         DrawSplit::PerObject, Primitives::Meshlets},
        {"visbuffer-compute",
         "visibility buffer with a compute rasterizer: visbuffer, but the task shader sends "
         "meshlets whose triangles project small to a compute pass that rasterizes them by "
         "Vulkan's rules into 64-bit (depth, payload) samples with atomics; the rest stay on "
         "the hardware",
         "techniques/packed_ids.glsl", Shade, IdBuffer::MeshletTrianglePartIds,
         DrawSplit::PerObject, Primitives::Meshlets, false, true},
        {"no-id",
         "reference floor: one draw per object, no part ID in any stage (material colour "
         "only, ID attachment masked)",
         nullptr, None, IdBuffer::None, DrawSplit::PerObject},
        {"no-id-mesh",
         "reference floor of the mesh pipeline: mesh-fs's meshlets and draws without any "
         "part ID",
         nullptr, None, IdBuffer::None, DrawSplit::PerObject, Primitives::Meshlets},
    };
    return list;
}

std::vector<const Technique*> partIdTechniques() {
    std::vector<const Technique*> list;
    for (const Technique& t : techniques())
        if (!t.isFloor()) list.push_back(&t);
    return list;
}

const Technique& floorTechnique() {
    return floorOf(defaultTechnique());
}

const Technique& floorOf(const Technique& technique) {
    const bool mesh = technique.usesMeshShader();
    for (const Technique& t : techniques())
        if (t.isFloor() && t.usesMeshShader() == mesh) return t;
    return techniques().back(); // not reached: the registry has a floor of each kind
}

const Technique& defaultTechnique() {
    return techniques().front();
}

const std::vector<DrawMode>& drawModes() {
    static const std::vector<DrawMode> list = {
        {"push", "push constants per draw; only the fields that changed are pushed",
         "IDV_MODE_PUSH", false, false},
        {"mdi-baseinstance",
         "one multi-draw-indirect per pipeline; shaders index a per-draw buffer by "
         "gl_InstanceIndex",
         "IDV_MODE_MDI_BASEINSTANCE", true, false},
        {"mdi-attribute",
         "one multi-draw-indirect per pipeline; the draw index is an instanced vertex attribute",
         "IDV_MODE_MDI_ATTRIBUTE", true, true},
    };
    return list;
}

const DrawMode& defaultDrawMode() {
    return drawModes().front();
}

std::string unavailableReason(const Technique& technique, const vk::DeviceInfo& device) {
    if (technique.usesMeshShader() && !device.meshShader)
        return "needs VK_EXT_mesh_shader (mesh shaders), which " + device.name + " does not offer";
    return "";
}

const Technique* findTechnique(const std::string& name) {
    return findByName(techniques(), name);
}
const DrawMode* findDrawMode(const std::string& name) {
    return findByName(drawModes(), name);
}
std::string techniqueNames() {
    return namesOf(techniques());
}
std::string drawModeNames() {
    return namesOf(drawModes());
}

} // namespace render
