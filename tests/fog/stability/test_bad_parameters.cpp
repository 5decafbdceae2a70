// Bad parameters (docs/stability.md, "Bad parameters"): NaN in every floating-point fog setting, and
// values just outside each documented range, are rejected by postfx's check (the one Context::record
// runs) with InvalidArgument naming the field by its scene-file key. Images (zero-size, mismatched,
// missing) are covered by tests/core/test_core.cpp (RecordValidatesFrameInputs), lighting and camera
// by tests/fog/test_fog_api.cpp; the command line by tests/demo/cli_bad_input.sh.
#include <gtest/gtest.h>
#include <postfx/fog.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace {

struct Field {
    const char* key;  // as the message names it
    std::function<float&(postfx::FogSettings&)> at;
    float below, above;  // just outside the documented range (NaN where there is no bound: NaN again)
};

const float kNan = std::numeric_limits<float>::quiet_NaN();

const Field kFields[] = {
    {"FrameInfo.fog.density", [](postfx::FogSettings& s) -> float& { return s.density; }, -1e-6f, 1.1e6f},
    {"FrameInfo.fog.albedo", [](postfx::FogSettings& s) -> float& { return s.albedo.g; }, -1e-6f, 1.001f},
    {"FrameInfo.fog.anisotropy", [](postfx::FogSettings& s) -> float& { return s.anisotropy; }, -1.001f,
     1.001f},
    {"FrameInfo.fog.heightFalloff", [](postfx::FogSettings& s) -> float& { return s.heightFalloff; }, -1e-6f,
     10.01f},
    {"FrameInfo.fog.baseHeight", [](postfx::FogSettings& s) -> float& { return s.baseHeight; }, kNan, kNan},
    {"FrameInfo.fog.maxDistance", [](postfx::FogSettings& s) -> float& { return s.maxDistance; }, 0.0f,
     1.1e7f},
    {"FrameInfo.fog.resolutionScale", [](postfx::FogSettings& s) -> float& { return s.resolutionScale; },
     0.2499f, 1.001f},
    {"FrameInfo.fog.transmittanceCutoff",
     [](postfx::FogSettings& s) -> float& { return s.transmittanceCutoff; }, -1e-6f, 1.0f},
    {"FrameInfo.fog.autoBudgetMs", [](postfx::FogSettings& s) -> float& { return s.autoBudgetMs; }, 0.0f,
     kNan},
    {"FrameInfo.fog.noise.tiling", [](postfx::FogSettings& s) -> float& { return s.noise.tiling; }, 0.0f,
     1001.0f},
    {"FrameInfo.fog.noise.threshold", [](postfx::FogSettings& s) -> float& { return s.noise.threshold; },
     -1e-6f, 1.001f},
    {"FrameInfo.fog.noise.multiplier", [](postfx::FogSettings& s) -> float& { return s.noise.multiplier; },
     -1e-6f, 1001.0f},
    {"FrameInfo.fog.noise.wind", [](postfx::FogSettings& s) -> float& { return s.noise.wind.z; }, -1001.0f,
     1001.0f},
};

postfx::FogSettings valid() {
    postfx::FogSettings s;
    s.enabled = true;
    s.noise.enabled = true;  // the noise's fields are checked only when it is on
    return s;
}

void expectRejected(const postfx::FogSettings& s, const std::string& key, const std::string& what) {
    const postfx::Status status = postfx::validateFogSettings(s);
    EXPECT_EQ(status.code, postfx::Result::InvalidArgument) << key << " " << what;
    EXPECT_EQ(status.message.rfind(key, 0), 0u) << key << " " << what << ": " << status.message;
    EXPECT_EQ(status.message.find('\n'), std::string::npos) << "one line: " << status.message;
}

TEST(FogStabilityBadParameters, NanInfAndOutOfRangeInEverySettingAreRejectedNamingIt) {
    ASSERT_TRUE(postfx::validateFogSettings(valid()).ok());
    for (const Field& f : kFields) {
        for (float bad : {kNan, std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity(), f.below, f.above}) {
            postfx::FogSettings s = valid();
            f.at(s) = bad;
            expectRejected(s, f.key, std::to_string(bad));
        }
    }
}

TEST(FogStabilityBadParameters, IntegerSettingsOutsideTheirRangeAreRejected) {
    postfx::FogSettings s = valid();
    s.steps = 0;
    expectRejected(s, "FrameInfo.fog.steps", "0");
    s = valid();
    s.steps = 4097;
    expectRejected(s, "FrameInfo.fog.steps", "4097");
    for (uint32_t kernel : {0u, 2u, 9u}) {
        s = valid();
        s.shadowKernel = kernel;
        expectRejected(s, "FrameInfo.fog.shadowKernel", std::to_string(kernel));
    }
    s = valid();
    s.noise.textureSize = 100;
    expectRejected(s, "FrameInfo.fog.noise.textureSize", "100");
}

}  // namespace
