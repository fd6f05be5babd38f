// test_lod_choice.cpp - which candidate levels are kept (scene/lod_choice.h), against a brute
// force that integrates the triangles drawn numerically: with memory to spare each geometry
// gets the chain that draws the fewest, a budget is never exceeded, memory goes to the
// geometry more objects draw, and kept levels shrink as their errors grow.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scene/lod_choice.h"

using namespace scene;

namespace {

// The triangles drawn, averaged over log-spaced spans by sampling: at each relative error
// allowed, the coarsest level under it (levels by growing error), else full detail.
double sampledDrawn(const CandidateSet& set, const std::vector<uint32_t>& levels) {
    const int samples = 20000;
    const double lo = std::log(1.0 / widestSpanPixels), hi = std::log(0.5);
    double sum = 0.0;
    for (int i = 0; i < samples; ++i) {
        const double allowed = std::exp(lo + (hi - lo) * (i + 0.5) / samples) * set.size;
        size_t drawn = set.triangles;
        for (uint32_t l : levels)
            if (set.candidates[l].error < allowed) drawn = set.candidates[l].triangles;
        sum += double(drawn);
    }
    return sum / samples;
}

uint64_t bytesOf(const CandidateSet& set, const std::vector<uint32_t>& levels) {
    uint64_t bytes = 0;
    for (uint32_t l : levels) bytes += set.candidates[l].bytes;
    return bytes;
}

// Every subset of up to `coarser` candidates that may be kept: errors growing, each level
// at most `keep` of the triangles before it.
void subsets(const CandidateSet& set, uint32_t coarser, float keep, std::vector<uint32_t>& held,
             std::vector<std::vector<uint32_t>>& out) {
    out.push_back(held);
    if (held.size() == coarser) return;
    for (uint32_t c = 0; c < set.candidates.size(); ++c) {
        const LevelCandidate& next = set.candidates[c];
        const size_t before = held.empty() ? set.triangles : set.candidates[held.back()].triangles;
        if (!held.empty() && next.error < set.candidates[held.back()].error) continue;
        if (!held.empty() && next.error == set.candidates[held.back()].error && c < held.back())
            continue;
        if (double(next.triangles) > double(keep) * double(before)) continue;
        if (std::find(held.begin(), held.end(), c) != held.end()) continue;
        held.push_back(c);
        subsets(set, coarser, keep, held, out);
        held.pop_back();
    }
}

CandidateSet randomSet(std::mt19937& random) {
    CandidateSet set;
    set.triangles = 1000 + random() % 50000;
    set.size = 0.1f + float(random() % 1000) / 100.0f;
    set.instances = 1 + random() % 300;
    const int count = 1 + int(random() % 10);
    for (int c = 0; c < count; ++c) {
        LevelCandidate level;
        level.triangles = 1 + random() % set.triangles;
        level.bytes = 40 * level.triangles + random() % 1000;
        level.error = set.size * std::pow(10.0f, -4.0f + 4.5f * float(random() % 1000) / 1000.0f);
        set.candidates.push_back(level);
    }
    return set;
}

void expectChain(const CandidateSet& set, const std::vector<uint32_t>& levels, float keep) {
    size_t before = set.triangles;
    float error = 0.0f;
    for (uint32_t l : levels) {
        EXPECT_LE(double(set.candidates[l].triangles), double(keep) * double(before));
        EXPECT_GE(set.candidates[l].error, error);
        before = set.candidates[l].triangles;
        error = set.candidates[l].error;
    }
}

} // namespace

TEST(LevelChoice, TheAverageOverSpansIsTheIntegral) {
    CandidateSet set;
    set.triangles = 100;
    set.size = 2.0f;
    // Half way along the spans in log terms (1/64 of the size), a level of 20 triangles.
    set.candidates = {{20, 800, 2.0f / 64.0f}};
    EXPECT_NEAR(drawnOverSpans(set, {0}), 60.0, 1e-6);
    EXPECT_NEAR(drawnOverSpans(set, {0}), sampledDrawn(set, {0}), 0.01);
    EXPECT_NEAR(drawnOverSpans(set, {}), 100.0, 1e-9);
    // Errors beyond the spans save nothing; under them, everything.
    set.candidates = {{20, 800, 2.0f}, {10, 400, 1e-6f}};
    EXPECT_NEAR(drawnOverSpans(set, {0}), 100.0, 1e-9);
    EXPECT_NEAR(drawnOverSpans(set, {1}), 10.0, 1e-9);
}

TEST(LevelChoice, WithMemoryToSpareEachGeometryDrawsTheFewest) {
    std::mt19937 random(7);
    std::vector<CandidateSet> sets;
    for (int s = 0; s < 40; ++s) sets.push_back(randomSet(random));
    const auto chosen = chooseLevels(sets, 3, 0.8f, 1e30);
    ASSERT_EQ(chosen.size(), sets.size());
    size_t withLevels = 0;
    for (size_t s = 0; s < sets.size(); ++s) {
        std::vector<uint32_t> held;
        std::vector<std::vector<uint32_t>> all;
        subsets(sets[s], 3, 0.8f, held, all);
        double best = 1e30;
        for (const auto& levels : all) best = std::min(best, sampledDrawn(sets[s], levels));
        EXPECT_LE(chosen[s].size(), 3u);
        expectChain(sets[s], chosen[s], 0.8f);
        // The sampling's own error is a fraction of a triangle per step it misses.
        EXPECT_NEAR(sampledDrawn(sets[s], chosen[s]), best, 1e-3 * double(sets[s].triangles))
            << "set " << s;
        withLevels += !chosen[s].empty();
    }
    EXPECT_GT(withLevels, 20u);
}

TEST(LevelChoice, TheBudgetHoldsAndGoesWhereMoreObjectsDraw) {
    std::mt19937 random(11);
    std::vector<CandidateSet> sets;
    for (int s = 0; s < 60; ++s) sets.push_back(randomSet(random));
    const auto unlimited = chooseLevels(sets, 3, 0.8f, 1e30);
    double all = 0.0;
    for (size_t s = 0; s < sets.size(); ++s) all += double(bytesOf(sets[s], unlimited[s]));
    ASSERT_GT(all, 0.0);
    for (double share : {0.0, 0.05, 0.2, 0.5, 0.9}) {
        const auto chosen = chooseLevels(sets, 3, 0.8f, share * all);
        double bytes = 0.0;
        for (size_t s = 0; s < sets.size(); ++s) {
            bytes += double(bytesOf(sets[s], chosen[s]));
            expectChain(sets[s], chosen[s], 0.8f);
        }
        EXPECT_LE(bytes, share * all) << "budget " << share;
        // Nor is most of it left unspent.
        if (share > 0.0) {
            EXPECT_GT(bytes, 0.5 * share * all) << "budget " << share;
        }
    }
    // Two geometries alike but for the objects that draw them, memory for one of them.
    CandidateSet few;
    few.triangles = 10000;
    few.size = 1.0f;
    few.instances = 1;
    few.candidates = {{2000, 80000, 0.01f}};
    CandidateSet many = few;
    many.instances = 100;
    const auto chosen = chooseLevels({few, many}, 3, 0.8f, 100000.0);
    EXPECT_TRUE(chosen[0].empty());
    EXPECT_EQ(chosen[1], std::vector<uint32_t>{0});
}
