#include "clouds_bench.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace bench {
namespace {

bool parseUint(const std::string& text, uint32_t& out) {
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && ptr == end;
}

bool parseFloat(const std::string& text, float& out) {
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && ptr == end && std::isfinite(out);
}

std::string floatText(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(v));
    return buf;
}

struct PresetName {
    const char* name;
    postfx::CloudQuality quality;
};
constexpr PresetName kPresets[] = {{"low", postfx::CloudQuality::Low},
                                   {"medium", postfx::CloudQuality::Medium},
                                   {"high", postfx::CloudQuality::High},
                                   {"ultra", postfx::CloudQuality::Ultra}};

}  // namespace

std::vector<CloudsView> cloudsViews() {
    return {{"ground_noon", 100.0, 20.0, 60.0, 30.0},
            {"ground_sunset", 100.0, 20.0, 5.0, 0.0},
            {"above", 6000.0, -10.0, 60.0, 30.0}};
}

postfx::CameraInput cloudsCamera(const CloudsView& view, uint32_t width, uint32_t height, double yawOffset) {
    postfx::CameraInput camera;
    const glm::dvec3 position(0.0, view.altitude, 0.0);
    camera.position = position;
    const double pitch = glm::radians(view.pitchDeg), yaw = yawOffset;
    const glm::dvec3 forward(std::cos(pitch) * std::cos(yaw), std::sin(pitch),
                             std::cos(pitch) * std::sin(yaw));
    // Only the rotation is used: the view about the origin.
    camera.view = glm::mat4(glm::lookAt(glm::dvec3(0.0), forward, glm::dvec3(0.0, 1.0, 0.0)));
    const float f = 1.0f / std::tan(glm::radians(kCloudsFovYDeg) / 2.0f);
    const float aspect = float(width) / float(height);
    glm::mat4 p(0.0f);  // right-handed view (looking down -z) to Vulkan clip (y down), reversed Z
    p[0][0] = f / aspect;
    p[1][1] = -f;
    p[2][3] = -1.0f;
    p[2][2] = kCloudsNear / (kCloudsFar - kCloudsNear);
    p[3][2] = kCloudsFar * kCloudsNear / (kCloudsFar - kCloudsNear);
    camera.projection = p;
    return camera;
}

postfx::Vec3 cloudsToSun(const CloudsView& view) {
    const double e = glm::radians(view.sunElevationDeg), a = glm::radians(view.sunAzimuthDeg);
    return postfx::Vec3(glm::dvec3(std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)));
}

const std::vector<std::string>& cloudsKnobs() {
    static const std::vector<std::string> knobs = {
        "model",    "steps",        "light_steps", "resolution_scale", "base_size", "detail_size",
        "temporal", "update_block", "preset"};
    return knobs;
}

CloudsSweepOptions defaultCloudsSweep(bool quick) {
    CloudsSweepOptions o;
    if (quick) {
        o.values = {{"model", {"octaves"}},
                    {"steps", {"16"}},
                    {"resolution_scale", {"1"}},
                    {"base_size", {"32"}},
                    {"preset", {"low"}}};
        return o;
    }
    o.values = {{"model", {"slab", "octaves"}},
                {"steps", {"16", "32", "64", "96", "128", "192"}},
                {"light_steps", {"2", "4", "6", "12", "16", "32"}},
                {"resolution_scale", {"1", "0.5", "0.25"}},
                {"base_size", {"32", "64", "128", "256"}},
                {"detail_size", {"16", "32", "64"}},
                {"temporal", {"off"}},
                {"update_block", {"1", "4"}},
                {"preset", {"low", "medium", "high", "ultra"}}};
    return o;
}

postfx::CloudSettings cloudsBaseSettings() {
    postfx::CloudSettings s =
        postfx::applyCloudQuality(postfx::CloudSettings{}, postfx::CloudQuality::Medium);
    s.enabled = true;
    return s;
}

bool applyCloudsKnob(postfx::CloudSettings& s, const std::string& knob, const std::string& value,
                     std::string& error) {
    uint32_t n = 0;
    float f = 0.0f;
    bool ok = false;
    const char* expected = "an integer";
    if (knob == "steps" || knob == "light_steps" || knob == "base_size" || knob == "detail_size" ||
        knob == "update_block") {
        ok = parseUint(value, n);
        if (ok) {
            uint32_t& field = knob == "steps"          ? s.steps
                              : knob == "light_steps"  ? s.lightSteps
                              : knob == "base_size"    ? s.noise.baseSize
                              : knob == "update_block" ? s.updateBlock
                                                       : s.noise.detailSize;
            field = n;
        }
    } else if (knob == "model") {
        // octaves: Wrenninge's octaves at their defaults (2 octaves, 0.5/0.5/0.5), the model postfx had.
        expected = "slab or octaves";
        ok = value == "slab" || value == "octaves";
        if (ok)
            s.multipleScattering.model = value == "octaves" ? postfx::CloudScatteringModel::Octaves
                                                            : postfx::CloudScatteringModel::Slab;
    } else if (knob == "resolution_scale") {
        expected = "a number";
        ok = parseFloat(value, f);
        if (ok) s.resolutionScale = f;
    } else if (knob == "temporal") {
        expected = "on or off";
        ok = value == "on" || value == "off";
        if (ok) s.temporal.enabled = value == "on";
    } else if (knob == "preset") {
        expected = "low, medium, high or ultra";
        for (const PresetName& p : kPresets)
            if (value == p.name) {
                s = postfx::applyCloudQuality(s, p.quality);
                ok = true;
            }
    } else {
        error = "unknown knob '" + knob + "'";
        return false;
    }
    if (!ok) {
        error = knob + " '" + value + "': expected " + expected;
        return false;
    }
    return true;
}

std::string cloudsKnobValue(const postfx::CloudSettings& s, const std::string& knob) {
    if (knob == "model")
        return s.multipleScattering.model == postfx::CloudScatteringModel::Octaves ? "octaves" : "slab";
    if (knob == "steps") return std::to_string(s.steps);
    if (knob == "light_steps") return std::to_string(s.lightSteps);
    if (knob == "resolution_scale") return floatText(s.resolutionScale);
    if (knob == "base_size") return std::to_string(s.noise.baseSize);
    if (knob == "detail_size") return std::to_string(s.noise.detailSize);
    if (knob == "temporal") return s.temporal.enabled ? "on" : "off";
    if (knob == "update_block") return std::to_string(s.updateBlock);
    return "";
}

bool cloudsSweep(const CloudsSweepOptions& options, std::vector<CloudsPoint>& out, std::string& error) {
    out.clear();
    for (const auto& [name, values] : options.values)
        if (std::find(cloudsKnobs().begin(), cloudsKnobs().end(), name) == cloudsKnobs().end()) {
            error = "unknown knob '" + name + "'";
            return false;
        }
    CloudsPoint base;
    base.knob = "default";
    base.settings = cloudsBaseSettings();
    out.push_back(base);
    for (const std::string& knob : cloudsKnobs()) {
        for (const auto& [name, values] : options.values) {
            if (name != knob) continue;
            for (const std::string& value : values) {
                CloudsPoint p = base;
                p.knob = knob;
                if (!applyCloudsKnob(p.settings, knob, value, error)) return false;
                p.value = knob == "preset" ? value : cloudsKnobValue(p.settings, knob);
                if (knob != "preset" && p.value == cloudsKnobValue(base.settings, knob)) continue;
                if (const postfx::Status s = postfx::validateCloudSettings(p.settings); !s.ok()) {
                    error = knob + " " + value + ": " + s.message;
                    return false;
                }
                out.push_back(p);
            }
        }
    }
    return true;
}

bool isCloudsPass(const std::string& name) {
    return name.rfind("clouds.", 0) == 0;
}

}  // namespace bench
