// json_number.h - numbers and points in JSON with every digit a double needs: world
// coordinates far from the origin (a building at its map position, in metres) must read back
// to the same double, which nine significant digits do not promise.
#pragma once

#include <string>

#include <glm/glm.hpp>

namespace util {

// The shortest decimal that reads back as exactly `value` ("0.1", "458005.5"); JSON has no
// NaN or infinity, so those print as null.
std::string jsonNumber(double value);

// [x,y,z], each as jsonNumber.
std::string jsonVector(const glm::dvec3& value);

} // namespace util
