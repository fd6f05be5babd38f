// units.h - the length unit of a scene's coordinates, said once per scene (Scene::unit, set
// where the scene is loaded); the viewer's lengths, areas and points written through these
// helpers, rounded to the scene's precision (precision.h), each line naming its unit at most
// once; the JSON's unit member. Plain C++.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "scene/precision.h"

namespace util {
class JsonWriter;
}

namespace scene {

struct LengthUnit {
    // "mm", "m", "in", ...; "" where the source has no physical unit (BREP files, the
    // procedural and built-in scenes).
    std::string symbol;
    std::string source; // where the unit comes from, for a tooltip and the docs
    bool operator==(const LengthUnit&) const = default;
};

// glTF's specification: metres.
LengthUnit gltfUnit();
// Generated scenes: sizes chosen for the eye, no physical unit.
LengthUnit generatedUnit();

// A block's heading, said once above bare numbers: "lengths in mm", "lengths: no unit".
std::string unitHeading(const LengthUnit& unit);

// Rounded (precision.h) and followed by their unit: "12.5 mm", "628.32 mm²", "1570.8 mm³",
// "(1, 2.5, -3) mm" (a coordinate or an offset vector). Without a unit the bare number: the
// panel says "lengths: no unit" once instead.
std::string formatLength(double value, const LengthUnit& unit, const Precision& precision);
std::string formatArea(double value, const LengthUnit& unit, const Precision& precision);
std::string formatVolume(double value, const LengthUnit& unit, const Precision& precision);
std::string formatPoint(glm::dvec3 p, const LengthUnit& unit, const Precision& precision);

// The JSON member every object holding lengths carries: "unit":"mm", or "unit":"none".
// Areas in such an object are in the unit squared.
void unitMember(util::JsonWriter& json, const LengthUnit& unit);

} // namespace scene
