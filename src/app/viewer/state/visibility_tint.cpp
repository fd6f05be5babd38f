// visibility_tint.cpp - the census's colours per part (visibility_tint.h).
#include "app/viewer/state/visibility_tint.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/packing.hpp>

namespace app {

double tintRampPosition(uint64_t pixels, uint64_t largest) {
    if (largest == 0) return 0.0;
    const double t = std::log1p(double(pixels)) / std::log1p(double(largest));
    return std::clamp(t, 0.0, 1.0);
}

uint32_t tintRamp(double t) {
    static constexpr std::array<glm::vec3, 5> stops = {glm::vec3(0, 0, 1), glm::vec3(0, 1, 1),
                                                       glm::vec3(0, 1, 0), glm::vec3(1, 1, 0),
                                                       glm::vec3(1, 0, 0)};
    const double at = std::clamp(t, 0.0, 1.0) * double(stops.size() - 1);
    const size_t i = std::min(size_t(at), stops.size() - 2);
    const glm::vec3 rgb = glm::mix(stops[i], stops[i + 1], float(at - double(i)));
    return glm::packUnorm4x8(glm::vec4(rgb, float(tintStrength) / 255.0f));
}

std::vector<uint32_t> visibilityTint(const scene::Census& census, const scene::PartSet& neverSeen) {
    uint64_t largest = 0;
    for (const scene::CensusPart& part : census.parts) largest = std::max(largest, part.pixels);
    std::vector<uint32_t> tint(census.parts.size(), 0u);
    for (uint32_t id = 0; id < tint.size(); ++id) {
        if (census.seen(id))
            tint[id] = tintRamp(tintRampPosition(census.parts[id].pixels, largest));
        else if (id < neverSeen.partCount() && neverSeen.contains(id))
            tint[id] = neverSeenTint;
    }
    return tint;
}

} // namespace app
