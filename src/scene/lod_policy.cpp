// lod_policy.cpp - candidates into levels of detail, the same for every kind (lod_policy.h).
#include "scene/lod_policy.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>

#include "scene/lod_choice.h"

namespace scene {
namespace {

// Appends `level` as the next level of geometry `base`, a geometry of its own.
void appendLevel(Scene& scene, uint32_t base, LevelMesh& level) {
    const Geometry& g = scene.geometries[base];
    Geometry out = levelShell(scene, g, uint32_t(g.levels.size() + 1));
    out.lodError = level.error;
    scene.vertices.insert(scene.vertices.end(), level.vertices.begin(), level.vertices.end());
    out.vertexCount = uint32_t(level.vertices.size());
    for (const std::vector<uint32_t>& part : level.parts) {
        const uint32_t first = out.triangleCount;
        scene.indices.insert(scene.indices.end(), part.begin(), part.end());
        out.triangleCount += uint32_t(part.size() / 3);
        scene.parts.push_back({first, out.triangleCount - first});
    }
    // A coarser level is never said to be closer than a finer one.
    const Geometry& finer = g.levels.empty() ? g : scene.geometries[g.levels.back()];
    out.lodError = std::max(out.lodError, finer.lodError);
    level = {};
    scene.geometries.push_back(std::move(out));
    scene.geometries[base].levels.push_back(uint32_t(scene.geometries.size() - 1));
}

} // namespace

float geometrySize(const Scene& scene, const Geometry& g) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (uint32_t v = 0; v < g.vertexCount; ++v) {
        lo = glm::min(lo, scene.vertices[g.firstVertex + v].position);
        hi = glm::max(hi, scene.vertices[g.firstVertex + v].position);
    }
    return g.vertexCount ? glm::length(hi - lo) : 0.0f;
}

void measureCandidate(const Scene& scene, const Geometry& full, LevelMesh& level, float size) {
    if (level.parts.empty()) return;
    for (uint32_t p = 0; p < full.partCount && p < level.parts.size(); ++p)
        if (scene.parts[full.firstPart + p].empty()) level.parts[p].clear();
    level.triangles = 0;
    for (const std::vector<uint32_t>& part : level.parts) level.triangles += part.size() / 3;
    level.bytes = geometryBytes(level.vertices.size(), level.triangles, full.partCount);
    level.error = levelError(scene, full, level, kUsefulErrorShare * size);
}

std::vector<LevelMesh> usefulCandidates(const Scene& scene, GeometryCandidates& candidates) {
    const Geometry& g = scene.geometries[candidates.geometry];
    const float size = geometrySize(scene, g);
    std::vector<LevelMesh> out;
    for (std::vector<LevelMesh>& chain : candidates.chains) {
        size_t triangles = g.triangleCount;
        for (LevelMesh& c : chain) {
            if (c.parts.empty() || c.error > kUsefulErrorShare * size) break;
            if (c.triangles >= triangles) continue;
            triangles = c.triangles;
            out.push_back(std::move(c));
        }
    }
    return out;
}

void addChosenLevels(Scene& scene, std::vector<GeometryCandidates>& candidates,
                     const LodOptions& options) {
    if (options.levels < 2) return;
    // Which candidates become levels weighs every geometry against the others, by the
    // objects that draw it, for the memory the scene may spend on levels.
    std::vector<uint32_t> instances(scene.geometries.size(), 0);
    for (const Object& o : scene.objects) ++instances[o.geometry];
    std::vector<CandidateSet> sets(candidates.size());
    std::vector<std::vector<LevelMesh>> useful(candidates.size());
    double bytes = 0.0;
    for (size_t i = 0; i < candidates.size(); ++i) {
        const Geometry& g = scene.geometries[candidates[i].geometry];
        useful[i] = usefulCandidates(scene, candidates[i]);
        sets[i].triangles = g.triangleCount;
        sets[i].size = geometrySize(scene, g);
        sets[i].instances = std::max(instances[candidates[i].geometry], 1u);
        for (const LevelMesh& c : useful[i])
            sets[i].candidates.push_back({c.triangles, c.bytes, c.error});
        bytes += double(geometryBytes(g));
    }
    const auto chosen =
        chooseLevels(sets, options.levels - 1, options.keepAtMost, double(options.memory) * bytes);
    for (size_t i = 0; i < candidates.size(); ++i)
        for (uint32_t c : chosen[i]) appendLevel(scene, candidates[i].geometry, useful[i][c]);
}

void forEachTask(size_t count, const std::function<void(size_t)>& task,
                 const std::function<void(double)>& progress) {
    std::atomic<size_t> next{0}, done{0};
    std::mutex failing;
    std::exception_ptr failed;
    // Each thread catches what its tasks throw (std::bad_alloc too; the caller's progress may
    // stop the work, a cancelled load): the first is rethrown on the caller once every thread
    // has stopped, and no thread takes a further task.
    auto work = [&](bool report) noexcept {
        try {
            for (size_t t; (t = next.fetch_add(1)) < count;) {
                task(t);
                const size_t finished = ++done;
                if (report && progress) progress(double(finished) / double(count));
            }
        } catch (...) {
            const std::lock_guard lock(failing);
            if (!failed) failed = std::current_exception();
            next = count;
        }
    };
    const unsigned threads =
        std::max(1u, std::min<unsigned>(std::thread::hardware_concurrency(), unsigned(count)));
    {
        std::vector<std::jthread> workers;
        try {
            for (unsigned t = 1; t < threads; ++t) workers.emplace_back(work, false);
        } catch (const std::exception&) {
            // A thread that cannot start leaves its tasks to those that did.
        }
        work(true);
    } // joins
    if (failed) std::rethrow_exception(failed);
}

} // namespace scene
