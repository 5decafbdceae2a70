// Hard cases through the demo's host renderer on whole scenes (docs/stability.md, "Whole scenes"): each
// committed scene in tests/fog/stability/scenes is rendered by demo::Renderer (G-buffer, shadow map,
// lighting, then postfx, as a host would) and by its CPU reference path (the same frame with postfx's fog
// replaced by the double-precision reference with the scene's step count). Asserts: no NaN or Inf, nothing
// beyond RGBA16F's largest finite value, and agreement with the reference clamped to that range.
#include "gpu_test.h"
#include "host/renderer.h"
#include "scene/scene.h"
#include "stability_frame.h"

#include <cstdio>
#include <ostream>
#include <string>

namespace test {
namespace {

struct RendererCase {
    const char* scene;  // under tests/fog/stability/scenes
    bool reversedZ = true;
    bool infiniteFar = false;
    double tolerance = 3e-3;  // relative, of max(|expected|, 1), per channel
};

void PrintTo(const RendererCase& c, std::ostream* os) {
    *os << c.scene << (c.reversedZ ? ", reversed Z" : ", standard Z")
        << (c.infiniteFar ? ", infinite far plane" : "");
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
    auto renderer = demo::Renderer::create(*host, options, error);
    ASSERT_TRUE(renderer) << error;
    demo::ImageF gpu, reference;
    ASSERT_TRUE(renderer->render(scene, gpu, error)) << error;
    ASSERT_TRUE(renderer->renderReference(scene, reference, error, scene.fog.steps)) << error;

    const Comparison cmp =
        compareToExpected(gpu.rgba, reference.rgba, VK_FORMAT_R16G16B16A16_SFLOAT, c.tolerance);
    std::printf("[ stability ] %s: worst relative difference %.3g (tolerance %.3g)\n", c.scene,
                cmp.worstRelative, c.tolerance);
    EXPECT_EQ(cmp.nonFinite, 0u) << "NaN or Inf in the output";
    EXPECT_EQ(cmp.outOfRange, 0u) << "values beyond RGBA16F's largest finite value";
    EXPECT_EQ(cmp.off, 0u) << cmp.firstOff;
}

const RendererCase kCases[] = {
    {"fog_far_below.json"},          {"fog_far_below.json", false, true},
    {"fog_sun_in_view.json"},        {"fog_far_from_origin.json"},
    {"fog_extreme_projection.json"}, {"fog_extreme_projection.json", true, true},
    {"fog_dense_night.json"},
};

std::string caseName(const ::testing::TestParamInfo<RendererCase>& info) {
    std::string name = info.param.scene;
    name = name.substr(0, name.find('.'));
    if (!info.param.reversedZ) name += "_standardZ";
    if (info.param.infiniteFar) name += "_infiniteFar";
    return name;
}

INSTANTIATE_TEST_SUITE_P(Scenes, FogStabilityRenderer, ::testing::ValuesIn(kCases), caseName);

}  // namespace
}  // namespace test
