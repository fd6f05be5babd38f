// lod_choice.h - which of a scene's candidate levels of detail to keep: those that would draw
// the fewest triangles, every object and every distance counted, within a memory budget for
// the whole scene. Plain arithmetic over sizes and errors, apart from the geometry itself.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace scene {

struct LevelCandidate {
    size_t triangles = 0;
    uint64_t bytes = 0;
    float error = 0.0f; // model units
};

struct CandidateSet {
    size_t triangles = 0;   // full detail's
    float size = 0.0f;      // the diagonal of its box, model units
    uint32_t instances = 1; // objects that draw it
    std::vector<LevelCandidate> candidates;
};

// Where an object is seen its level is chosen by error over size on screen: at one pixel of
// error, an error of r times its size is allowed where it spans 1 / r pixels. Levels are
// weighed over every span from this many pixels (about a screen's width) down to two, each
// doubling of the distance alike.
constexpr double widestSpanPixels = 2048.0;

// The triangles an object draws with full detail and `levels` (candidates by growing error),
// averaged over the spans weighed.
double drawnOverSpans(const CandidateSet& set, const std::vector<uint32_t>& levels);

// For each set, the candidates kept as its levels 1, 2, ... by growing error: at most
// `coarser` of them, each keeping at most `keepAtMost` of the triangles of the level before,
// such that the scene's objects draw the fewest triangles over the spans weighed while every
// level kept takes at most `byteBudget` bytes in all. The budget is shared by a price per
// byte that every set weighs its triangles saved against (the price found by bisection), so
// memory goes where the objects that draw a geometry save the most with it.
std::vector<std::vector<uint32_t>> chooseLevels(const std::vector<CandidateSet>& sets,
                                                uint32_t coarser, float keepAtMost,
                                                double byteBudget);

} // namespace scene
