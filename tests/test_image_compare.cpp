// test_image_compare.cpp - the tests' image comparison (image_compare.h) fails where images
// differ, and says where: the number of differing pixels, the first with its coordinates and
// both values, and for colour the largest difference; equal images and differences within
// the tolerance pass; images of different sizes never do.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include "image_compare.h"

namespace {

using testing_support::colourDifference;
using testing_support::idDifference;
using testing_support::sameColours;
using testing_support::sameIds;

constexpr uint32_t W = 4, H = 3;
constexpr uint32_t NONE = gpu::BACKGROUND_ID;

std::vector<uint32_t> idImage() {
    std::vector<uint32_t> ids(size_t(W) * H, NONE);
    for (uint32_t i = 0; i < W; ++i) ids[size_t(W) + i] = 7 + i; // the middle row: parts
    return ids;
}

std::vector<uint8_t> colourImage() {
    std::vector<uint8_t> rgba(size_t(W) * H * 4);
    for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = uint8_t(40 + i);
    return rgba;
}

TEST(ImageCompare, EqualIdImagesPass) {
    const auto ids = idImage();
    const auto d = idDifference(ids, ids, W);
    EXPECT_TRUE(d.same());
    EXPECT_EQ(d.pixels, 0u);
    EXPECT_EQ(d.compared, size_t(W) * H);
    EXPECT_FALSE(d.first.has_value());
    EXPECT_TRUE(sameIds(ids, ids, W));
}

TEST(ImageCompare, DifferingIdImagesFailAndSayWhere) {
    const auto expected = idImage();
    auto actual = expected;
    actual[size_t(W) + 2] = 99;    // (2, 1): part 9 became 99
    actual[size_t(2 * W) + 3] = 8; // (3, 2): background became part 8
    const auto d = idDifference(actual, expected, W);
    EXPECT_FALSE(d.same());
    EXPECT_EQ(d.pixels, 2u);
    EXPECT_EQ(d.first, size_t(W) + 2);
    EXPECT_EQ(d.message, "2 of 12 pixels of the ID images differ; the first at (2, 1): 99 "
                         "instead of 9");
    EXPECT_NE(idDifference(expected, actual, W).message.find("first at (2, 1): 9 instead of 99"),
              std::string::npos);
    // Background is named as such.
    actual[size_t(W) + 2] = 9;
    EXPECT_NE(idDifference(actual, expected, W).message.find("8 instead of background"),
              std::string::npos);
    EXPECT_NONFATAL_FAILURE(EXPECT_TRUE(sameIds(actual, expected, W)),
                            "1 of 12 pixels of the ID images differ; the first at (3, 2)");
}

TEST(ImageCompare, ImagesOfAnotherSizeNeverPass) {
    const auto ids = idImage();
    const std::vector<uint32_t> shorter(ids.begin(), ids.end() - 1);
    const auto d = idDifference(shorter, ids, W);
    EXPECT_TRUE(d.sizesDiffer);
    EXPECT_FALSE(d.same());
    EXPECT_EQ(d.message, "the ID images differ in size: 11 pixels against 12 expected");
    EXPECT_FALSE(sameColours({}, colourImage(), W));
    EXPECT_FALSE(sameColours(colourImage(), colourImage(), 0)) << "no width, no image";
}

TEST(ImageCompare, ColourExactlyOrWithinATolerance) {
    const auto expected = colourImage();
    EXPECT_TRUE(sameColours(expected, expected, W));
    auto actual = expected;
    actual[4 * (size_t(W) * 2 + 1) + 2] += 1; // (1, 2), blue one up
    EXPECT_FALSE(sameColours(actual, expected, W));
    EXPECT_TRUE(sameColours(actual, expected, W, 1));
    const auto within = colourDifference(actual, expected, W, 1);
    EXPECT_EQ(within.pixels, 0u);
    EXPECT_EQ(within.largest, 1);
    EXPECT_EQ(within.message, "the colour images are the same within 1 per channel (12 pixels, "
                              "largest difference 1)");

    actual[4 * 1 + 0] -= 2;                // (1, 0), red two down: past the tolerance
    actual[4 * (size_t(W) + 3) + 3] -= 30; // (3, 1), alpha thirty down
    const auto d = colourDifference(actual, expected, W, 1);
    EXPECT_EQ(d.pixels, 2u);
    EXPECT_EQ(d.largest, 30);
    EXPECT_EQ(d.message, "2 of 12 pixels of the colour images differ by more than 1 in a "
                         "channel; the first at (1, 0): (42, 45, 46, 47) instead of (44, 45, 46, "
                         "47); largest difference 30 in a channel");
    EXPECT_NONFATAL_FAILURE(EXPECT_TRUE(sameColours(actual, expected, W, 1)),
                            "largest difference 30");
    // Exact: the pixel one off counts too.
    EXPECT_EQ(colourDifference(actual, expected, W).pixels, 3u);
}

} // namespace
