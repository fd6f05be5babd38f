// census.h - the visibility census's views and what it found (the GPU part is
// render/census.h): which unique parts a set of views spread over the sphere shows, how many
// pixels of each summed over the views, in how many views, and the most of one view.
// Every view is orthographic and holds the same bounding sphere, so a pixel stands for the
// same area in each and the sums compare across parts and views.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/camera.h"
#include "scene/part_set.h"
#include "scene/scene.h"

namespace scene {

// What a census draws: `views` views of `size` x `size` pixels (--census VIEWSxSIZE).
struct CensusSpec {
    uint32_t views = 0;
    uint32_t size = 0;
    bool operator==(const CensusSpec&) const = default;
};

// `count` unit directions spread evenly over the sphere: a Fibonacci lattice, whose points
// keep about the same spacing for any count (no poles crowded, as a latitude grid has).
std::vector<glm::dvec3> censusDirections(uint32_t count);

// The orthographic camera of the census view from `direction` (target to eye): looking at
// the centre of `bounds`, its square view the bounding sphere's diameter plus 2%, its planes
// taking in the whole sphere.
Camera censusCamera(const Bounds& bounds, glm::dvec3 direction);

using CensusPart = gpu::CensusTotals; // pixels (summed over the views), views, largest

struct Census {
    uint32_t views = 0;             // views drawn
    uint32_t width = 0, height = 0; // of each view
    std::vector<CensusPart> parts;  // by unique part ID
    double ms = 0.0;                // from the first view's recording to the read-back

    bool seen(uint32_t part) const { return parts[part].pixels > 0; }
    // The part's largest count in one view over the view's pixels.
    double largestShare(uint32_t part) const {
        return double(parts[part].largest) / (double(width) * height);
    }
};

// The parts with a pixel in some view.
PartSet seenParts(const Census& census);
// Per object: 1 where some part of it was seen.
std::vector<uint8_t> seenObjects(const Scene& scene, const Census& census);

// The census's answer in counts. Never seen: drawable (with triangles) and not hidden, yet
// in no view; hidden and empty parts are counted apart, as the census could not see them.
struct CensusSummary {
    uint32_t parts = 0, partsSeen = 0, partsNeverSeen = 0, partsHidden = 0, partsEmpty = 0;
    uint32_t objects = 0, objectsSeen = 0, objectsNeverSeen = 0; // objects: solids in CAD
    uint64_t triangles = 0;                // drawn for every object (instances counted)
    uint64_t trianglesNeverSeen = 0;       // of the parts never seen
    uint64_t objectTrianglesNeverSeen = 0; // of the objects never seen
};
CensusSummary summarize(const Scene& scene, const Census& census, const PartSet& hidden);

// The parts never seen, as CensusSummary counts them.
PartSet neverSeenParts(const Scene& scene, const Census& census, const PartSet& hidden);

} // namespace scene
