// blink.h - the hovered part's blink (compose.comp's highlight weight). It steps between two
// weights twice a period instead of following a smooth wave, so that a viewer at rest over a
// part composes the picture 2 * blinkHz times a second and sleeps in between.
#pragma once

#include <cmath>

namespace render {

constexpr double blinkHz = 1.5;
// Strong, then weak, never off: the hovered part always shows.
constexpr float blinkStrong = 1.0f, blinkWeak = 0.4f;

// The weight at `seconds` since the start: strong in the first half of each period.
inline float blinkWeight(double seconds) {
    const double halves = std::floor(seconds * 2.0 * blinkHz);
    return std::fmod(halves, 2.0) == 0.0 ? blinkStrong : blinkWeak;
}

// When the weight next changes, after `seconds`.
inline double nextBlinkChange(double seconds) {
    return (std::floor(seconds * 2.0 * blinkHz) + 1.0) / (2.0 * blinkHz);
}

} // namespace render
