// Every setting of every registered effect (postfx::effectSettingsTables) at both ends of its documented
// range renders: the demo renderer's GPU frame is finite and within RGBA16F's range, and its CPU
// reference (postfx-render --reference) is finite, or postfx refuses the frame with one line naming the
// setting (a rule across fields, the memory budget). The table alone drives it, so an effect added to the
// registry (and to sceneSettings below, which fails the test until it is) is covered at birth. Every
// count and size is at its minimum except the one under test, so each frame is small; the values just
// outside the ranges are CoreApiRanges.EveryTableSettingJustOutsideItsRangeIsRefusedNamingIt's.
#include "gpu_test.h"
#include "host/renderer.h"
#include "scene/scene.h"

#include <postfx/settings_table.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

namespace test {
namespace {

using postfx::SettingField;
using postfx::SettingKind;

// The scene's settings struct of the registered effect `key`; nullptr for an effect the demo lacks.
void* sceneSettings(demo::Scene& scene, const std::string& key) {
    if (key == "atmosphere") return &scene.atmosphere;
    if (key == "clouds") return &scene.clouds;
    if (key == "fog") return &scene.fog;
    if (key == "froxel_fog") return &scene.froxelFog;
    return nullptr;
}

// A ground, a box, the sun 40° up at 1e5 lux behind the camera's right, a sky of 1e3 cd/m².
demo::Scene baseScene() {
    demo::Scene s;
    s.camera.position = {0.0f, 2.0f, 10.0f};
    s.camera.lookAt = {0.0f, 4.0f, 0.0f};
    s.camera.farPlane = 1e5f;
    s.camera.ev100 = 14.0f;
    s.sun.direction = glm::normalize(glm::vec3(0.4f, 0.64f, 0.3f));
    s.sun.illuminance = glm::vec3(1e5f);
    s.sky = glm::vec3(1e3f);
    s.ambient = glm::vec3(1e3f);
    demo::Object ground;
    s.objects.push_back(ground);
    demo::Object box;
    box.type = demo::ObjectType::Box;
    box.position = {0.0f, 1.0f, -5.0f};
    box.halfSize = glm::vec3(1.0f);
    s.objects.push_back(box);
    return s;
}

// Counts and sizes at their minimum (the frame small), where the minimum passes postfx's own rules.
void smallest(std::span<const SettingField> table, void* s) {
    for (const SettingField& f : table) {
        const uint32_t lo = uint32_t(f.min);
        if (f.kind == SettingKind::Uint) postfx::settingValue<uint32_t>(f, s) = lo;
        if (f.kind == SettingKind::UVec2) postfx::settingValue<postfx::UVec2>(f, s) = {lo, lo};
        if (f.kind == SettingKind::UVec3) postfx::settingValue<postfx::UVec3>(f, s) = {lo, lo, lo};
    }
}

// The field (component `c`, -1: all) at `value`; false when the kind has no range.
bool setValue(const SettingField& f, void* s, double value) {
    switch (f.kind) {
        case SettingKind::Float:
            postfx::settingValue<float>(f, s) = float(value);
            return true;
        case SettingKind::Vec3:
        case SettingKind::Color:
            postfx::settingValue<postfx::Vec3>(f, s) = postfx::Vec3(float(value));
            return true;
        case SettingKind::Double:
            postfx::settingValue<double>(f, s) = value;
            return true;
        case SettingKind::DVec3:
            postfx::settingValue<postfx::DVec3>(f, s) = postfx::DVec3(value);
            return true;
        case SettingKind::Uint:
            postfx::settingValue<uint32_t>(f, s) = uint32_t(value);
            return true;
        case SettingKind::UVec2:
            postfx::settingValue<postfx::UVec2>(f, s) = postfx::UVec2(uint32_t(value));
            return true;
        case SettingKind::UVec3:
            postfx::settingValue<postfx::UVec3>(f, s) = postfx::UVec3(uint32_t(value));
            return true;
        default:
            return false;
    }
}

// The end of the range nearest `bound` that a float field can hold inside it.
double insideEnd(const SettingField& f, bool upper) {
    const double bound = upper ? f.max : f.min;
    const bool open = upper ? f.maxOpen : f.minOpen;
    const bool isFloat =
        f.kind == SettingKind::Float || f.kind == SettingKind::Vec3 || f.kind == SettingKind::Color;
    if (!isFloat) return open ? std::nextafter(bound, upper ? -HUGE_VAL : HUGE_VAL) : bound;
    float v = float(bound);
    const float inward = upper ? -HUGE_VALF : HUGE_VALF;
    if ((upper && double(v) > bound) || (!upper && double(v) < bound) || (open && double(v) == bound))
        v = std::nextafter(v, inward);
    return v;
}

bool allFinite(const demo::ImageF& image, float limit) {
    for (float v : image.rgba)
        if (!std::isfinite(v) || std::abs(v) > limit) return false;
    return true;
}

class DemoSettingsExtremes : public GpuTest {};

TEST_F(DemoSettingsExtremes, EveryTableSettingRendersAtBothEndsOfItsRange) {
    ASSERT_TRUE(host);
    demo::RenderOptions o;
    o.width = 6;
    o.height = 4;
    o.shadowMapSize = 64;
    std::string error;
    auto renderer = demo::Renderer::create(*host, o, error);
    ASSERT_TRUE(renderer) << error;
    const char* largest = std::getenv("POSTFX_TEST_LARGEST_SIZES");
    const bool largestSizes = largest && std::strcmp(largest, "1") == 0;
    int rendered = 0, refused = 0;
    for (const postfx::EffectSettingsTable& e : postfx::effectSettingsTables()) {
        // The atmosphere's keys have a sweep of their own across each range, with the GPU against the
        // reference (AtmosphereStability.EveryNumberAcrossItsRange); its frames cost seconds each here.
        if (std::strcmp(e.key, "atmosphere") == 0) continue;
        demo::Scene base = baseScene();
        ASSERT_NE(sceneSettings(base, e.key), nullptr) << e.key << ": map it in sceneSettings";
        const auto table = e.table();
        for (const SettingField& f : table) {
            if (!std::isfinite(f.min) && !std::isfinite(f.max)) continue;
            for (bool upper : {false, true}) {
                const double bound = upper ? f.max : f.min;
                if (!std::isfinite(bound)) continue;
                demo::Scene scene = base;
                void* s = sceneSettings(scene, e.key);
                smallest(table, s);
                postfx::settingValue<bool>(*postfx::findSettingByMember(table, "enabled"), s) = true;
                if (f.activeIf)
                    postfx::settingValue<bool>(*postfx::findSettingByMember(table, f.activeIf), s) = true;
                if (f.usedWith)
                    postfx::settingValue<uint32_t>(*postfx::findSettingByMember(table, f.usedWith), s) =
                        f.usedWithChoices[0];
                // The largest sizes and counts cost seconds to a minute each on lavapipe: their frames run
                // with POSTFX_TEST_LARGEST_SIZES=1 (docs/stability.md); their memory is the budget's.
                const bool size = f.kind == SettingKind::Uint || f.kind == SettingKind::UVec2 ||
                                  f.kind == SettingKind::UVec3;
                if (upper && size && !largestSizes) continue;
                const double value = insideEnd(f, upper);
                if (!setValue(f, s, value)) continue;
                char label[160];
                std::snprintf(label, sizeof label, "%s.%s = %.9g", e.key, f.key ? f.key : f.member, value);
                const auto start = std::chrono::steady_clock::now();
                demo::ImageF gpu, reference;
                std::string gpuError, referenceError;
                const bool gpuOk = renderer->render(scene, gpu, gpuError);
                const bool referenceOk =
                    gpuOk && renderer->renderReference(scene, reference, referenceError, 16);
                const double seconds =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                if (!gpuOk) {
                    // Refused: only by name (a rule across fields, the memory budget).
                    const char* dot = std::strrchr(f.member, '.');  // a rule names the field's own name
                    EXPECT_NE(gpuError.find(dot ? dot + 1 : f.member), std::string::npos)
                        << label << ": " << gpuError;
                    EXPECT_EQ(gpuError.find('\n'), std::string::npos) << label << ": " << gpuError;
                    std::printf("[ extremes ] %s: refused (%.1f s): %s\n", label, seconds, gpuError.c_str());
                    ++refused;
                    continue;
                }
                ASSERT_TRUE(referenceOk) << label << ": " << referenceError;
                EXPECT_TRUE(allFinite(gpu, 65504.0f / renderer->preExposure() * 1.001f)) << label << ": GPU";
                EXPECT_TRUE(allFinite(reference, std::numeric_limits<float>::max()))
                    << label << ": reference";
                if (seconds > 2.0) std::printf("[ extremes ] %s: %.1f s\n", label, seconds);
                ++rendered;
            }
        }
    }
    std::printf("[ extremes ] %d frames rendered, %d refused by name\n", rendered, refused);
    EXPECT_GT(rendered, 100);
}

}  // namespace
}  // namespace test
