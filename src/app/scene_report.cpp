// scene_report.cpp - the JSON of --stats and --tree (scene_source.h), and the levels of
// detail's array the benchmark's file shares with --stats.
#include <algorithm>
#include <filesystem>

#include "app/scene_source.h"

#include "render/draw_list.h"
#include "scene/assembly_tree.h"
#include "scene/lod.h"
#include "scene/part_data.h"
#include "util/json_writer.h"
#include "util/memory.h"

namespace app {

namespace {

// {"name", then the object's "object" and "parts":[first, count], then "children" for a
// group (an object's node with children too).
void writeNode(util::JsonWriter& json, const scene::AssemblyNode& node) {
    json.beginObject().member("name", node.name);
    if (node.object)
        json.member("object", *node.object)
            .beginArray("parts")
            .value(node.firstPart)
            .value(node.partCount)
            .endArray();
    if (!node.object || !node.children.empty()) {
        json.beginArray("children");
        for (const scene::AssemblyNode& child : node.children) writeNode(json, child);
        json.endArray();
    }
    json.endObject();
}

// Milliseconds with 3 decimals, as --stats has always printed them.
util::Fixed ms(double value) {
    return {value, 3};
}

// What the scene holds and how its load went: the members from "source" to "lod_levels".
void sceneMembers(util::JsonWriter& json, const LoadedScene& loaded, uint32_t searchBatch) {
    const scene::Scene& s = loaded.scene;
    const scene::IdDataBytes bytes = scene::idDataBytes(s, searchBatch);
    json.member("source", loaded.source)
        .member("part_mode", loaded.cad ? "faces" : scene::partModeName(loaded.settings.parts))
        .member("copies", loaded.settings.copies)
        .member("objects", s.objects.size())
        .member("geometries", s.geometries.size())
        .member("parts", s.uniquePartCount())
        .member("empty_parts", scene::emptyParts(s).size())
        .member("geometry_parts", s.parts.size())
        .member("triangles", s.drawnTriangleCount())
        .member("unique_triangles", s.indices.size() / 3)
        .member("vertices", s.vertices.size())
        .member("load_ms", ms(loaded.loadMs))
        .member("read_ms", ms(loaded.cadLoad.readMs))
        .member("tessellation_ms", ms(loaded.cadLoad.tessellationMs))
        .member("faces_failed", loaded.cadLoad.facesFailed);
    scene::unitMember(json, s.unit);
    json.member("deflection", util::Significant{loaded.cadLoad.deflection, 6})
        .member("cache", loaded.cadLoad.cache)
        .member("cache_note", loaded.cadLoad.cacheNote)
        .member("cache_ms", ms(loaded.cadLoad.cacheMs))
        .member("search_batch", searchBatch)
        .member("triangle_part_id_bytes", bytes.trianglePartIds)
        .member("part_triangle_count_bytes", bytes.partTriangleCounts)
        .member("part_triangle_offset_bytes", bytes.partTriangleOffsets)
        .member("lod_ms", ms(loaded.lodMs))
        .member("lod_level", loaded.settings.lodLevel)
        .key("lod_levels");
    levelStatsArray(json, scene::levelStats(s));
}

// Mebibytes, for the memory figures.
uint64_t mib(uint64_t bytes) {
    return util::mebibytes(bytes);
}

// A CAD load's stages (scene::CadStageFigures): where its time and memory went.
void loadMembers(util::JsonWriter& json, const scene::CadLoadFigures& f) {
    const scene::CadStageFigures& s = f.stages;
    json.beginObject("load")
        .member("split", s.split)
        .member("not_split", s.notSplit)
        .member("workers", s.workers)
        .member("pieces", s.pieces)
        .member("pieces_lost", s.piecesLost)
        .member("worker_restarts", s.workerRestarts)
        .member("lex_ms", ms(s.lexMs))
        .member("split_ms", ms(s.splitMs))
        .member("skeleton_ms", ms(s.skeletonMs))
        .member("first_solid_ms", ms(s.firstSolidMs))
        .member("pieces_ms", ms(s.piecesMs))
        .member("largest_piece_ms", ms(s.largestPieceMs))
        .member("parse_ms", ms(s.parseMs))
        .member("transfer_ms", ms(s.transferMs))
        .member("healing_ms", ms(s.healingMs))
        .member("pieces_healed", s.piecesHealed)
        .member("mesh_ms", ms(s.meshMs))
        .member("build_ms", ms(s.buildMs))
        .member("levels_ms", ms(s.levelsMs))
        .member("encode_ms", ms(s.encodeMs))
        .member("assembly_ms", ms(s.assemblyMs))
        .member("cache_ms", ms(f.cacheMs));
    const uint64_t tree =
        std::max({s.peakLexBytes, s.peakSkeletonBytes, s.peakPiecesBytes, s.peakAssemblyBytes});
    json.beginObject("peak_mib")
        .member("lex", mib(s.peakLexBytes))
        .member("skeleton", mib(s.peakSkeletonBytes))
        .member("pieces", mib(s.peakPiecesBytes))
        .member("assembly", mib(s.peakAssemblyBytes))
        .member("worker", mib(s.peakWorkerBytes))
        .member("process_tree", mib(tree))
        .endObject()
        .endObject();
}

// What the chosen renderer and mode would draw and upload, derived geometry included.
void drawMembers(util::JsonWriter& json, const scene::Scene& s,
                 const render::RenderSettings& settings) {
    const render::PipelineKey& key = settings.pipeline;
    const render::DerivedGeometry geometry = render::buildDerivedGeometry(s, *key.technique);
    const render::DerivedPrimitives derived = geometry.view();
    const render::RenderStats r = render::statsFor(
        render::buildDrawList(s, key, settings.draws, derived), *key.mode, derived);
    json.member("renderer", key.technique->name)
        .member("mode", key.mode->name)
        .member("draws", r.draws)
        .member("drawn_triangles", r.triangles)
        .member("pipelines", r.pipelines)
        .member("id_buffer_bytes", r.idBufferBytes)
        .member("per_draw_bytes", r.perDrawBytes)
        .member("indirect_bytes", r.indirectBytes);
    derivedGeometryMembers(json, r);
    json.member("meshlets", r.meshlets);
}

} // namespace

std::string treeRootName(const LoadedScene& loaded) {
    const std::filesystem::path source(loaded.source);
    return source.has_extension() ? source.filename().string() : loaded.source;
}

std::string treeJson(const LoadedScene& loaded) {
    util::JsonWriter json;
    writeNode(json, scene::assemblyTree(loaded.scene, treeRootName(loaded)));
    return json.text();
}

void levelStatsArray(util::JsonWriter& json, const std::vector<scene::LevelStats>& levels) {
    json.beginArray();
    for (size_t l = 0; l < levels.size(); ++l) {
        const scene::LevelStats& v = levels[l];
        json.beginObject()
            .member("level", l)
            .member("geometries", v.geometries)
            .member("unique_triangles", v.uniqueTriangles)
            .member("vertices", v.vertices)
            .member("bytes", v.bytes)
            .member("triangles", v.drawnTriangles)
            // Six digits: the error is a float, and a tolerance.
            .member("max_error", util::Significant{v.maxError, 6})
            .endObject();
    }
    json.endArray();
}

void derivedGeometryMembers(util::JsonWriter& json, const render::RenderStats& stats) {
    json.member("geometry_bytes", stats.geometryBytes)
        .member("added_vertices", stats.addedVertices)
        .member("added_vertex_bytes", stats.addedVertexBytes);
}

std::string statsJson(const LoadedScene& loaded, const render::RenderSettings& settings,
                      const std::optional<FirstFrame>& first) {
    util::JsonWriter json;
    json.beginObject();
    sceneMembers(json, loaded, settings.pipeline.searchBatch);
    drawMembers(json, loaded.scene, settings);
    json.array("warnings", loaded.warnings);
    if (loaded.cad)
        loadMembers(json, loaded.cadLoad);
    else
        json.key("load").null();
    // This process's own peak so far (the workers' are in "load").
    json.member("peak_mib", mib(util::peakResidentBytes()));
    if (first)
        json.member("first_frame_ms", ms(first->ms)).member("pipeline_cache", first->pipelineCache);
    else
        json.key("first_frame_ms").null().key("pipeline_cache").null();
    return json.endObject().text();
}

} // namespace app
