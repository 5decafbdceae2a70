// The demo's metering (host/metering.h): the pre-exposure is the camera's when what the frame shows fits
// half precision, lowered when the largest pixel would pass 2^15 (re-measured after a clip), raised when
// the median would fall below 2^-10 (re-measured after a frame of zeros).
#include "host/metering.h"

#include <gtest/gtest.h>

#include <glm/gtc/packing.hpp>

#include <vector>

namespace {

// Pixels of (v, v/2, v/4, 1) for each stored value v.
std::vector<uint16_t> image(const std::vector<float>& values) {
    std::vector<uint16_t> out;
    for (float v : values)
        for (float c : {v, 0.5f * v, 0.25f * v, 1.0f})
            out.push_back(glm::packHalf1x16(c));
    return out;
}

constexpr double kLowest = 0x1p-33, kHighest = 0x1p33;

}  // namespace

TEST(DemoMetering, MeasuresTheLargestAndTheMedianOfTheLitPixels) {
    const std::vector<uint16_t> im = image({0.0f, 2.0f, 0.5f, 8.0f, 0.0f});
    const demo::Metering m = demo::meterHalfImage(im.data(), 5);
    EXPECT_EQ(m.largest, 8.0);
    EXPECT_EQ(m.median, 2.0);  // of 0.5, 2 and 8
    EXPECT_FALSE(m.clipped());
    const std::vector<uint16_t> clipped = image({1.0f, 1e6f});  // stored as Inf
    EXPECT_TRUE(demo::meterHalfImage(clipped.data(), 2).clipped());
}

TEST(DemoMetering, KeepsTheCamerasExposureWhenTheFrameFits) {
    demo::Metering m;
    m.largest = 20000.0;  // below 2^15
    m.median = 0.01;
    // The camera's exposure rounded down to a power of two, within the scene's limit.
    EXPECT_EQ(demo::meteredPreExposure(m, 0x1p-16, 2.2e-5, kLowest, kHighest), 0x1p-16);
    EXPECT_EQ(demo::meteredPreExposure(m, 0x1p-16, 2.2e-5, kLowest, 0x1p-17), 0x1p-17);
}

TEST(DemoMetering, LowersThePreExposureSoThatNothingSeenClips) {
    demo::Metering m;
    m.largest = demo::Metering::kClipped;
    m.median = 100.0;
    // A clip is a lower bound: measure again 2^16 lower.
    EXPECT_EQ(demo::meteredPreExposure(m, 64.0, 1e9, kLowest, 64.0), 64.0 * 0x1p-16);
    // Measured: a sky of 10,000 cd/m² at 2^-10 is 9.8; it goes to at most 2^14, below the camera's wish.
    m.largest = 1e4 * 0x1p-10;
    m.median = 5e3 * 0x1p-10;
    EXPECT_EQ(demo::meteredPreExposure(m, 0x1p-10, 1e9, kLowest, 64.0), 1.0);
}

TEST(DemoMetering, RaisesThePreExposureSoThatWhatIsSeenKeepsItsDigits) {
    demo::Metering m;  // all zero at 2^-31: measure again 2^16 higher
    EXPECT_EQ(demo::meteredPreExposure(m, 0x1p-31, 7.8e-10, kLowest, kHighest), 0x1p-15);
    // All zero at a pre-exposure where nothing could have underflowed: a black frame, left as it is.
    EXPECT_EQ(demo::meteredPreExposure(m, 0x1p-5, 0x1p-5, kLowest, kHighest), 0x1p-5);
    // A median of 2 cd/m² goes to 2^-3 (middle grey), unless the largest pixel then passes 2^15.
    m.largest = 50.0 * 0x1p-15;
    m.median = 2.0 * 0x1p-15;
    EXPECT_EQ(demo::meteredPreExposure(m, 0x1p-15, 7.8e-10, kLowest, kHighest), 0x1p-4);
    m.largest = 1e6 * 0x1p-15;
    EXPECT_EQ(demo::meteredPreExposure(m, 0x1p-15, 7.8e-10, kLowest, kHighest), 0x1p-6);
}
