// The image comparison the golden and reference tests rely on.
#include "image_compare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

std::vector<float> constant(size_t pixels, float v) {
    std::vector<float> image(pixels * 4, v);
    for (size_t p = 0; p < pixels; ++p)
        image[p * 4 + 3] = 1.0f;
    return image;
}

TEST(CommonImageCompare, IdenticalImagesHaveZeroError) {
    const auto a = constant(12, 5.0f);
    const test::ImageStats s = test::compareImages(a, a, 4, 3, 0.01, 1.0);
    EXPECT_EQ(s.relativeRmse, 0.0);
    EXPECT_EQ(s.maxAbsError, 0.0);
    EXPECT_EQ(s.fractionOff, 0.0);
}

TEST(CommonImageCompare, UniformScaleGivesThatRelativeRmse) {
    const auto expected = constant(12, 100.0f);
    const auto actual = constant(12, 103.0f);
    const test::ImageStats s = test::compareImages(actual, expected, 4, 3, 0.01, 1.0);
    EXPECT_NEAR(s.relativeRmse, 0.03, 1e-9);
    EXPECT_NEAR(s.maxAbsError, 3.0, 1e-9);
    EXPECT_EQ(s.fractionOff, 1.0);  // 3% > 1% on every pixel
    EXPECT_EQ(test::compareImages(actual, expected, 4, 3, 0.05, 1.0).fractionOff, 0.0);
}

TEST(CommonImageCompare, OnePixelOffAndNonFiniteValuesAreCounted) {
    const auto expected = constant(4, 10.0f);
    auto actual = expected;
    actual[1] = 12.0f;      // pixel 0, green
    actual[8] = NAN;        // pixel 2, red
    actual[13] = INFINITY;  // pixel 3, green
    const test::ImageStats s = test::compareImages(actual, expected, 2, 2, 0.05, 1.0);
    EXPECT_EQ(s.nonFinite, 2u);
    EXPECT_EQ(s.fractionOff, 0.75);
    EXPECT_TRUE(std::isfinite(s.relativeRmse));
}

TEST(CommonImageCompare, MismatchedSizesFail) {
    const auto a = constant(4, 1.0f);
    const test::ImageStats s = test::compareImages(a, a, 4, 4, 0.01, 1.0);
    EXPECT_TRUE(std::isinf(s.relativeRmse));
}

}  // namespace
