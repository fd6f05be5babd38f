// test_cad_workers.cpp - CAD loads done by worker processes (scene/cad/cad_session.h): the
// scene does not depend on how many workers read it; a split STEP file's partial scenes number
// every part as the finished scene does; a worker that dies costs the solids it was reading,
// named in a warning, never the load; a cancel stops every worker at once; no worker outlives
// its load.
#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "cad_test_parts.h"
#include "rig_step.h"
#include "scene/cad/brep_shapes.h"
#include "scene/cad/cad_loader.h"
#include "scene/cad/scene_codec.h"
#include "test_data.h"

namespace {

namespace fs = std::filesystem;
using scene::CadLoadResult;
using scene::CadOptions;

const fs::path kSteps = "/usr/share/opencascade/data/step";

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

fs::path scratch() {
    return cadtest::scratchFolder("cad_workers");
}

fs::path sample(const char* name) {
    const fs::path path = kSteps / name;
    if (!fs::exists(path)) ADD_FAILURE() << testing_support::missingData(path);
    return path;
}

// `copies` deep copies of a sample as one assembly, by idview-step-copies: one piece each.
fs::path copiesOf(const char* name, int copies) {
    const fs::path out =
        scratch() / (fs::path(name).stem().string() + std::to_string(copies) + ".step");
    if (fs::exists(out)) return out;
    const std::string command = std::string(IDVIEW_STEP_COPIES) + " -n " + std::to_string(copies) +
                                " -o '" + out.string() + "' '" + sample(name).string() + "'";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    return out;
}

fs::path rig() {
    const fs::path path = scratch() / "rig.step";
    if (!fs::exists(path)) cadtest::writeRigStep(path);
    return path;
}

CadOptions withWorkers(unsigned workers) {
    CadOptions options;
    options.workers = workers;
    return options;
}

// The scene and its shapes as bytes: equal bytes, the same scene.
std::string bytesOf(const CadLoadResult& r) {
    scene::ByteWriter out;
    scene::encodeScene(r.scene, out);
    for (uint32_t g = 0; g < r.scene.brep->geometryCount(); ++g)
        out.putString(r.scene.brep->encoded(g));
    for (const std::string& warning : r.warnings) out.putString(warning);
    return std::move(out.bytes());
}

// The processes this one started that are still there.
std::vector<pid_t> children() {
    std::vector<pid_t> out;
    for (const auto& entry : fs::directory_iterator("/proc")) {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        std::ifstream stat(entry.path() / "stat");
        std::string line;
        std::getline(stat, line);
        // pid (comm) state ppid ...: the command may hold spaces, so read after its ')'.
        const size_t close = line.rfind(')');
        if (close == std::string::npos) continue;
        char state = 0;
        int parent = 0;
        if (std::sscanf(line.c_str() + close + 1, " %c %d", &state, &parent) == 2 &&
            parent == ::getpid())
            out.push_back(pid_t(std::stoi(name)));
    }
    return out;
}

// Runs `body` with IDVIEW_TEST_WORKER_SIGNAL set: the worker handed `piece` raises `signal`.
template <typename Body>
void withFault(uint32_t piece, int signal, Body&& body) {
    const std::string value = std::to_string(piece) + ":" + std::to_string(signal);
    ::setenv("IDVIEW_TEST_WORKER_SIGNAL", value.c_str(), 1);
    body();
    ::unsetenv("IDVIEW_TEST_WORKER_SIGNAL");
}

} // namespace

// One, two and four workers give the same bytes: the scene, every shape, the warnings. The
// split files' pieces come back in another order each time; the single piece of linkrods.step
// and a file read whole (BREP) go through the same workers.
TEST(CadWorkers, TheSceneIsTheSameWhateverTheWorkers) {
    const std::vector<fs::path> files = {rig(), copiesOf("screw.step", 5), sample("linkrods.step"),
                                         "/usr/share/opencascade/data/occ/Motor-c.brep"};
    for (const fs::path& file : files) {
        const CadLoadResult one = scene::loadCad(file.string(), withWorkers(1));
        EXPECT_EQ(one.stages.workers, 1u) << file;
        for (unsigned workers : {2u, 4u}) {
            const CadLoadResult more = scene::loadCad(file.string(), withWorkers(workers));
            EXPECT_EQ(more.stages.workers, file.extension() == ".brep" ? 1u : workers) << file;
            EXPECT_TRUE(bytesOf(one) == bytesOf(more)) << file << " with " << workers;
        }
        EXPECT_TRUE(children().empty()) << file;
    }
}

// The split path names, places and colours the objects as the whole file read in one process
// does: the same objects in the same order, paths, placements and part counts.
TEST(CadWorkers, ASplitFileHasTheObjectsOfTheWholeFile) {
    for (const fs::path& file : {rig(), copiesOf("screw.step", 5)}) {
        const CadLoadResult split = scene::loadCad(file.string(), withWorkers(2));
        const CadLoadResult whole = scene::loadCadInProcess(file.string());
        ASSERT_TRUE(split.stages.split) << file << ": " << split.stages.notSplit;
        ASSERT_EQ(split.scene.objects.size(), whole.scene.objects.size()) << file;
        for (size_t o = 0; o < split.scene.objects.size(); ++o) {
            const scene::Object &a = split.scene.objects[o], &b = whole.scene.objects[o];
            EXPECT_EQ(a.name, b.name) << file;
            EXPECT_EQ(a.path, b.path) << file;
            EXPECT_EQ(a.uniquePartOffset, b.uniquePartOffset) << file << " " << a.path;
            EXPECT_EQ(split.scene.materials[a.material].color,
                      whole.scene.materials[b.material].color)
                << file << " " << a.path;
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    EXPECT_NEAR(a.world[c][r], b.world[c][r], 1e-9) << file << " " << a.path;
        }
    }
}

// Every partial scene holds every object with the unique part IDs it ends with; a solid shown
// is the finished one, a solid not yet read draws nothing.
TEST(CadWorkers, PartialScenesNumberEveryPartAsTheFinishedScene) {
    std::vector<scene::CadPartial> partials;
    const CadLoadResult done =
        scene::loadCad(copiesOf("screw.step", 5).string(), withWorkers(2), {}, 1, nullptr,
                       [&](const scene::CadPartial& p) { partials.push_back(p); });
    ASSERT_GE(partials.size(), 2u); // the tree with its boxes, then solids
    EXPECT_EQ(partials.front().solidsReady, 0u);
    const scene::Scene& final = done.scene;
    for (const scene::CadPartial& p : partials) {
        const scene::Scene& s = *p.scene;
        ASSERT_EQ(s.objects.size(), final.objects.size());
        ASSERT_EQ(p.state.size(), s.objects.size());
        EXPECT_EQ(s.uniquePartCount(), final.uniquePartCount());
        for (size_t o = 0; o < s.objects.size(); ++o) {
            const scene::Geometry& g = s.geometries[s.objects[o].geometry];
            const scene::Geometry& f = final.geometries[final.objects[o].geometry];
            EXPECT_EQ(s.objects[o].uniquePartOffset, final.objects[o].uniquePartOffset);
            EXPECT_EQ(g.partCount, f.partCount);
            EXPECT_LE(p.boxes[o].min.x, p.boxes[o].max.x); // every solid has its box
            if (p.state[o] == scene::kObjectReady) {
                EXPECT_EQ(g.triangleCount, f.triangleCount);
                EXPECT_EQ(s.objects[o].world, final.objects[o].world);
            } else {
                EXPECT_EQ(g.triangleCount, 0u);
            }
        }
        EXPECT_NO_THROW(scene::validate(s));
    }
    EXPECT_GT(partials.back().solidsReady, 0u);
}

// A worker killed (SIGKILL, as from outside) or crashing (SIGSEGV, as inside Open CASCADE)
// while it reads a piece costs that piece's solids alone: the load ends with every other solid,
// the lost ones keep their part IDs and draw nothing, a warning names them, and a new worker
// took over the pieces left. One worker, so that pieces are always left when it dies: it is
// handed piece 4 (the quick first), then 0, 1 and 2, where it dies, and 3 waits. With two, the
// other might have taken every piece left while the first was still dying (as slowly as
// AddressSanitizer's report makes it), and none would need a new worker.
TEST(CadWorkers, AWorkerThatDiesCostsItsSolidsNeverTheLoad) {
    const fs::path file = copiesOf("screw.step", 5);
    const CadLoadResult clean = scene::loadCad(file.string(), withWorkers(2));
    for (int signal : {SIGKILL, SIGSEGV}) {
        std::optional<CadLoadResult> r;
        withFault(2, signal, [&] { r = scene::loadCad(file.string(), withWorkers(1)); });
        ASSERT_TRUE(r);
        EXPECT_EQ(r->stages.piecesLost, 1u);
        EXPECT_GE(r->stages.workerRestarts, 1u);
        // Under AddressSanitizer its own handler takes the fault and ends the worker with its
        // exit status.
        const std::string reason = signal == SIGKILL ? "killed by SIGKILL"
                                   : kSanitized      ? "exited with status"
                                                     : "killed by SIGSEGV";
        const auto warned = std::find_if(r->warnings.begin(), r->warnings.end(), [&](auto& w) {
            return w.find("not loaded") != std::string::npos && w.find(reason) != std::string::npos;
        });
        EXPECT_NE(warned, r->warnings.end()) << reason;
        size_t empty = 0;
        ASSERT_EQ(r->scene.objects.size(), clean.scene.objects.size());
        for (size_t o = 0; o < r->scene.objects.size(); ++o) {
            const scene::Object &a = r->scene.objects[o], &b = clean.scene.objects[o];
            EXPECT_EQ(a.uniquePartOffset, b.uniquePartOffset);
            EXPECT_EQ(a.path, b.path);
            const uint32_t triangles = r->scene.geometries[a.geometry].triangleCount;
            empty += triangles == 0;
            if (triangles) {
                EXPECT_EQ(triangles, clean.scene.geometries[b.geometry].triangleCount);
            }
        }
        EXPECT_EQ(empty, 1u); // one copy of the screw: one solid
        EXPECT_TRUE(children().empty());
    }
}

// Cancel while the pieces load: the load says so in one line, at once, and no worker is left.
TEST(CadWorkers, CancelStopsEveryWorkerAtOnce) {
    const fs::path file = copiesOf("screw.step", 5);
    std::atomic<bool> cancel{false};
    try {
        scene::loadCad(file.string(), withWorkers(2), {}, 1, &cancel,
                       [&](const scene::CadPartial&) { cancel = true; });
        ADD_FAILURE() << "the load went on after its cancel";
    } catch (const scene::ModelError& e) {
        EXPECT_EQ(std::string(e.what()), file.string() + ": cancelled");
    }
    EXPECT_TRUE(children().empty());
}

// A worker that runs out of memory (its heap bounded by the tests' fault injection) costs its
// piece; where none is left to read the file with, the load is refused in one line that says
// so, and no worker is left.
TEST(CadWorkers, RunningOutOfMemoryIsARefusalInOneLine) {
    const fs::path file = copiesOf("screw.step", 5);
    ::setenv("IDVIEW_TEST_WORKER_MEMORY", "4", 1);
    try {
        scene::loadCad(file.string(), withWorkers(2));
        ADD_FAILURE() << "loaded in 4 MiB";
    } catch (const scene::ModelError& e) {
        const std::string said = e.what();
        EXPECT_EQ(said.rfind(file.string() + ": ", 0), 0u) << said;
        EXPECT_NE(said.find("out of memory"), std::string::npos) << said;
        EXPECT_EQ(said.find('\n'), std::string::npos) << said;
    }
    ::unsetenv("IDVIEW_TEST_WORKER_MEMORY");
    EXPECT_TRUE(children().empty());
}

// Without its worker program a load is refused in one line that says where it looked.
TEST(CadWorkers, AMissingWorkerProgramIsRefusedInOneLine) {
    ::setenv("IDVIEW_LOAD_WORKER", "/nonexistent/idview-load-worker", 1);
    try {
        scene::loadCad(sample("screw.step").string());
        ADD_FAILURE() << "loaded without a worker";
    } catch (const scene::ModelError& e) {
        const std::string said = e.what();
        EXPECT_NE(said.find("cannot start /nonexistent/idview-load-worker"), std::string::npos)
            << said;
        EXPECT_EQ(said.find('\n'), std::string::npos);
    }
    ::unsetenv("IDVIEW_LOAD_WORKER");
}
