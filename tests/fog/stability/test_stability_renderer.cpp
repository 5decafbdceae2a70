// Hard cases through the demo's host renderer on whole scenes (docs/stability.md, "Whole scenes"): each
// committed scene in tests/fog/stability/scenes is rendered by demo::Renderer (G-buffer, shadow map,
// lighting, then postfx, as a host would) and by its CPU reference path (the same frame with postfx's fog
// replaced by the double-precision reference with the scene's step count), into the renderer's RGBA16F
// image. Pre-exposed (FrameInfo::preExposure, the demo's default: the camera's exposure): no NaN or Inf,
// the stored values within RGBA16F's range, and agreement with the unclamped reference in physical units.
// Without pre-exposure (physical units in RGBA16F): no NaN or Inf, nothing beyond 65,504, and agreement with
// the reference clamped to that range (the documented clipping: a 1e5 lux sun's in-scattering exceeds it).
#include "gpu_test.h"
#include "host/renderer.h"
#include "scene/scene.h"
#include "stability_frame.h"

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <string>

namespace test {
namespace {

struct RendererCase {
    const char* scene;  // under tests/fog/stability/scenes
    bool reversedZ = true;
    bool infiniteFar = false;
    bool preExpose = true;    // RenderOptions::preExpose
    double tolerance = 3e-3;  // relative, of max(|expected|, 1), per channel
};

void PrintTo(const RendererCase& c, std::ostream* os) {
    *os << c.scene << (c.reversedZ ? ", reversed Z" : ", standard Z")
        << (c.infiniteFar ? ", infinite far plane" : "") << (c.preExpose ? "" : ", no pre-exposure");
}

class FogStabilityRenderer : public GpuTest, public ::testing::WithParamInterface<RendererCase> {};

TEST_P(FogStabilityRenderer, FiniteAndWithinToleranceOfTheReference) {
    const RendererCase& c = GetParam();
    demo::Scene scene;
    std::string error;
    const std::string path = std::string(POSTFX_SOURCE_DIR) + "/tests/fog/stability/scenes/" + c.scene;
    ASSERT_TRUE(demo::loadSceneFile(path, scene, error)) << error;
    // The scenes' fog marches without jitter or early cutoff, so the reference with the same step count
    // samples the same points.
    ASSERT_FALSE(scene.fog.jitter);
    ASSERT_EQ(scene.fog.transmittanceCutoff, 0.0f);

    demo::RenderOptions options;
    options.width = 64;
    options.height = 36;
    options.shadowMapSize = 256;
    options.reversedZ = c.reversedZ;
    options.infiniteFar = c.infiniteFar;
    options.preExpose = c.preExpose;
    auto renderer = demo::Renderer::create(*host, options, error);
    ASSERT_TRUE(renderer) << error;
    demo::ImageF gpu, reference;
    ASSERT_TRUE(renderer->render(scene, gpu, error)) << error;
    ASSERT_TRUE(renderer->renderReference(scene, reference, error, scene.fog.steps)) << error;

    // Both images are in physical units (the renderer divides its pre-exposure out). Pre-exposed, the
    // RGBA16F image held gpu · p: compared with the reference unclamped, and its stored values checked
    // against half's range; without, the reference clamped to half's range as the image was.
    const float p = renderer->preExposure();
    std::vector<float> stored = gpu.rgba;
    for (float& v : stored)
        v *= p;
    const Comparison range = compareToExpected(stored, stored, VK_FORMAT_R16G16B16A16_SFLOAT, c.tolerance);
    const Comparison cmp = compareToExpected(
        gpu.rgba, reference.rgba, c.preExpose ? VK_FORMAT_R32G32B32A32_SFLOAT : VK_FORMAT_R16G16B16A16_SFLOAT,
        c.tolerance);
    float largest = 0.0f;
    for (size_t i = 0; i < gpu.rgba.size(); ++i)
        if (i % 4 != 3) largest = std::max(largest, gpu.rgba[i]);
    std::printf(
        "[ stability ] %s%s (pre-exposure %.3g): worst relative difference %.3g (tolerance %.3g), "
        "largest radiance %.4g\n",
        c.scene, c.preExpose ? "" : " without pre-exposure", double(p), cmp.worstRelative, c.tolerance,
        double(largest));
    EXPECT_EQ(c.preExpose, p < 1.0f);  // the demo's cameras (ev100 > 0) pre-expose below 1
    EXPECT_EQ(cmp.nonFinite, 0u) << "NaN or Inf in the output";
    EXPECT_EQ(range.outOfRange, 0u) << "stored values beyond RGBA16F's largest finite value";
    EXPECT_EQ(cmp.off, 0u) << cmp.firstOff;
}

const RendererCase kCases[] = {
    {"fog_far_below.json"},
    {"fog_far_below.json", false, true},
    {"fog_sun_in_view.json"},
    {"fog_sun_in_view.json", true, false, false},
    // Haze (0.02 /m) of g = 0.8 and 0.999 in front of a 100,000 lux sun: its in-scattering is
    // ~3e5 and ~1e8 cd/m² toward the sun, beyond RGBA16F without pre-exposure.
    {"fog_haze_sun_g08.json"},
    {"fog_haze_sun_g08.json", true, false, false},
    {"fog_haze_sun_g0999.json"},
    {"fog_haze_sun_g0999.json", true, false, false},
    {"fog_far_from_origin.json"},
    {"fog_extreme_projection.json"},
    {"fog_extreme_projection.json", true, true},
    {"fog_dense_night.json"},
};

std::string caseName(const ::testing::TestParamInfo<RendererCase>& info) {
    std::string name = info.param.scene;
    name = name.substr(0, name.find('.'));
    if (!info.param.reversedZ) name += "_standardZ";
    if (info.param.infiniteFar) name += "_infiniteFar";
    if (!info.param.preExpose) name += "_noPreExposure";
    return name;
}

INSTANTIATE_TEST_SUITE_P(Scenes, FogStabilityRenderer, ::testing::ValuesIn(kCases), caseName);

}  // namespace
}  // namespace test
