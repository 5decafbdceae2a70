// Host-side API misuse (docs/integration.md, "Input ranges"): every ContextCreateInfo / FrameInfo field with
// a documented range, one table row each. A valid frame with that one field set to a value outside its range
// (below, above, NaN, ±Inf, an enum cast from another int, a null handle) is refused by Context::plan (the
// checks record() runs) with InvalidArgument naming the field in one line; the boundary values themselves
// are accepted. Then the derived quantities: inputs valid one by one that overflowed float together are
// refused naming the fields, or give a finite, bounded result on the device.
#include "core/checks.h"
#include "fog/fog_uniforms.h"
#include "fog_harness.h"

#include <postfx/settings_table.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace test {
namespace {

using postfx::FrameInfo;
using postfx::Result;

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr double kMaxCoordinate = postfx::core::kMaxWorldCoordinate;

template <class T>
T fake(uintptr_t value) {
    return reinterpret_cast<T>(value);
}

// A valid frame of fake handles (plan() makes no Vulkan call): every optional input present, so each of its
// fields is checked: a separate output, a shadow map, a spot light, fog with a host noise texture.
FrameInfo validFrame() {
    FrameInfo f;
    const VkExtent2D extent{16, 8};
    f.color = {fake<VkImage>(1), fake<VkImageView>(2),    VK_FORMAT_R16G16B16A16_SFLOAT,
               extent,           VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_USAGE_STORAGE_BIT};
    f.depth = {fake<VkImage>(3),
               fake<VkImageView>(4),
               VK_FORMAT_D32_SFLOAT,
               extent,
               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
               VK_IMAGE_USAGE_SAMPLED_BIT};
    f.output = f.color;
    f.output.image = fake<VkImage>(5);
    f.output.view = fake<VkImageView>(6);
    f.camera = testCamera({1.0, 2.0, 3.0}, 60.0f, 2.0f, 0.1f, 1000.0f, true);
    f.sun.illuminance = {1e3f, 1e3f, 1e3f};
    f.ambient = {1.0f, 1.0f, 1.0f};
    f.shadowMap.image = {fake<VkImage>(7),
                         fake<VkImageView>(8),
                         VK_FORMAT_D32_SFLOAT,
                         {32, 32},
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                         VK_IMAGE_USAGE_SAMPLED_BIT};
    f.shadowMap.worldToClip = glm::orthoRH_ZO(-50.0, 50.0, -50.0, 50.0, 0.0, 200.0);
    f.localShadows.image = {fake<VkImage>(10),
                            fake<VkImageView>(11),
                            VK_FORMAT_D16_UNORM,
                            {64, 32},
                            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                            VK_IMAGE_USAGE_SAMPLED_BIT};
    f.fog.enabled = true;
    f.fog.noise.enabled = true;
    f.fog.noise.hostTexture = fake<VkImageView>(9);
    return f;
}

// The frame's one light (FrameInfo::lights points here while a row runs).
postfx::LocalLight gLight;

// The frame's one local shadow (FrameInfo::localShadows.shadows points here while a row runs): a spot's
// face in the right half of the 64×32 atlas.
postfx::LocalShadow gShadow;

postfx::LocalShadow validShadow() {
    postfx::LocalShadow s;
    s.faces[0].offset = {32, 0};
    s.faces[0].extent = {32, 32};
    s.faces[0].worldToClip =
        glm::perspectiveRH_ZO(1.0, 1.0, 0.05, 50.0) *
        glm::lookAtRH(glm::dvec3(5.0, 1.0, -3.0), glm::dvec3(5.0, 0.0, -3.0), glm::dvec3(1, 0, 0));
    return s;
}

postfx::LocalLight validLight() {
    postfx::LocalLight l;
    l.type = postfx::LightType::Spot;
    l.position = {5.0, 1.0, -3.0};
    l.intensity = {100.0f, 100.0f, 100.0f};
    l.innerConeAngle = 0.0f;
    l.outerConeAngle = 0.5f;
    l.shadow = 0;
    return l;
}

struct Row {
    std::string field;  // the message must contain this
    std::string value;  // for the failure message
    std::function<void(FrameInfo&)> set;
};

// Rows for a number in [lo, hi]: the next representable values outside, NaN and both infinities rejected;
// lo and hi accepted. `openLo` / `openHi`: that bound is excluded (then it is rejected, and the next value
// inside is accepted).
template <class T>
void addRange(std::vector<Row>& bad, std::vector<Row>& good, const std::string& field,
              std::function<T&(FrameInfo&)> at, T lo, T hi, bool openLo = false, bool openHi = false) {
    constexpr T inf = std::numeric_limits<T>::infinity();
    auto row = [&](std::vector<Row>& rows, T v) {
        rows.push_back({field, std::to_string(v), [at, v](FrameInfo& f) { at(f) = v; }});
    };
    row(bad, std::numeric_limits<T>::quiet_NaN());
    row(bad, inf);
    row(bad, -inf);
    row(bad, openLo ? lo : std::nextafter(lo, -inf));
    row(bad, openHi ? hi : std::nextafter(hi, inf));
    row(good, openLo ? std::nextafter(lo, inf) : lo);
    row(good, openHi ? std::nextafter(hi, -inf) : hi);
}

void addBad(std::vector<Row>& bad, const std::string& field, const std::string& value,
            std::function<void(FrameInfo&)> set) {
    bad.push_back({field, value, std::move(set)});
}

// The image fields every ImageInput has (`name`: "FrameInfo.color").
void addImageRows(std::vector<Row>& bad, const std::string& name,
                  std::function<postfx::ImageInput&(FrameInfo&)> at) {
    addBad(bad, name + ".image", "null", [at](FrameInfo& f) { at(f).image = VK_NULL_HANDLE; });
    addBad(bad, name + ".view", "null", [at](FrameInfo& f) { at(f).view = VK_NULL_HANDLE; });
    addBad(bad, name + ".format", "R8G8_SNORM", [at](FrameInfo& f) { at(f).format = VK_FORMAT_R8G8_SNORM; });
    addBad(bad, name + ".format", "cast 0x7ffffffe",
           [at](FrameInfo& f) { at(f).format = VkFormat(0x7ffffffe); });
    addBad(bad, name + ".samples", "4", [at](FrameInfo& f) { at(f).samples = VK_SAMPLE_COUNT_4_BIT; });
    addBad(bad, name + ".extent", "0 wide", [at](FrameInfo& f) { at(f).extent.width = 0; });
    addBad(bad, name + ".extent", "0 high", [at](FrameInfo& f) { at(f).extent.height = 0; });
    addBad(bad, name + ".layout", "UNDEFINED",
           [at](FrameInfo& f) { at(f).layout = VK_IMAGE_LAYOUT_UNDEFINED; });
    addBad(bad, name + ".layout", "PREINITIALIZED",
           [at](FrameInfo& f) { at(f).layout = VK_IMAGE_LAYOUT_PREINITIALIZED; });
    addBad(bad, name + ".layout", "cast 12345", [at](FrameInfo& f) { at(f).layout = VkImageLayout(12345); });
    addBad(bad, name + ".usage", "0", [at](FrameInfo& f) { at(f).usage = 0; });
}

void addVec3Range(std::vector<Row>& bad, std::vector<Row>& good, const std::string& field,
                  std::function<postfx::Vec3&(FrameInfo&)> at, float lo, float hi) {
    for (int c = 0; c < 3; ++c)
        addRange<float>(
            bad, good, field, [at, c](FrameInfo& f) -> float& { return at(f)[c]; }, lo, hi);
}

using FogField = std::function<float&(FrameInfo&)>;

// FrameInfo::localShadows and the light's index into it.
void localShadowRows(std::vector<Row>& bad, std::vector<Row>& good) {
    addBad(bad, "FrameInfo.lights[0].shadow", "1 (one shadow)", [](FrameInfo&) { gLight.shadow = 1; });
    good.push_back({"FrameInfo.lights[0].shadow", "kNoLocalShadow",
                    [](FrameInfo&) { gLight.shadow = postfx::kNoLocalShadow; }});
    good.push_back({"no local shadows", "", [](FrameInfo& f) {
                        gLight.shadow = postfx::kNoLocalShadow;
                        f.localShadows = {};
                    }});
    addImageRows(bad, "FrameInfo.localShadows.image",
                 [](FrameInfo& f) -> postfx::ImageInput& { return f.localShadows.image; });
    addBad(bad, "FrameInfo.localShadows.shadows", "257 shadows",
           [](FrameInfo& f) { f.localShadows.shadowCount = postfx::kMaxLocalLights + 1; });
    addBad(bad, "FrameInfo.localShadows.shadows is null", "null with count 1",
           [](FrameInfo& f) { f.localShadows.shadows = nullptr; });
    const std::string shadow = "FrameInfo.localShadows.shadows[0]";
    addBad(bad, shadow + ".faceCount", "0", [](FrameInfo&) { gShadow.faceCount = 0; });
    addBad(bad, shadow + ".faceCount", "7", [](FrameInfo&) { gShadow.faceCount = 7; });
    addRange<float>(
        bad, good, shadow + ".depthBias", [](FrameInfo&) -> float& { return gShadow.depthBias; }, 0.0f,
        std::numeric_limits<float>::max());
    const std::string face = shadow + ".faces[0]";
    addBad(bad, face + ".extent", "0 wide", [](FrameInfo&) { gShadow.faces[0].extent.x = 0; });
    addBad(bad, face + ".extent", "0 high", [](FrameInfo&) { gShadow.faces[0].extent.y = 0; });
    addBad(bad, face + ": offset", "past the right edge", [](FrameInfo&) { gShadow.faces[0].offset.x = 33; });
    addBad(bad, face + ": offset", "past the bottom edge", [](FrameInfo&) { gShadow.faces[0].offset.y = 1; });
    addBad(bad, face + ": offset", "wrapping around 2^32",
           [](FrameInfo&) { gShadow.faces[0].offset.x = 0xffffffffu; });
    good.push_back({face + ".extent", "the whole atlas", [](FrameInfo&) {
                        gShadow.faces[0].offset = {0, 0};
                        gShadow.faces[0].extent = {64, 32};
                    }});
    addBad(bad, face + ".worldToClip", "NaN", [](FrameInfo&) { gShadow.faces[0].worldToClip[3][1] = kNan; });
    addBad(bad, face + ".worldToClip", "1e39 (not finite in float)",
           [](FrameInfo&) { gShadow.faces[0].worldToClip[0][0] = 1e39; });
    addBad(bad, face + ".worldToClip", "singular", [](FrameInfo&) { gShadow.faces[0].worldToClip[2] = {}; });
    addBad(bad, face + ".worldToClip", "zero",
           [](FrameInfo&) { gShadow.faces[0].worldToClip = glm::dmat4(0.0); });
    addBad(bad, shadow + ".faces[1].extent", "a cube's unset faces",
           [](FrameInfo&) { gShadow.faceCount = 6; });
}

void frameRows(std::vector<Row>& bad, std::vector<Row>& good) {
    addBad(bad, "FrameInfo.structSize", "+4", [](FrameInfo& f) { f.structSize += 4; });
    addImageRows(bad, "FrameInfo.color", [](FrameInfo& f) -> postfx::ImageInput& { return f.color; });
    addBad(bad, "maxExtent", "65x8", [](FrameInfo& f) { f.color.extent.width = 65; });
    addImageRows(bad, "FrameInfo.depth", [](FrameInfo& f) -> postfx::ImageInput& { return f.depth; });
    addBad(bad, "FrameInfo.depth.extent", "other than color's", [](FrameInfo& f) {
        f.depth.extent = {8, 8};
    });
    addImageRows(bad, "FrameInfo.output", [](FrameInfo& f) -> postfx::ImageInput& { return f.output; });
    // The output's null image means "composite in place": accepted.
    std::erase_if(bad, [](const Row& r) { return r.field == "FrameInfo.output.image"; });
    good.push_back({"no output", "", [](FrameInfo& f) { f.output = {}; }});
    addBad(bad, "FrameInfo.output.format", "other than color's",
           [](FrameInfo& f) { f.output.format = VK_FORMAT_R32G32B32A32_SFLOAT; });
    addBad(bad, "FrameInfo.output is FrameInfo.color", "color",
           [](FrameInfo& f) { f.output.image = f.color.image; });
    addImageRows(bad, "FrameInfo.shadowMap.image",
                 [](FrameInfo& f) -> postfx::ImageInput& { return f.shadowMap.image; });
    // The image's own null handle means "no shadow map": that row is accepted.
    std::erase_if(bad, [](const Row& r) { return r.field == "FrameInfo.shadowMap.image.image"; });
    good.push_back({"no shadow map", "", [](FrameInfo& f) { f.shadowMap.image.image = VK_NULL_HANDLE; }});

    addRange<double>(
        bad, good, "FrameInfo.timeSeconds", [](FrameInfo& f) -> double& { return f.timeSeconds; },
        -postfx::core::kMaxTimeSeconds, postfx::core::kMaxTimeSeconds);
    addRange<float>(
        bad, good, "FrameInfo.budgetMs", [](FrameInfo& f) -> float& { return f.budgetMs; }, 0.0f,
        postfx::core::kMaxBudgetMs);
    // Pre-exposure: its range, and the light it pre-exposes within the light's own ranges (the frame's
    // sun 1e3 lux, ambient 1, one light of 100 cd).
    {
        const std::string pe = "FrameInfo.preExposure";
        constexpr float kInfF = std::numeric_limits<float>::infinity();
        for (float v : {std::numeric_limits<float>::quiet_NaN(), kInfF, -kInfF, 0.0f, -1.0f,
                        std::nextafter(float(postfx::core::kMinPreExposure), 0.0f),
                        std::nextafter(float(postfx::core::kMaxPreExposure), kInfF)})
            addBad(bad, pe, std::to_string(v), [v](FrameInfo& f) { f.preExposure = v; });
        addBad(bad, pe, "2e4 × sun 1e3 lux", [](FrameInfo& f) { f.preExposure = 2e4f; });
        addBad(bad, pe, "2e4 × ambient 1e3", [](FrameInfo& f) {
            f.sun.illuminance = postfx::Vec3(0.0f);
            f.ambient = postfx::Vec3(1e3f);
            f.preExposure = 2e4f;
        });
        addBad(bad, pe, "2e7 × a light of 100 cd", [](FrameInfo& f) {
            f.sun.illuminance = postfx::Vec3(0.0f);
            f.ambient = postfx::Vec3(0.0f);
            f.preExposure = 2e7f;
        });
        good.push_back(
            {pe, "the smallest", [](FrameInfo& f) { f.preExposure = float(postfx::core::kMinPreExposure); }});
        good.push_back({pe, "1e4 × sun 1e3 lux: 1e7", [](FrameInfo& f) { f.preExposure = 1e4f; }});
        good.push_back({pe, "the largest, without light", [](FrameInfo& f) {
                            f.sun.illuminance = postfx::Vec3(0.0f);
                            f.ambient = postfx::Vec3(0.0f);
                            f.lightCount = 0;
                            f.preExposure = float(postfx::core::kMaxPreExposure);
                        }});
    }
    for (int c = 0; c < 3; ++c)
        addRange<double>(
            bad, good, "FrameInfo.camera.position",
            [c](FrameInfo& f) -> double& { return f.camera.position[c]; }, -kMaxCoordinate, kMaxCoordinate);
    addBad(bad, "FrameInfo.camera.view", "NaN", [](FrameInfo& f) { f.camera.view[1][2] = kNan; });
    addBad(bad, "FrameInfo.camera.view", "Inf", [](FrameInfo& f) { f.camera.view[0][0] = kInf; });
    addBad(bad, "FrameInfo.camera.view", "singular rotation",
           [](FrameInfo& f) { f.camera.view = glm::mat4(0.0f); });
    addBad(bad, "FrameInfo.camera.projection", "NaN", [](FrameInfo& f) { f.camera.projection[2][3] = kNan; });
    addBad(bad, "FrameInfo.camera.projection", "singular",
           [](FrameInfo& f) { f.camera.projection = glm::mat4(0.0f); });
    // Determinant 1e-9, but an inverse element of 1e39: beyond float.
    addBad(bad, "FrameInfo.camera.projection", "inverse not finite in float", [](FrameInfo& f) {
        f.camera.projection = glm::mat4(1.0f);
        f.camera.projection[0][0] = 1e-39f;
        f.camera.projection[1][1] = 1e30f;
    });

    addBad(bad, "FrameInfo.sun.toSun", "NaN", [](FrameInfo& f) { f.sun.toSun.y = kNan; });
    addBad(bad, "FrameInfo.sun.toSun", "Inf", [](FrameInfo& f) { f.sun.toSun.x = kInf; });
    addBad(bad, "FrameInfo.sun.toSun", "zero", [](FrameInfo& f) { f.sun.toSun = glm::vec3(0.0f); });
    addBad(bad, "FrameInfo.sun.toSun", "length 1e-45", [](FrameInfo& f) {
        f.sun.toSun = {0.0f, 1e-45f, 0.0f};
    });
    good.push_back({"FrameInfo.sun.toSun", "length 2e-6", [](FrameInfo& f) {
                        f.sun.toSun = {0.0f, 2e-6f, 0.0f};
                    }});
    good.push_back({"FrameInfo.sun.toSun", "length 1e30 (a float dot product overflows)", [](FrameInfo& f) {
                        f.sun.toSun = {1e30f, 1e30f, 0.0f};
                    }});
    addVec3Range(
        bad, good, "FrameInfo.sun.illuminance",
        [](FrameInfo& f) -> postfx::Vec3& { return f.sun.illuminance; }, 0.0f, 1e7f);
    addVec3Range(
        bad, good, "FrameInfo.ambient", [](FrameInfo& f) -> postfx::Vec3& { return f.ambient; }, 0.0f, 1e7f);

    addBad(bad, "FrameInfo.shadowMap.worldToClip", "NaN",
           [](FrameInfo& f) { f.shadowMap.worldToClip[3][1] = NAN; });
    addBad(bad, "FrameInfo.shadowMap.worldToClip", "1e39 (not finite in float)",
           [](FrameInfo& f) { f.shadowMap.worldToClip[0][0] = 1e39; });
    addRange<float>(
        bad, good, "FrameInfo.shadowMap.depthBias",
        [](FrameInfo& f) -> float& { return f.shadowMap.depthBias; }, 0.0f,
        std::numeric_limits<float>::max());

    addBad(bad, "FrameInfo.lightCount", "257",
           [](FrameInfo& f) { f.lightCount = postfx::kMaxLocalLights + 1; });
    addBad(bad, "FrameInfo.lights is null", "null with count 1", [](FrameInfo& f) { f.lights = nullptr; });
    const std::string light = "FrameInfo.lights[0]";
    addBad(bad, light + ".type", "cast 7", [](FrameInfo&) { gLight.type = postfx::LightType(7); });
    for (int c = 0; c < 3; ++c)
        addRange<double>(
            bad, good, light + ".position", [c](FrameInfo&) -> double& { return gLight.position[c]; },
            -kMaxCoordinate, kMaxCoordinate);
    addBad(bad, light + ".direction", "NaN", [](FrameInfo&) { gLight.direction.x = kNan; });
    addBad(bad, light + ".direction", "zero", [](FrameInfo&) { gLight.direction = glm::vec3(0.0f); });
    for (int c = 0; c < 3; ++c)
        addRange<float>(
            bad, good, light + ".intensity", [c](FrameInfo&) -> float& { return gLight.intensity[c]; }, 0.0f,
            1e9f);
    addRange<float>(
        bad, good, light + ".range", [](FrameInfo&) -> float& { return gLight.range; }, 0.0f,
        std::numeric_limits<float>::max(), true);
    // The smallest range is the light's sourceRadius (0.05), a bound of its own (below).
    std::erase_if(good, [&](const Row& r) { return r.field == light + ".range" && r.value == "0.000000"; });
    good.push_back(
        {light + ".range", "sourceRadius", [](FrameInfo&) { gLight.range = gLight.sourceRadius; }});
    // sourceRadius in (0, range] with range 100.
    addRange<float>(
        bad, good, light + ".sourceRadius", [](FrameInfo&) -> float& { return gLight.sourceRadius; }, 0.0f,
        100.0f, true);
    addRange<float>(
        bad, good, light + ".outerConeAngle", [](FrameInfo&) -> float& { return gLight.outerConeAngle; },
        0.0f, 1.5707962f);
    // In [0, outer] with outer 0.5:
    addRange<float>(
        bad, good, light + ".innerConeAngle", [](FrameInfo&) -> float& { return gLight.innerConeAngle; },
        0.0f, 0.5f);
    localShadowRows(bad, good);
}

void fogRows(std::vector<Row>& bad, std::vector<Row>& good) {
    auto fogRange = [&](const std::string& key, FogField at, float lo, float hi, bool openLo = false,
                        bool openHi = false) { addRange<float>(bad, good, key, at, lo, hi, openLo, openHi); };
    addBad(bad, "FrameInfo.fog.quality", "cast 6",
           [](FrameInfo& f) { f.fog.quality = postfx::FogQuality(6); });
    addBad(bad, "FrameInfo.fog.quality", "cast 1000",
           [](FrameInfo& f) { f.fog.quality = postfx::FogQuality(1000); });
    fogRange(
        "FrameInfo.fog.autoBudgetMs", [](FrameInfo& f) -> float& { return f.fog.autoBudgetMs; }, 0.0f,
        std::numeric_limits<float>::max(), true);
    fogRange(
        "FrameInfo.fog.density", [](FrameInfo& f) -> float& { return f.fog.density; }, 0.0f, 1e6f);
    for (int c = 0; c < 3; ++c)
        fogRange(
            "FrameInfo.fog.albedo", [c](FrameInfo& f) -> float& { return f.fog.albedo[c]; }, 0.0f, 1.0f);
    fogRange(
        "FrameInfo.fog.anisotropy", [](FrameInfo& f) -> float& { return f.fog.anisotropy; }, -0.999f, 0.999f);
    fogRange(
        "FrameInfo.fog.heightFalloff", [](FrameInfo& f) -> float& { return f.fog.heightFalloff; }, 0.0f,
        10.0f);
    addBad(bad, "FrameInfo.fog.baseHeight", "NaN", [](FrameInfo& f) { f.fog.baseHeight = kNan; });
    addBad(bad, "FrameInfo.fog.baseHeight", "Inf", [](FrameInfo& f) { f.fog.baseHeight = -kInf; });
    fogRange(
        "FrameInfo.fog.maxDistance", [](FrameInfo& f) -> float& { return f.fog.maxDistance; }, 0.0f, 1e7f,
        true);
    addBad(bad, "FrameInfo.fog.steps", "0", [](FrameInfo& f) { f.fog.steps = 0; });
    addBad(bad, "FrameInfo.fog.steps", "4097", [](FrameInfo& f) { f.fog.steps = 4097; });
    good.push_back({"FrameInfo.fog.steps", "1", [](FrameInfo& f) { f.fog.steps = 1; }});
    good.push_back({"FrameInfo.fog.steps", "4096", [](FrameInfo& f) { f.fog.steps = 4096; }});
    fogRange(
        "FrameInfo.fog.resolutionScale", [](FrameInfo& f) -> float& { return f.fog.resolutionScale; }, 0.25f,
        1.0f);
    fogRange(
        "FrameInfo.fog.transmittanceCutoff", [](FrameInfo& f) -> float& { return f.fog.transmittanceCutoff; },
        0.0f, 1.0f, false, true);
    for (uint32_t k : {0u, 2u, 8u, 9u})
        addBad(bad, "FrameInfo.fog.shadowKernel", std::to_string(k),
               [k](FrameInfo& f) { f.fog.shadowKernel = k; });
    good.push_back({"FrameInfo.fog.shadowKernel", "7", [](FrameInfo& f) { f.fog.shadowKernel = 7; }});
    for (uint32_t size : {8u, 100u, 512u})
        addBad(bad, "FrameInfo.fog.noise.textureSize", std::to_string(size), [size](FrameInfo& f) {
            f.fog.noise.hostTexture = VK_NULL_HANDLE;
            f.fog.noise.textureSize = size;
        });
    for (uint32_t size : {16u, 256u})
        good.push_back({"FrameInfo.fog.noise.textureSize", std::to_string(size), [size](FrameInfo& f) {
                            f.fog.noise.hostTexture = VK_NULL_HANDLE;
                            f.fog.noise.textureSize = size;
                        }});
    addBad(bad, "FrameInfo.fog.noise.hostTextureLayout", "UNDEFINED",
           [](FrameInfo& f) { f.fog.noise.hostTextureLayout = VK_IMAGE_LAYOUT_UNDEFINED; });
    addBad(bad, "FrameInfo.fog.noise.hostTextureLayout", "cast 12345",
           [](FrameInfo& f) { f.fog.noise.hostTextureLayout = VkImageLayout(12345); });
    good.push_back({"FrameInfo.fog.noise.hostTextureLayout", "GENERAL",
                    [](FrameInfo& f) { f.fog.noise.hostTextureLayout = VK_IMAGE_LAYOUT_GENERAL; }});
    fogRange(
        "FrameInfo.fog.noise.tiling", [](FrameInfo& f) -> float& { return f.fog.noise.tiling; }, 0.0f,
        1000.0f, true);
    fogRange(
        "FrameInfo.fog.noise.threshold", [](FrameInfo& f) -> float& { return f.fog.noise.threshold; }, 0.0f,
        1.0f);
    fogRange(
        "FrameInfo.fog.noise.multiplier", [](FrameInfo& f) -> float& { return f.fog.noise.multiplier; }, 0.0f,
        1e3f);
    for (int c = 0; c < 3; ++c)
        fogRange(
            "FrameInfo.fog.noise.wind", [c](FrameInfo& f) -> float& { return f.fog.noise.wind[c]; }, -1e3f,
            1e3f);
}

// The froxel fog's fields (FroxelFogSettings, its volumes): each row runs on the valid frame with the
// ray-marched fog off and the froxel fog on, with gVolumes as its volumes.
postfx::FogVolume gVolumes[postfx::kMaxFogVolumes + 1];

void froxelRows(std::vector<Row>& bad, std::vector<Row>& good) {
    auto froxel = [](std::function<void(FrameInfo&)> set) {
        return [set](FrameInfo& f) {
            f.fog.enabled = false;
            f.froxelFog.enabled = true;
            for (postfx::FogVolume& v : gVolumes)
                v = postfx::FogVolume{};
            f.froxelFog.volumes = gVolumes;
            f.froxelFog.volumeCount = 2;
            gVolumes[1].shape = postfx::FogVolumeShape::Sphere;
            set(f);
        };
    };
    std::vector<Row> b, g;
    auto range = [&](const std::string& key, std::function<float&(FrameInfo&)> at, float lo, float hi,
                     bool openLo = false) { addRange<float>(b, g, key, at, lo, hi, openLo); };
    range(
        "FrameInfo.froxelFog.density", [](FrameInfo& f) -> float& { return f.froxelFog.density; }, 0.0f,
        1e6f);
    range(
        "FrameInfo.froxelFog.maxDistance", [](FrameInfo& f) -> float& { return f.froxelFog.maxDistance; },
        0.0f, 1e7f, true);
    range(
        "FrameInfo.froxelFog.depthExponent", [](FrameInfo& f) -> float& { return f.froxelFog.depthExponent; },
        1.0f, 8.0f);
    for (int a = 0; a < 3; ++a) {
        const std::string key = "FrameInfo.froxelFog.grid[" + std::to_string(a) + "]";
        addBad(b, key, "0", [a](FrameInfo& f) { f.froxelFog.grid[a] = 0; });
        addBad(b, key, "513", [a](FrameInfo& f) { f.froxelFog.grid[a] = 513; });
        g.push_back({key, "1", [a](FrameInfo& f) { f.froxelFog.grid[a] = 1; }});
        g.push_back({key, "512", [a](FrameInfo& f) {
                         f.froxelFog.grid = {64, 64, 64};  // within kMaxFroxels
                         f.froxelFog.grid[a] = 512;
                     }});
    }
    addBad(b, "FrameInfo.froxelFog.grid", "512x512x33 (over kMaxFroxels)", [](FrameInfo& f) {
        f.froxelFog.grid = {512, 512, 33};
    });
    addBad(b, "FrameInfo.froxelFog.tileSizePx", "4097", [](FrameInfo& f) { f.froxelFog.tileSizePx = 4097; });
    g.push_back(
        {"FrameInfo.froxelFog.tileSizePx", "4096", [](FrameInfo& f) { f.froxelFog.tileSizePx = 4096; }});
    addBad(b, "FrameInfo.froxelFog.lightListMinLights", "0",
           [](FrameInfo& f) { f.froxelFog.lightListMinLights = 0; });
    addBad(b, "FrameInfo.froxelFog.lightListMinLights", "258",
           [](FrameInfo& f) { f.froxelFog.lightListMinLights = 258; });
    g.push_back({"FrameInfo.froxelFog.lightListMinLights", "257",
                 [](FrameInfo& f) { f.froxelFog.lightListMinLights = 257; }});
    addBad(b, "FrameInfo.froxelFog.depthDistribution", "cast 2",
           [](FrameInfo& f) { f.froxelFog.depthDistribution = postfx::FroxelDepthDistribution(2); });
    addBad(b, "FrameInfo.froxelFog.volumeCount", "65", [](FrameInfo& f) { f.froxelFog.volumeCount = 65; });
    g.push_back(
        {"FrameInfo.froxelFog.volumeCount", "64", [](FrameInfo& f) { f.froxelFog.volumeCount = 64; }});
    addBad(b, "FrameInfo.froxelFog.volumes", "null", [](FrameInfo& f) { f.froxelFog.volumes = nullptr; });
    addBad(b, "FrameInfo.froxelFog.volumes[1].shape", "cast 2",
           [](FrameInfo&) { gVolumes[1].shape = postfx::FogVolumeShape(2); });
    range(
        "FrameInfo.froxelFog.volumes[0].density", [](FrameInfo&) -> float& { return gVolumes[0].density; },
        0.0f, 1e6f);
    range(
        "FrameInfo.froxelFog.volumes[1].radius", [](FrameInfo&) -> float& { return gVolumes[1].radius; },
        0.0f, 1e7f);
    range(
        "FrameInfo.froxelFog.volumes[0].edgeFalloff",
        [](FrameInfo&) -> float& { return gVolumes[0].edgeFalloff; }, 0.0f, 1e7f);
    for (int c = 0; c < 3; ++c)
        range(
            "FrameInfo.froxelFog.volumes[0].halfSize",
            [c](FrameInfo&) -> float& { return gVolumes[0].halfSize[c]; }, 0.0f, 1e7f);
    addBad(b, "FrameInfo.froxelFog.volumes[1].center", "NaN",
           [](FrameInfo&) { gVolumes[1].center.y = kNan; });
    addBad(b, "FrameInfo.froxelFog.volumes[1].center", "-1.1e9",
           [](FrameInfo&) { gVolumes[1].center.x = -1.1e9; });
    // Both fogs in one frame: the two keys named.
    addBad(b, "FrameInfo.fog.enabled and FrameInfo.froxelFog.enabled", "both",
           [](FrameInfo& f) { f.fog.enabled = true; });
    for (Row& r : b)
        bad.push_back({r.field, r.value, froxel(r.set)});
    for (Row& r : g)
        good.push_back({r.field, r.value, froxel(r.set)});
}

// Device-memory callbacks for the create-info rows (create() allocates no device memory).
VkResult refuseDeviceMemory(void*, const VkMemoryRequirements&, VkMemoryPropertyFlags,
                            postfx::DeviceAllocation&) {
    return VK_ERROR_OUT_OF_DEVICE_MEMORY;
}
void freeNoDeviceMemory(void*, const postfx::DeviceAllocation&) {}

class CoreApiRanges : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        postfx::ContextCreateInfo info;
        info.maxExtent = {64, 64};
        ASSERT_TRUE(createContext(context, info).ok());
    }
    postfx::Status plan(const Row& row) {
        FrameInfo f = validFrame();
        gLight = validLight();
        f.lights = &gLight;
        f.lightCount = 1;
        gShadow = validShadow();
        f.localShadows.shadows = &gShadow;
        f.localShadows.shadowCount = 1;
        row.set(f);
        postfx::FramePlan plan;
        return context->plan(f, plan);
    }
    std::unique_ptr<postfx::Context> context;
};

TEST_F(CoreApiRanges, EveryFrameFieldOutsideItsRangeIsRefusedNamingIt) {
    std::vector<Row> bad, good;
    frameRows(bad, good);
    fogRows(bad, good);
    froxelRows(bad, good);
    ASSERT_GT(bad.size(), 200u);
    {
        const postfx::Status s = plan({"valid", "", [](FrameInfo&) {}});
        ASSERT_TRUE(s.ok()) << s.message;
    }
    for (const Row& row : bad) {
        const postfx::Status s = plan(row);
        EXPECT_EQ(s.code, Result::InvalidArgument) << row.field << " = " << row.value << ": " << s.message;
        EXPECT_NE(s.message.find(row.field), std::string::npos)
            << row.field << " = " << row.value << ": " << s.message;
        EXPECT_EQ(s.message.find('\n'), std::string::npos) << s.message;
    }
    for (const Row& row : good) {
        const postfx::Status s = plan(row);
        EXPECT_TRUE(s.ok()) << row.field << " = " << row.value << " (a boundary) refused: " << s.message;
    }
    // record() runs the same checks, and refuses a frame without a command buffer.
    FrameInfo f = validFrame();
    const postfx::Status s = context->record(f);
    EXPECT_EQ(s.code, Result::InvalidArgument);
    EXPECT_NE(s.message.find("FrameInfo.commandBuffer"), std::string::npos) << s.message;
}

// Every setting of every registered effect (postfx::effectSettingsTables), from its table alone, so that an
// effect added to the registry is covered without a row written here: the values just outside its range
// (and NaN, ±Inf, an enum cast from another int) are refused naming "FrameInfo.<effect>.<member>"; the
// ends themselves are accepted, the effect on, the field's switch on and its mode chosen.
struct TableRow {
    const postfx::EffectSettingsTable* effect;
    const postfx::SettingField* field;
    int component;  // of a vector field, else 0
    double value;
    std::string text;  // the value as a message shows it
};

// The nearest float at or inside [lo, hi] of `bound`: the table's bounds are doubles, the fields floats.
float insideFloat(double bound, bool up) {
    float f = float(bound);
    if (up && double(f) < bound) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    if (!up && double(f) > bound) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}

void tableRows(std::vector<TableRow>& bad, std::vector<TableRow>& good) {
    using postfx::SettingKind;
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (const postfx::EffectSettingsTable& e : postfx::effectSettingsTables())
        for (const postfx::SettingField& f : e.table()) {
            auto add = [&](std::vector<TableRow>& rows, int c, double v) {
                char text[64];
                std::snprintf(text, sizeof text, "%.9g", v);
                rows.push_back({&e, &f, c, v, text});
            };
            const int components = f.kind == SettingKind::Vec3 || f.kind == SettingKind::Color ||
                                           f.kind == SettingKind::DVec3 || f.kind == SettingKind::UVec3
                                       ? 3
                                   : f.kind == SettingKind::UVec2 ? 2
                                                                  : 1;
            for (int c = 0; c < components; ++c)
                switch (f.kind) {
                    case SettingKind::Float:
                    case SettingKind::Vec3:
                    case SettingKind::Color: {
                        add(bad, c, std::numeric_limits<double>::quiet_NaN());
                        add(bad, c, inf);
                        add(bad, c, -inf);
                        if (std::isfinite(f.min)) {
                            const float lo = insideFloat(f.min, true);
                            add(bad, c,
                                f.minOpen && double(lo) == f.min ? lo : std::nextafter(lo, -HUGE_VALF));
                            add(good, c,
                                f.minOpen && double(lo) == f.min ? std::nextafter(lo, HUGE_VALF) : lo);
                        }
                        if (std::isfinite(f.max)) {
                            const float hi = insideFloat(f.max, false);
                            add(bad, c,
                                f.maxOpen && double(hi) == f.max ? hi : std::nextafter(hi, HUGE_VALF));
                            add(good, c,
                                f.maxOpen && double(hi) == f.max ? std::nextafter(hi, -HUGE_VALF) : hi);
                        }
                        break;
                    }
                    case SettingKind::Double:
                    case SettingKind::DVec3:
                        add(bad, c, std::numeric_limits<double>::quiet_NaN());
                        if (std::isfinite(f.min)) {
                            add(bad, c, std::nextafter(f.min, -inf));
                            add(good, c, f.min);
                        }
                        if (std::isfinite(f.max)) {
                            add(bad, c, std::nextafter(f.max, inf));
                            add(good, c, f.max);
                        }
                        break;
                    case SettingKind::Uint:
                    case SettingKind::UVec2:
                    case SettingKind::UVec3:
                        if (f.min >= 1.0) add(bad, c, f.min - 1.0);
                        if (f.max < 4294967295.0) add(bad, c, f.max + 1.0);
                        add(good, c, f.min);
                        add(good, c, f.max);
                        break;
                    case SettingKind::Enum: {
                        uint32_t largest = 0;
                        for (const postfx::SettingChoice& choice : f.choices)
                            largest = std::max(largest, choice.value);
                        add(bad, c, double(largest) + 1.0);
                        for (const postfx::SettingChoice& choice : f.choices)
                            add(good, c, double(choice.value));
                        break;
                    }
                    case SettingKind::Bool:
                    case SettingKind::Opaque:
                        break;
                }
        }
}

// Every field of `table` in `s` at the table's default; host handles (Opaque) null.
void resetToDefaults(std::span<const postfx::SettingField> table, void* s) {
    using postfx::SettingKind;
    for (const postfx::SettingField& f : table) {
        const double* d = f.defaults;
        switch (f.kind) {
            case SettingKind::Bool:
                postfx::settingValue<bool>(f, s) = d[0] != 0.0;
                break;
            case SettingKind::Uint:
            case SettingKind::Enum:
                postfx::settingValue<uint32_t>(f, s) = uint32_t(d[0]);
                break;
            case SettingKind::Float:
                postfx::settingValue<float>(f, s) = float(d[0]);
                break;
            case SettingKind::Double:
                postfx::settingValue<double>(f, s) = d[0];
                break;
            case SettingKind::Vec3:
            case SettingKind::Color:
                postfx::settingValue<postfx::Vec3>(f, s) = {float(d[0]), float(d[1]), float(d[2])};
                break;
            case SettingKind::DVec3:
                postfx::settingValue<postfx::DVec3>(f, s) = {d[0], d[1], d[2]};
                break;
            case SettingKind::UVec2:
                postfx::settingValue<postfx::UVec2>(f, s) = {uint32_t(d[0]), uint32_t(d[1])};
                break;
            case SettingKind::UVec3:
                postfx::settingValue<postfx::UVec3>(f, s) = {uint32_t(d[0]), uint32_t(d[1]), uint32_t(d[2])};
                break;
            case SettingKind::Opaque:
                std::memset(f.address(s), 0, f.size);
                break;
        }
    }
}

// `row`'s value in `frame`'s settings, every other setting at its default, only its effect on, its switch
// on and its mode chosen.
void applyTableRow(const TableRow& row, FrameInfo& frame) {
    using postfx::SettingKind;
    for (const postfx::EffectSettingsTable& e : postfx::effectSettingsTables()) {
        resetToDefaults(e.table(), e.address(&frame));
        if (const postfx::SettingField* on = postfx::findSettingByMember(e.table(), "enabled"))
            postfx::settingValue<bool>(*on, e.address(&frame)) = &e == row.effect;
    }
    const auto table = row.effect->table();
    void* s = row.effect->address(&frame);
    const postfx::SettingField& f = *row.field;
    if (f.activeIf) postfx::settingValue<bool>(*postfx::findSettingByMember(table, f.activeIf), s) = true;
    if (f.usedWith)
        postfx::settingValue<uint32_t>(*postfx::findSettingByMember(table, f.usedWith), s) =
            f.usedWithChoices[0];
    const int c = row.component;
    switch (f.kind) {
        case SettingKind::Float:
            postfx::settingValue<float>(f, s) = float(row.value);
            break;
        case SettingKind::Vec3:
        case SettingKind::Color:
            postfx::settingValue<postfx::Vec3>(f, s)[c] = float(row.value);
            break;
        case SettingKind::Double:
            postfx::settingValue<double>(f, s) = row.value;
            break;
        case SettingKind::DVec3:
            postfx::settingValue<postfx::DVec3>(f, s)[c] = row.value;
            break;
        case SettingKind::Uint:
        case SettingKind::Enum:
            postfx::settingValue<uint32_t>(f, s) = uint32_t(row.value);
            break;
        case SettingKind::UVec2:
            postfx::settingValue<postfx::UVec2>(f, s)[c] = uint32_t(row.value);
            break;
        case SettingKind::UVec3:
            postfx::settingValue<postfx::UVec3>(f, s)[c] = uint32_t(row.value);
            break;
        case SettingKind::Bool:
        case SettingKind::Opaque:
            break;
    }
}

TEST_F(CoreApiRanges, EveryTableSettingJustOutsideItsRangeIsRefusedNamingIt) {
    std::vector<TableRow> bad, good;
    tableRows(bad, good);
    ASSERT_GT(bad.size(), 300u);
    auto planRow = [&](const TableRow& row) {
        return plan({"", "", [&row](FrameInfo& f) { applyTableRow(row, f); }});
    };
    for (const TableRow& row : bad) {
        const std::string name = std::string("FrameInfo.") + row.effect->member + "." + row.field->member;
        const postfx::Status s = planRow(row);
        SCOPED_TRACE(name + "[" + std::to_string(row.component) + "] = " + row.text);
        EXPECT_EQ(s.code, Result::InvalidArgument) << s.message;
        EXPECT_NE(s.message.find(name), std::string::npos) << s.message;
        EXPECT_EQ(s.message.find('\n'), std::string::npos) << s.message;
    }
    // The ends that a rule across fields refuses with the other field at its default (documented beside
    // the table, and named in the message): the atmosphere's top above its ground, the clouds' top above
    // their bottom, the octaves' contribution at most their attenuation, the froxel grid's product.
    const std::pair<std::string, std::string> crossFieldRules[] = {
        {"atmosphere.groundRadius", "greater than groundRadius"},
        {"atmosphere.topRadius", "greater than groundRadius"},
        {"clouds.bottomHeight", "greater than bottomHeight"},
        {"clouds.topHeight", "greater than bottomHeight"},
        {"clouds.multipleScattering.attenuation", "at most attenuation"},
        {"clouds.multipleScattering.contribution", "at most attenuation"},
        {"froxelFog.grid", "more than kMaxFroxels"}};
    for (const TableRow& row : good) {
        const postfx::Status s = planRow(row);
        const std::string field = std::string(row.effect->member) + "." + row.field->member;
        if (!s.ok() &&
            std::any_of(std::begin(crossFieldRules), std::end(crossFieldRules), [&](const auto& r) {
                return r.first == field && s.message.find(r.second) != std::string::npos;
            }))
            continue;
        // A vector whose components have ranges of their own (checked beside the table, the table's
        // range holding them all) refuses an end of another component's range naming the component.
        if (!s.ok() && row.field->customCheck &&
            s.message.find("FrameInfo." + field + "[" + std::to_string(row.component) + "]") !=
                std::string::npos)
            continue;
        EXPECT_TRUE(s.ok()) << "FrameInfo." << row.effect->member << "." << row.field->member << "["
                            << row.component << "] = " << row.text
                            << " (inside its range) refused: " << s.message;
    }
}

TEST_F(CoreApiRanges, EveryCreateInfoFieldOutsideItsRangeIsRefusedNamingIt) {
    static VkAllocationCallbacks callbacks{};  // only its pointers are looked at before any use
    struct CreateRow {
        const char* field;
        std::function<void(postfx::ContextCreateInfo&)> set;
    };
    const uint32_t maxDimension = [&] {
        VkPhysicalDeviceProperties p{};
        vkGetPhysicalDeviceProperties(host->physicalDevice, &p);
        return p.limits.maxImageDimension2D;
    }();
    auto allocator = [](void (*edit)(VkAllocationCallbacks&)) {
        return [edit](postfx::ContextCreateInfo& i) {
            callbacks = {};
            callbacks.pfnAllocation = [](void*, size_t, size_t, VkSystemAllocationScope) -> void* {
                return nullptr;
            };
            callbacks.pfnReallocation = [](void*, void*, size_t, size_t, VkSystemAllocationScope) -> void* {
                return nullptr;
            };
            callbacks.pfnFree = [](void*, void*) {};
            edit(callbacks);
            i.allocator = &callbacks;
        };
    };
    const CreateRow bad[] = {
        {"ContextCreateInfo.structSize", [](postfx::ContextCreateInfo& i) { i.structSize -= 4; }},
        {"ContextCreateInfo.instance", [](postfx::ContextCreateInfo& i) { i.instance = VK_NULL_HANDLE; }},
        {"ContextCreateInfo.physicalDevice",
         [](postfx::ContextCreateInfo& i) { i.physicalDevice = VK_NULL_HANDLE; }},
        {"ContextCreateInfo.device", [](postfx::ContextCreateInfo& i) { i.device = VK_NULL_HANDLE; }},
        {"ContextCreateInfo.getInstanceProcAddr",
         [](postfx::ContextCreateInfo& i) { i.getInstanceProcAddr = nullptr; }},
        {"ContextCreateInfo.getDeviceProcAddr",
         [](postfx::ContextCreateInfo& i) { i.getDeviceProcAddr = nullptr; }},
        {"ContextCreateInfo.queueFamilyIndex",
         [](postfx::ContextCreateInfo& i) { i.queueFamilyIndex = 1000; }},
        {"ContextCreateInfo.allocator->pfnAllocation",
         allocator([](VkAllocationCallbacks& a) { a.pfnAllocation = nullptr; })},
        {"ContextCreateInfo.allocator->pfnReallocation",
         allocator([](VkAllocationCallbacks& a) { a.pfnReallocation = nullptr; })},
        {"ContextCreateInfo.allocator->pfnFree",
         allocator([](VkAllocationCallbacks& a) { a.pfnFree = nullptr; })},
        {"ContextCreateInfo.allocator->pfnInternalAllocation", allocator([](VkAllocationCallbacks& a) {
             a.pfnInternalAllocation = [](void*, size_t, VkInternalAllocationType, VkSystemAllocationScope) {
             };
         })},
        {"ContextCreateInfo.deviceMemory.free",
         [](postfx::ContextCreateInfo& i) { i.deviceMemory.allocate = &refuseDeviceMemory; }},
        {"ContextCreateInfo.deviceMemory.allocate",
         [](postfx::ContextCreateInfo& i) { i.deviceMemory.free = &freeNoDeviceMemory; }},
        {"ContextCreateInfo.maxExtent",
         [](postfx::ContextCreateInfo& i) {
             i.maxExtent = {0, 16};
         }},
        {"ContextCreateInfo.maxExtent",
         [](postfx::ContextCreateInfo& i) {
             i.maxExtent = {16, 0};
         }},
        {"ContextCreateInfo.maxExtent",
         [maxDimension](postfx::ContextCreateInfo& i) {
             i.maxExtent = {maxDimension + 1, 16};
         }},
        {"ContextCreateInfo.maxExtent",
         [maxDimension](postfx::ContextCreateInfo& i) {
             i.maxExtent = {16, maxDimension + 1};
         }},
        {"ContextCreateInfo.framesInFlight", [](postfx::ContextCreateInfo& i) { i.framesInFlight = 0; }},
        {"ContextCreateInfo.framesInFlight", [](postfx::ContextCreateInfo& i) { i.framesInFlight = 9; }},
        {"ContextCreateInfo.world.up", [](postfx::ContextCreateInfo& i) { i.world.up = postfx::UpAxis(2); }},
        {"ContextCreateInfo.world.handedness",
         [](postfx::ContextCreateInfo& i) { i.world.handedness = postfx::Handedness(2); }},
        {"ContextCreateInfo.world.unitsPerMetre",
         [](postfx::ContextCreateInfo& i) { i.world.unitsPerMetre = std::nextafter(1e-3, 0.0); }},
        {"ContextCreateInfo.world.unitsPerMetre",
         [](postfx::ContextCreateInfo& i) { i.world.unitsPerMetre = std::nextafter(1e3, 2e3); }},
        {"ContextCreateInfo.world.unitsPerMetre",
         [](postfx::ContextCreateInfo& i) { i.world.unitsPerMetre = std::nan(""); }},
    };
    for (const CreateRow& row : bad) {
        postfx::ContextCreateInfo info = hostHandles();
        row.set(info);
        std::unique_ptr<postfx::Context> created;
        const postfx::Status s = postfx::Context::create(info, created);
        EXPECT_EQ(s.code, Result::InvalidArgument) << row.field << ": " << s.message;
        EXPECT_NE(s.message.find(row.field), std::string::npos) << row.field << ": " << s.message;
        EXPECT_FALSE(created);
    }
    VkPipelineCacheCreateInfo cacheInfo{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
    VkPipelineCache cache = VK_NULL_HANDLE;
    ASSERT_EQ(vkCreatePipelineCache(host->device, &cacheInfo, nullptr, &cache), VK_SUCCESS);
    const CreateRow good[] = {
        {"framesInFlight 1", [](postfx::ContextCreateInfo& i) { i.framesInFlight = 1; }},
        {"framesInFlight 8", [](postfx::ContextCreateInfo& i) { i.framesInFlight = 8; }},
        {"maxExtent 1x1",
         [](postfx::ContextCreateInfo& i) {
             i.maxExtent = {1, 1};
         }},
        {"maxExtent the device's limit",
         [maxDimension](postfx::ContextCreateInfo& i) {
             i.maxExtent = {maxDimension, maxDimension};
         }},
        {"world z up, left-handed",
         [](postfx::ContextCreateInfo& i) {
             i.world = {postfx::UpAxis::Z, postfx::Handedness::Left, 100.0};
         }},
        {"world.unitsPerMetre 1e-3", [](postfx::ContextCreateInfo& i) { i.world.unitsPerMetre = 1e-3; }},
        {"world.unitsPerMetre 1e3", [](postfx::ContextCreateInfo& i) { i.world.unitsPerMetre = 1e3; }},
        // Borrowed, any cache of the device (or none, the default).
        {"pipelineCache a host cache", [cache](postfx::ContextCreateInfo& i) { i.pipelineCache = cache; }},
        {"deviceMemory both callbacks",
         [](postfx::ContextCreateInfo& i) {
             i.deviceMemory.allocate = &refuseDeviceMemory;
             i.deviceMemory.free = &freeNoDeviceMemory;
         }},
    };
    for (const CreateRow& row : good) {
        postfx::ContextCreateInfo info = hostHandles();
        row.set(info);
        std::unique_ptr<postfx::Context> created;
        const postfx::Status s = postfx::Context::create(info, created);
        EXPECT_TRUE(s.ok()) << row.field << ": " << s.message;
    }
    vkDestroyPipelineCache(host->device, cache, nullptr);
}

// Derived quantities: fields valid one by one whose products overflowed float.
TEST_F(CoreApiRanges, JointlyOverflowingInputsAreRefusedNamingTheFields) {
    // The shadow map's camera-relative transform worldToClip · translate(camera) goes to the GPU in float:
    // an element of 1e30 with the camera 1e9 m away makes 1e39.
    postfx::Status s = plan({"", "", [](FrameInfo& f) {
                                 f.shadowMap.worldToClip = glm::dmat4(1e30);
                                 f.camera.position = {kMaxCoordinate, 0.0, 0.0};
                             }});
    EXPECT_EQ(s.code, Result::InvalidArgument);
    EXPECT_NE(s.message.find("FrameInfo.shadowMap.worldToClip"), std::string::npos) << s.message;
    EXPECT_NE(s.message.find("camera.position"), std::string::npos) << s.message;
    s = plan({"", "", [](FrameInfo& f) { f.shadowMap.worldToClip = glm::dmat4(1e30); }});
    EXPECT_TRUE(s.ok()) << "near the origin the same matrix is fine: " << s.message;
}

TEST_F(CoreApiRanges, JointlyLargeInputsGiveFiniteUniforms) {
    // A long sun vector, time, wind and tiling at their bounds, the camera far away: every uniform finite.
    FrameInfo f = validFrame();
    f.sun.toSun = {1e30f, 1e30f, 0.0f};  // a float dot product of it overflows: normalised in double
    f.timeSeconds = postfx::core::kMaxTimeSeconds;
    f.fog.noise.wind = glm::vec3(1e3f);
    f.fog.noise.tiling = 1e3f;
    f.fog.density = 1e6f;
    f.fog.noise.multiplier = 1e3f;
    f.fog.maxDistance = 1e7f;
    f.fog.heightFalloff = 1e-30f;  // the medium's top ln(bound) / 1e-30 is 5e31 m: may be +Inf, never NaN
    f.fog.baseHeight = -3e38f;
    f.camera.position = {kMaxCoordinate, kMaxCoordinate, -kMaxCoordinate};
    postfx::FramePlan p;
    ASSERT_TRUE(context->plan(f, p).ok());
    const postfx::gpu::FogUniforms u = postfx::fog::buildUniforms(f, {}, true, true);
    EXPECT_NEAR(u.toSun.x, 0.70710678f, 1e-6f);
    EXPECT_NEAR(u.toSun.y, 0.70710678f, 1e-6f);
    auto finite = [](const float* v, size_t n) {
        for (size_t i = 0; i < n; ++i)
            if (std::isnan(v[i]) || (std::isinf(v[i]))) return false;
        return true;
    };
    EXPECT_TRUE(finite(&u.clipToView[0][0], 16));
    EXPECT_TRUE(finite(&u.viewToShadow[0][0], 16));
    EXPECT_TRUE(finite(&u.toSun[0], 4));
    EXPECT_TRUE(finite(&u.noise[0], 4));
    EXPECT_TRUE(finite(&u.medium[0], 4));
    EXPECT_TRUE(std::isfinite(u.heights.x));
    EXPECT_FALSE(std::isnan(u.heights.y));
}

// density · h(y) overflows float far below the base height (h is clamped at e^80 ≈ 5.5e34): with density 1e4
// it is +Inf, and +Inf times a noise of 0 was NaN, which the composite's clamp turned into the format's
// largest value on lavapipe. The extinction is now density · noise · h: +Inf only where the noise is not 0
// (an opaque step). The fog over color 0.5 with ambient 1, albedo 1 and no sun lies in [0.5, 1] wherever it
// is.
TEST_F(CoreApiRanges, DenseFogFarBelowItsBaseStaysBounded) {
    postfx::core::Gpu gpu;
    ASSERT_TRUE(gpu.init(hostHandles()).ok());
    constexpr uint32_t kSize = 8;
    FrameInfo frame;
    frame.camera = testCamera({0.0, -20.0, 0.0}, 60.0f, 1.0f, 0.1f, 1000.0f, true);
    frame.ambient = glm::vec3(1.0f);
    postfx::FogSettings& fog = frame.fog;
    fog.enabled = true;
    fog.density = 1e4f;
    fog.albedo = glm::vec3(1.0f);
    fog.heightFalloff = 10.0f;  // 20 m below the base: exponent 200, clamped to 80
    fog.maxDistance = 50.0f;
    fog.steps = 4;
    fog.analyticTail = false;
    fog.noise.enabled = true;
    fog.noise.textureSize = 16;
    fog.noise.threshold = 0.5f;  // about half the texels give noise 0
    FogHarnessImages images;
    images.width = images.height = kSize;
    images.color.assign(kSize * kSize * 4, 0.5f);
    images.depth.assign(kSize * kSize, 0.0f);  // no geometry (reversed Z)
    for (float scale : {1.0f, 0.5f}) {
        fog.resolutionScale = scale;
        FogHarness harness(*host, gpu);
        std::vector<float> color;
        const postfx::Status s = harness.run(*context, images, frame, color);
        ASSERT_TRUE(s.ok()) << s.message;
        for (size_t i = 0; i < color.size(); ++i) {
            if (i % 4 == 3) continue;  // alpha
            ASSERT_TRUE(color[i] >= 0.5f - 1e-3f && color[i] <= 1.0f + 1e-3f)
                << "scale " << scale << ", value " << i << ": " << color[i];
        }
        frame.frameIndex++;
    }
}

}  // namespace
}  // namespace test
