// measure_json.cpp - the measured distance's JSON line (measure_json.h).
#include "app/measure_json.h"

#include "util/json_writer.h"

namespace app {

std::string measureJson(const std::array<std::optional<glm::dvec3>, 2>& points,
                        const std::array<std::optional<uint32_t>, 2>& parts,
                        const scene::LengthUnit& unit) {
    util::JsonWriter json;
    measureMembers(json.beginObject(), points, parts, unit);
    return json.endObject().text();
}

void measureMembers(util::JsonWriter& json, const std::array<std::optional<glm::dvec3>, 2>& points,
                    const std::array<std::optional<uint32_t>, 2>& parts,
                    const scene::LengthUnit& unit) {
    const auto& [p0, p1] = points;
    std::optional<glm::dvec3> delta;
    std::optional<double> distance;
    if (p0 && p1) {
        delta = *p1 - *p0;
        distance = glm::length(*delta);
    }
    // Every digit of a double: points far from the origin read back exactly.
    json.member("p0", p0)
        .member("p1", p1)
        .member("distance", distance)
        .member("delta", delta)
        .beginArray("parts")
        .value(parts[0])
        .value(parts[1])
        .endArray();
    scene::unitMember(json, unit);
}

} // namespace app
