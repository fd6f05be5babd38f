// test_cull_table.cpp - docs/techniques.md's table of the cull phases is the one the code
// runs: printed here from shared_cull.h's CULL_PHASES, it must be the page's generated block
// (a failure prints the block to paste in).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "shared.h"

namespace {

const char* const PHASE_NAMES[gpu::CULL_PHASE_COUNT] = {"NONE", "FRUSTUM", "EARLY",
                                                        "LATE", "FROZEN",  "FROZEN_LATE"};
static_assert(gpu::CULL_PHASE_FROZEN_LATE + 1 == gpu::CULL_PHASE_COUNT);

// The steps as the table's letters, levels in brackets: it runs only where levels are chosen.
std::string steps(uint32_t bits) {
    static const std::pair<uint32_t, const char*> letters[] = {
        {gpu::CULL_L, "[L]"}, {gpu::CULL_D, "D"}, {gpu::CULL_C, "C"},   {gpu::CULL_M, "M"},
        {gpu::CULL_N, "N"},   {gpu::CULL_P, "P"}, {gpu::CULL_RN, "RN"}, {gpu::CULL_RP, "RP"}};
    std::string text;
    for (const auto& [bit, letter] : letters)
        if (bits & bit) text.append(text.empty() ? "" : " ").append(letter);
    return text.empty() ? "-" : text;
}

std::string words(uint32_t bits, const std::vector<std::pair<uint32_t, const char*>>& names,
                  const char* none) {
    std::string text;
    for (const auto& [bit, name] : names)
        if (bits & bit) text.append(text.empty() ? "" : ", ").append(name);
    return text.empty() ? none : text;
}

std::string pass(uint32_t bits) {
    return words(bits,
                 {{gpu::CULL_PASS_TESTS, "culls"},
                  {gpu::CULL_PASS_EARLY, "by the history, drawn early"},
                  {gpu::CULL_PASS_LATE, "the second list"},
                  {gpu::CULL_PASS_HISTORY, "makes the history"}},
                 "-");
}

std::string task(uint32_t bits) {
    const std::string tests = words(bits & ~gpu::CULL_TASK_CHOSEN,
                                    {{gpu::CULL_TASK_WITH_HISTORY, "with history"},
                                     {gpu::CULL_TASK_NOT_EARLY, "of draws not drawn early"},
                                     {gpu::CULL_TASK_IN_VIEW, "in view"},
                                     {gpu::CULL_TASK_NOT_BEHIND, "not behind the pyramid"},
                                     {gpu::CULL_TASK_WITHOUT_HISTORY, "without history"}},
                                    "every meshlet");
    return bits & gpu::CULL_TASK_CHOSEN ? "mdi: those M chose; push: " + tests : tests;
}

std::string phaseTable() {
    std::string text = "| phase | runs | mesh draws | vertex draws | pass | task shader draws |\n"
                       "|---|---|---|---|---|---|\n";
    for (uint32_t phase = 0; phase < gpu::CULL_PHASE_COUNT; ++phase) {
        const gpu::CullPhase& row = gpu::CULL_PHASES[phase];
        text += "| `" + std::string(PHASE_NAMES[phase]) + "` | " + steps(row.runs) + " | " +
                steps(row.meshDraws) + " | " + steps(row.vertexDraws) + " | " + pass(row.pass) +
                " | " + task(row.task) + " |\n";
    }
    return text;
}

// The lines between the page's marker and the end of its block, or "" without them.
std::string generatedBlock(const std::string& page, const std::string& marker) {
    const size_t start = page.find(marker + "\n");
    if (start == std::string::npos) return "";
    const size_t first = start + marker.size() + 1;
    const size_t end = page.find("<!-- end generated -->", first);
    return end == std::string::npos ? "" : page.substr(first, end - first);
}

TEST(CullTable, TheDocsPrintThePhasesTheCodeRuns) {
    std::ifstream in(IDVIEW_TECHNIQUES_DOC);
    ASSERT_TRUE(in) << IDVIEW_TECHNIQUES_DOC;
    std::stringstream page;
    page << in.rdbuf();
    const std::string marker = "<!-- generated: test_cull_table.cpp phases -->";
    EXPECT_EQ(generatedBlock(page.str(), marker), phaseTable())
        << IDVIEW_TECHNIQUES_DOC << " should hold, after its line " << marker << ":\n"
        << phaseTable() << "<!-- end generated -->";
}

} // namespace
