// test_step_copies.cpp - idview-step-copies (src/tools/step_copies.cpp) as a user runs it:
// deep and instanced copies of occt-misc's STEP samples and of an assembly written here, read
// back with idview's own CAD loader and checked against the input read the same way; and its
// one-line refusals of bad input.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

#include <gtest/gtest.h>

#include "cad_test_parts.h"
#include "rig_step.h"
#include "scene/cad/cad_loader.h"
#include "scene/copy_grid.h"
#include "test_data.h"

namespace {

namespace fs = std::filesystem;

const fs::path kSteps = "/usr/share/opencascade/data/step";

fs::path scratch() {
    return cadtest::scratchFolder("step_copies");
}

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// `path` in single quotes, for the shell. Appended piece by piece: GCC 12 takes "'" + string
// for an overlapping copy (a false -Wrestrict).
std::string quoted(const fs::path& path) {
    std::string text(1, '\'');
    text += path.string();
    text += '\'';
    return text;
}

struct Run {
    int code = -1;
    std::string out; // stdout
    std::string err; // stderr
};

// The tool with `args` (quoted by the caller where needed), its exit code and what it printed.
Run runTool(const std::string& args) {
    const fs::path out = scratch() / "stdout.txt", err = scratch() / "stderr.txt";
    const std::string command =
        quoted(IDVIEW_STEP_COPIES) + " " + args + " >" + quoted(out) + " 2>" + quoted(err);
    const int status = std::system(command.c_str());
    Run run;
    run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = readText(out);
    run.err = readText(err);
    return run;
}

// An occt-misc sample: a missing one fails the test, naming the package.
fs::path sample(const std::string& name) {
    const fs::path path = kSteps / name;
    EXPECT_TRUE(fs::exists(path)) << testing_support::missingData(path);
    return path;
}

glm::vec4 objectColor(const scene::Scene& s, const scene::Object& o) {
    return s.materials[o.material].color;
}

// Each face's colour as drawn: its own, else its object's.
std::vector<glm::vec4> faceColors(const scene::Scene& s, const scene::Object& o) {
    const scene::Geometry& g = s.geometries[o.geometry];
    std::vector<glm::vec4> colors;
    for (uint32_t p = 0; p < g.partCount; ++p) {
        const bool own = !g.partMaterials.empty() && g.partMaterials[p] != gpu::OBJECT_MATERIAL;
        colors.push_back(own ? s.materials[g.partMaterials[p]].color : objectColor(s, o));
    }
    return colors;
}

// Object `a` of the input and its copy `b`: the same name under "stem/copy k/", the same
// faces and colours, the same turn; returns how far `b` is moved from `a`.
glm::dvec3 expectSameObject(const scene::Scene& in, const scene::Object& a, const scene::Scene& out,
                            const scene::Object& b, const std::string& group) {
    EXPECT_EQ(b.name, a.name);
    EXPECT_EQ(b.path, group + a.path);
    EXPECT_EQ(out.geometries[b.geometry].partFaces, in.geometries[a.geometry].partFaces) << b.path;
    EXPECT_EQ(objectColor(out, b), objectColor(in, a)) << b.path;
    EXPECT_EQ(faceColors(out, b), faceColors(in, a)) << b.path;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) EXPECT_NEAR(b.world[c][r], a.world[c][r], 1e-12) << b.path;
    return glm::dvec3(b.world[3]) - glm::dvec3(a.world[3]);
}

// What idview loads from `input`, loaded once for the tests that copy it.
const scene::Scene& loadedInput(const fs::path& input) {
    static std::map<fs::path, scene::Scene> loaded;
    auto found = loaded.find(input);
    if (found == loaded.end())
        found = loaded.emplace(input, scene::loadCad(input.string()).scene).first;
    return found->second;
}

// Runs the tool on `input` and checks what idview loads from its output against what it
// loads from the input.
void expectCopies(const fs::path& input, uint32_t copies, bool instanced) {
    const std::string stem = input.stem().string() + (instanced ? "_instanced" : "_deep");
    const fs::path output = scratch() / (stem + ".step");
    const Run run = runTool(std::string(instanced ? "--instanced " : "") + "-n " +
                            std::to_string(copies) + " -o " + quoted(output) + " " + quoted(input));
    ASSERT_EQ(run.code, 0) << run.err;
    EXPECT_EQ(run.out, "");
    EXPECT_EQ(run.err, ""); // no progress line: stderr is no terminal here
    const scene::Scene& in = loadedInput(input);
    const scene::Scene out = scene::loadCad(output.string()).scene;
    const size_t n = in.objects.size();
    ASSERT_EQ(out.objects.size(), copies * n);
    EXPECT_EQ(out.uniquePartCount(), copies * in.uniquePartCount()); // N times the faces
    // Deep: each copy its own shapes; instanced: the input's, shared by every copy.
    EXPECT_EQ(out.geometries.size(), (instanced ? 1 : copies) * in.geometries.size());
    std::vector<glm::dvec3> shifts;
    std::set<uint32_t> before; // the geometries of the copies before this one
    for (uint32_t k = 0; k < copies; ++k) {
        const std::string group = stem + "/copy " + std::to_string(k + 1) + "/";
        std::set<uint32_t> mine;
        for (size_t i = 0; i < n; ++i) {
            const scene::Object& b = out.objects[k * n + i];
            const glm::dvec3 shift = expectSameObject(in, in.objects[i], out, b, group);
            if (i == 0) shifts.push_back(shift);
            for (int a = 0; a < 3; ++a) EXPECT_NEAR(shift[a], shifts[k][a], 1e-9) << b.path;
            mine.insert(b.geometry);
            if (instanced)
                EXPECT_EQ(b.geometry, out.objects[i].geometry) << b.path;
            else
                EXPECT_FALSE(before.count(b.geometry)) << b.path << " shares a geometry";
        }
        before.insert(mine.begin(), mine.end());
    }
    // The grid: idview's own steps, from the box the tool measures exactly on the surfaces
    // and the loader on their tessellation (within a few deflections of 0.1% of the diagonal).
    const scene::Bounds box = in.bounds();
    const glm::dvec3 step = scene::copyStep(box.max - box.min);
    const double slack = 0.005 * glm::length(box.max - box.min);
    for (uint32_t k = 0; k < copies; ++k) {
        const glm::dvec3 expected = scene::copyShift(k, copies, scene::COPY_XY, step);
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(shifts[k][a], expected[a], slack) << k << a;
    }
}

TEST(StepCopies, ScrewThreeDeepCopies) {
    expectCopies(sample("screw.step"), 3, false);
}
TEST(StepCopies, ScrewFourInstancedCopies) {
    expectCopies(sample("screw.step"), 4, true);
}
TEST(StepCopies, LinkrodsThreeDeepCopies) {
    expectCopies(sample("linkrods.step"), 3, false);
}
TEST(StepCopies, LinkrodsFourInstancedCopies) {
    expectCopies(sample("linkrods.step"), 4, true);
}

// The samples hold one product without colours; the rig has sub-assemblies, a product placed
// three times, instance, product and face colours.
TEST(StepCopies, AssemblyKeepsStructureNamesAndColours) {
    const fs::path rig = scratch() / "rig.step";
    cadtest::writeRigStep(rig);
    const scene::Scene& in = loadedInput(rig);
    ASSERT_EQ(in.geometries.size(), 2u); // what makes the checks below worth their while
    ASSERT_EQ(in.objects.size(), 4u);
    size_t ownFaceColors = 0;
    for (const scene::Geometry& g : in.geometries)
        for (uint32_t m : g.partMaterials) ownFaceColors += m != gpu::OBJECT_MATERIAL;
    ASSERT_EQ(ownFaceColors, 1u);
    expectCopies(rig, 3, false);
    expectCopies(rig, 2, true);
}

// Bad input: one line naming the thing and the reason, exit code 1, nothing written.
void expectRefused(const std::string& args, const std::string& reason) {
    const fs::path output = scratch() / "refused.step";
    const Run run = runTool(args + " -o " + quoted(output));
    EXPECT_EQ(run.code, 1) << args;
    EXPECT_EQ(run.out, "") << args;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_EQ(run.err.rfind("idview-step-copies: error: ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find(reason), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(output)) << args;
}

TEST(StepCopies, RefusesBadInputInOneLine) {
    const fs::path missing = scratch() / "missing.step";
    expectRefused("-n 2 " + quoted(missing), missing.string() + ": file not found");
    const fs::path junk = scratch() / "junk.step";
    std::ofstream(junk) << "this is no STEP file\n";
    expectRefused("-n 2 " + quoted(junk), junk.string() + ": not a readable STEP file");
    const fs::path empty = scratch() / "noshapes.step";
    std::ofstream(empty) << "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\n"
                            "FILE_NAME('nothing','2024-01-01T00:00:00',(''),(''),'','','');\n"
                            "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\n"
                            "ENDSEC;\nDATA;\nENDSEC;\nEND-ISO-10303-21;\n";
    expectRefused("-n 2 " + quoted(empty), empty.string() + ": the STEP file holds no");
    const std::string screw = quoted(sample("screw.step"));
    expectRefused("-n 0 " + screw, "-n: the number of copies must be a whole number from 1");
    expectRefused("-n -3 " + screw, "not '-3'");
    expectRefused(screw, "-n N is missing");
    expectRefused("--axes xw -n 2 " + screw, "--axes expects some of x, y and z");
}

} // namespace
