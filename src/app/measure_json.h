// measure_json.h - the line of a measured distance, as --measure prints it and the viewer's
// measure mode says it.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "scene/units.h"
#include "util/json_writer.h"

namespace app {

// {"p0":[x,y,z],"p1":[x,y,z],"distance":D,"delta":[dx,dy,dz],"parts":[A,B],"unit":"mm"}, null
// where a point shows no part (and the distance and delta then), every digit of a double.
std::string measureJson(const std::array<std::optional<glm::dvec3>, 2>& points,
                        const std::array<std::optional<uint32_t>, 2>& parts,
                        const scene::LengthUnit& unit);
// The same members, into an object `json` has open (the viewer's measure record nests them).
void measureMembers(util::JsonWriter& json, const std::array<std::optional<glm::dvec3>, 2>& points,
                    const std::array<std::optional<uint32_t>, 2>& parts,
                    const scene::LengthUnit& unit);

} // namespace app
