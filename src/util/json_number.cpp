// json_number.cpp - shortest round-trip decimals through std::to_chars.
#include "util/json_number.h"

#include <charconv>
#include <cmath>

namespace util {

std::string jsonNumber(double value) {
    if (!std::isfinite(value)) return "null";
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

std::string jsonVector(const glm::dvec3& value) {
    return "[" + jsonNumber(value.x) + "," + jsonNumber(value.y) + "," + jsonNumber(value.z) + "]";
}

} // namespace util
