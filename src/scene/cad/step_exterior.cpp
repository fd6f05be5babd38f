// step_exterior.cpp - writeStepSubset's parent side (step_exterior.h): the refusals that need no
// file read, then one worker process (util/worker_pool.h) that reads and writes.
#include "scene/cad/step_exterior.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "scene/cad/cad_jobs.h"
#include "scene/cad/cad_session.h"
#include "util/worker_pool.h"

namespace scene {
namespace {

namespace fs = std::filesystem;
using Event = util::WorkerPool::Event;

void refuseUnfit(const std::string& sourcePath, const Scene& scene,
                 const std::vector<uint8_t>& keepObject) {
    if (!isCadPath(sourcePath))
        throw std::runtime_error(
            "STEP export needs a CAD source (STEP, IGES or BREP); this scene is " +
            (sourcePath.empty() ? std::string("not from a file")
                                : "a mesh (" + fs::path(sourcePath).filename().string() + ")"));
    if (keepObject.size() != scene.objects.size())
        throw std::runtime_error("STEP export: " + std::to_string(keepObject.size()) +
                                 " keep flags for " + std::to_string(scene.objects.size()) +
                                 " objects");
    if (std::none_of(keepObject.begin(), keepObject.end(), [](uint8_t k) { return k != 0; }))
        throw std::runtime_error("nothing to write: no solid was seen");
}

// Fails early, before the source is read again, where the file cannot be made.
void refuseUnwritable(const std::string& outPath) {
    const std::string partial = cad::partialStepPath(outPath);
    std::ofstream probe(partial, std::ios::binary);
    if (!probe)
        throw std::runtime_error(outPath + ": cannot write the STEP file there (" +
                                 std::strerror(errno) + ")");
    probe.close();
    std::remove(partial.c_str());
}

// Waits for the worker's word; throws its failure as one line.
void awaitWritten(util::WorkerPool& pool, const std::string& sourcePath) {
    for (;;) {
        // The wait's timeout only paces the loop: an end or an answer wakes it at once.
        const Event event = pool.wait(std::chrono::seconds(1));
        if (event.kind == Event::Kind::Ended)
            throw std::runtime_error(sourcePath + ": the worker writing the STEP file was " +
                                     event.reason);
        if (event.kind != Event::Kind::Message) continue;
        if (event.frame.kind == uint32_t(cad::AnswerKind::StepExport)) return;
        if (event.frame.kind == uint32_t(cad::AnswerKind::Progress)) continue;
        throw std::runtime_error(event.frame.bytes);
    }
}

} // namespace

void writeStepSubset(const std::string& sourcePath, const Scene& scene,
                     const std::vector<uint8_t>& keepObject, const std::string& outPath,
                     Healing healing) {
    refuseUnfit(sourcePath, scene, keepObject);
    refuseUnwritable(outPath);
    cad::StepExportJob job{sourcePath, outPath, healing, {}, keepObject};
    job.paths.reserve(scene.objects.size());
    for (const Object& object : scene.objects) job.paths.push_back(object.path);
    try {
        util::WorkerPool pool(cad::loadWorkerProgram(), {}, 1);
        pool.send(0, uint32_t(cad::JobKind::StepExport), cad::encode(job));
        awaitWritten(pool, sourcePath);
    } catch (...) {
        std::remove(cad::partialStepPath(outPath).c_str()); // a worker that died half-way leaves it
        throw;
    }
}

} // namespace scene
