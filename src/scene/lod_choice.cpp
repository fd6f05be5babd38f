// lod_choice.cpp - the levels kept, by a price per byte of memory (lod_choice.h).
#include "scene/lod_choice.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace scene {
namespace {

// One way to take a set's levels: what it costs in bytes and draws, averaged over the spans.
struct Option {
    std::vector<uint32_t> levels;
    uint64_t bytes = 0;
    double drawn = 0.0;
};

// Every chain of candidates a set may keep (candidates sorted by growing error), none
// included: a set holds a few dozen candidates at most.
std::vector<Option> optionsOf(const CandidateSet& set, const std::vector<uint32_t>& order,
                              uint32_t coarser, float keepAtMost) {
    std::vector<Option> out;
    Option current;
    auto walk = [&](auto& self, size_t from, size_t previous) -> void {
        current.drawn = drawnOverSpans(set, current.levels);
        out.push_back(current);
        if (current.levels.size() >= coarser) return;
        for (size_t i = from; i < order.size(); ++i) {
            const LevelCandidate& c = set.candidates[order[i]];
            if (double(c.triangles) > double(keepAtMost) * double(previous)) continue;
            current.levels.push_back(order[i]);
            current.bytes += c.bytes;
            self(self, i + 1, c.triangles);
            current.bytes -= c.bytes;
            current.levels.pop_back();
        }
    };
    walk(walk, 0, set.triangles);
    // Only the lower hull of (bytes, drawn) can be cheapest at some price: a scene of many
    // geometries then weighs a handful of options each, not every chain.
    std::stable_sort(out.begin(), out.end(), [](const Option& a, const Option& b) {
        return a.bytes < b.bytes || (a.bytes == b.bytes && a.drawn < b.drawn);
    });
    std::vector<Option> hull;
    for (Option& o : out) {
        if (!hull.empty() && o.drawn >= hull.back().drawn) continue; // more bytes, no fewer drawn
        while (hull.size() >= 2) {
            const Option &a = hull[hull.size() - 2], &b = hull.back();
            // b goes where it lies on or above the line from a to o.
            const double cross = double(b.bytes - a.bytes) * (o.drawn - a.drawn) -
                                 (b.drawn - a.drawn) * double(o.bytes - a.bytes);
            if (cross > 0.0) break;
            hull.pop_back();
        }
        hull.push_back(std::move(o));
    }
    return hull;
}

// Each set's cheapest option at `price` triangles per byte; ties to the fewer bytes.
std::vector<size_t> cheapest(const std::vector<CandidateSet>& sets,
                             const std::vector<std::vector<Option>>& options, double price,
                             uint64_t* bytes) {
    std::vector<size_t> picks(sets.size(), 0);
    *bytes = 0;
    for (size_t s = 0; s < sets.size(); ++s) {
        double best = 0.0;
        for (size_t o = 0; o < options[s].size(); ++o) {
            const Option& option = options[s][o];
            const double cost =
                double(sets[s].instances) * option.drawn + price * double(option.bytes);
            const Option& held = options[s][picks[s]];
            if (o == 0 || cost < best || (cost == best && option.bytes < held.bytes))
                best = cost, picks[s] = o;
        }
        *bytes += options[s][picks[s]].bytes;
    }
    return picks;
}

} // namespace

double drawnOverSpans(const CandidateSet& set, const std::vector<uint32_t>& levels) {
    const double lo = std::log(1.0 / widestSpanPixels), hi = std::log(0.5);
    double sum = 0.0, from = lo;
    size_t drawn = set.triangles;
    for (uint32_t l : levels) {
        const LevelCandidate& level = set.candidates[l];
        const double relative = set.size > 0.0f ? double(level.error) / double(set.size) : 1e30;
        const double to = std::clamp(std::log(std::max(relative, 1e-30)), lo, hi);
        sum += double(drawn) * (std::max(to, from) - from);
        from = std::max(to, from);
        drawn = level.triangles;
    }
    return (sum + double(drawn) * (hi - from)) / (hi - lo);
}

std::vector<std::vector<uint32_t>> chooseLevels(const std::vector<CandidateSet>& sets,
                                                uint32_t coarser, float keepAtMost,
                                                double byteBudget) {
    std::vector<std::vector<Option>> options(sets.size());
    for (size_t s = 0; s < sets.size(); ++s) {
        std::vector<uint32_t> order(sets[s].candidates.size());
        std::iota(order.begin(), order.end(), 0u);
        const auto& c = sets[s].candidates;
        std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
            return c[a].error < c[b].error ||
                   (c[a].error == c[b].error && c[a].triangles < c[b].triangles);
        });
        options[s] = optionsOf(sets[s], order, coarser, keepAtMost);
    }
    // The higher the price, the fewer bytes are kept; the lowest price within the budget wins.
    uint64_t bytes = 0;
    std::vector<size_t> picks = cheapest(sets, options, 0.0, &bytes);
    if (double(bytes) > byteBudget) {
        double lo = 0.0, hi = 1.0;
        while (cheapest(sets, options, hi, &bytes), double(bytes) > byteBudget && hi < 1e30)
            hi *= 4.0;
        for (int i = 0; i < 100 && hi > lo * (1.0 + 1e-9); ++i) {
            const double mid = lo > 0.0 ? std::sqrt(lo * hi) : hi / 1024.0;
            cheapest(sets, options, mid, &bytes);
            (double(bytes) > byteBudget ? lo : hi) = mid;
        }
        picks = cheapest(sets, options, hi, &bytes);
    }
    std::vector<std::vector<uint32_t>> out(sets.size());
    for (size_t s = 0; s < sets.size(); ++s) out[s] = options[s][picks[s]].levels;
    return out;
}

} // namespace scene
