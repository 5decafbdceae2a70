#include "golden.h"

#include "image_compare.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <vector>

namespace test {

void expectMatchesGolden(const demo::ImageF& image, const std::string& group, const std::string& name) {
    const std::string golden =
        std::string(POSTFX_SOURCE_DIR) + "/tests/" + group + "/golden/" + name + ".exr";
    std::string error;
    if (const char* accept = std::getenv("POSTFX_ACCEPT_GOLDENS"); accept && std::string(accept) == "1") {
        ASSERT_TRUE(demo::writeImage(golden, image, 15.0f, error)) << error;
        GTEST_SKIP() << "accepted new golden " << golden;
    }
    demo::ImageF expected;
    ASSERT_TRUE(demo::readImage(golden, expected, error)) << error;
    ASSERT_EQ(expected.width, image.width);
    ASSERT_EQ(expected.height, image.height);
    const ImageStats stats = compareImages(image.rgba, expected.rgba, image.width, image.height, 0.02, 1.0);
    if (stats.relativeRmse < 0.01 && stats.fractionOff < 0.005 && stats.nonFinite == 0) return;

    const std::filesystem::path dir = std::filesystem::current_path() / "golden-failures";
    std::filesystem::create_directories(dir);
    const std::string actualPath = (dir / (name + ".actual.exr")).string();
    const std::string diffPath = (dir / (name + ".diff.png")).string();
    EXPECT_TRUE(demo::writeImage(actualPath, image, 15.0f, error)) << error;
    // Red: |actual - expected| summed over RGB, white at 500 (about 5% of a sunlit surface).
    const std::vector<float> diff = diffImage(image.rgba, expected.rgba, 500.0);
    std::vector<uint8_t> diffBytes(diff.size());
    for (size_t i = 0; i < diff.size(); ++i)
        diffBytes[i] = uint8_t(std::lround(std::clamp(diff[i], 0.0f, 1.0f) * 255.0f));
    EXPECT_TRUE(demo::writePng8(diffPath, image.width, image.height, 4, diffBytes, error)) << error;
    ADD_FAILURE() << name << " differs from " << golden << ": " << stats.summary() << "; wrote " << actualPath
                  << " and " << diffPath;
}

}  // namespace test
