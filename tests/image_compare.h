// image_compare.h - the one way the tests compare two images: ID images exactly, colour
// images exactly or within a tolerance per channel. A difference comes with a message a
// person can act on: how many pixels differ, the first with its coordinates and both values,
// and for colour the largest difference of one channel.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace testing_support {

// How one image differs from another of `width` pixels a row.
struct ImageDifference {
    size_t pixels = 0;           // pixels where a channel differs by more than the tolerance
    size_t compared = 0;         // pixels compared (0 when the sizes differ)
    std::optional<size_t> first; // the first such pixel, row-major
    int largest = 0;             // colour: the largest difference of one channel, any pixel
    bool sizesDiffer = false;
    std::string message; // what differs, or that nothing does
    bool same() const { return !sizesDiffer && pixels == 0; }
};

namespace image_compare_detail {

inline std::string idText(uint32_t id) {
    return id == gpu::BACKGROUND_ID ? std::string("background") : std::to_string(id);
}

inline std::string colourText(const uint8_t* rgba) {
    std::ostringstream text;
    text << "(" << int(rgba[0]) << ", " << int(rgba[1]) << ", " << int(rgba[2]) << ", "
         << int(rgba[3]) << ")";
    return text.str();
}

// The counts and the first pixel; `channels` values a pixel, differences by more than
// `tolerance` count. IDs (uint32_t) have no distance between them: any difference counts.
// `what` names the images ("ID", "colour") in the message.
template <typename T>
ImageDifference compare(const std::vector<T>& actual, const std::vector<T>& expected,
                        uint32_t width, uint32_t channels, int tolerance, const char* what) {
    constexpr bool colour = sizeof(T) == 1;
    ImageDifference d;
    std::ostringstream text;
    if (actual.size() != expected.size() || width == 0 || actual.size() % channels != 0) {
        d.sizesDiffer = true;
        if (width == 0)
            text << "the " << what << " images were compared without a width";
        else
            text << "the " << what << " images differ in size: " << actual.size() / channels
                 << " pixels against " << expected.size() / channels << " expected";
        d.message = text.str();
        return d;
    }
    d.compared = actual.size() / channels;
    for (size_t p = 0; p < d.compared; ++p) {
        bool differs = false;
        for (size_t c = 0; c < channels; ++c) {
            const size_t i = p * channels + c;
            if (actual[i] == expected[i]) continue;
            if constexpr (colour) {
                const int by = std::abs(int(actual[i]) - int(expected[i]));
                d.largest = std::max(d.largest, by);
                differs = differs || by > tolerance;
            } else {
                differs = true;
            }
        }
        if (!differs) continue;
        if (!d.first) d.first = p;
        ++d.pixels;
    }
    if (d.pixels == 0) {
        text << "the " << what << " images are the same";
        if (tolerance > 0) text << " within " << tolerance << " per channel";
        text << " (" << d.compared << " pixels";
        if (colour) text << ", largest difference " << d.largest;
        text << ")";
    } else {
        const size_t p = *d.first;
        text << d.pixels << " of " << d.compared << " pixels of the " << what << " images differ";
        if (tolerance > 0) text << " by more than " << tolerance << " in a channel";
        text << "; the first at (" << p % width << ", " << p / width << "): ";
        if constexpr (colour)
            text << colourText(&actual[p * channels]) << " instead of "
                 << colourText(&expected[p * channels]);
        else
            text << idText(actual[p]) << " instead of " << idText(expected[p]);
        if (colour) text << "; largest difference " << d.largest << " in a channel";
    }
    d.message = text.str();
    return d;
}

inline ::testing::AssertionResult asAssertion(const ImageDifference& d) {
    return (d.same() ? ::testing::AssertionSuccess() : ::testing::AssertionFailure()) << d.message;
}

} // namespace image_compare_detail

// ID images (one uint32 a pixel) compared exactly.
inline ImageDifference idDifference(const std::vector<uint32_t>& actual,
                                    const std::vector<uint32_t>& expected, uint32_t width) {
    return image_compare_detail::compare(actual, expected, width, 1, 0, "ID");
}

// RGBA8 colour images, a pixel differing where a channel is more than `tolerance` off.
inline ImageDifference colourDifference(const std::vector<uint8_t>& actual,
                                        const std::vector<uint8_t>& expected, uint32_t width,
                                        int tolerance = 0) {
    return image_compare_detail::compare(actual, expected, width, 4, tolerance, "colour");
}

// For EXPECT_TRUE / EXPECT_FALSE: gtest prints the message either way it fails.
inline ::testing::AssertionResult sameIds(const std::vector<uint32_t>& actual,
                                          const std::vector<uint32_t>& expected, uint32_t width) {
    return image_compare_detail::asAssertion(idDifference(actual, expected, width));
}
inline ::testing::AssertionResult sameColours(const std::vector<uint8_t>& actual,
                                              const std::vector<uint8_t>& expected, uint32_t width,
                                              int tolerance = 0) {
    return image_compare_detail::asAssertion(colourDifference(actual, expected, width, tolerance));
}

} // namespace testing_support
