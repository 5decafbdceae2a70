#include "atmosphere_bench.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace bench {
namespace {

bool parseUint(const std::string& text, uint32_t& out) {
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && ptr == end;
}

bool parseSize2(const std::string& text, postfx::UVec2& out) {
    const size_t x = text.find('x');
    return x != std::string::npos && parseUint(text.substr(0, x), out.x) &&
           parseUint(text.substr(x + 1), out.y);
}

std::string size2(const postfx::UVec2& s) {
    return std::to_string(s.x) + "x" + std::to_string(s.y);
}

}  // namespace

std::vector<AtmosphereView> atmosphereViews() {
    std::vector<AtmosphereView> views(4);
    views[0] = {"ground_sun30", 300.0, 5.0, 30.0, 30.0, 30000.0};
    views[1] = {"ground_sunset", 300.0, 5.0, 5.0, 0.0, 30000.0};
    // 105 km up, just above the top (the sky-view LUT's sky half between the inside span Z and αt - β),
    // the horizon about 10° below: the camera pitched down to it.
    views[2] = {"space_sun30", 105000.0, -10.0, 30.0, 40.0, 0.0};
    // 400 km up (an orbit), the horizon about 20° below: the sky-view LUT's sky half spans αt - β.
    views[3] = {"orbit_sun30", 400000.0, -20.0, 30.0, 40.0, 0.0};
    return views;
}

postfx::CameraInput atmosphereCamera(const AtmosphereView& view, uint32_t width, uint32_t height,
                                     double yawOffset) {
    postfx::CameraInput camera;
    const glm::dvec3 position(0.0, view.altitude, 0.0);
    camera.position = position;
    const double pitch = glm::radians(view.pitchDeg), yaw = yawOffset;
    const glm::dvec3 forward(std::cos(pitch) * std::cos(yaw), std::sin(pitch),
                             std::cos(pitch) * std::sin(yaw));
    // Only the rotation is used: the view about the origin.
    camera.view = glm::mat4(glm::lookAt(glm::dvec3(0.0), forward, glm::dvec3(0.0, 1.0, 0.0)));
    const float f = 1.0f / std::tan(glm::radians(kAtmosphereFovYDeg) / 2.0f);
    const float aspect = float(width) / float(height);
    glm::mat4 p(0.0f);  // right-handed view (looking down -z) to Vulkan clip (y down), reversed Z
    p[0][0] = f / aspect;
    p[1][1] = -f;
    p[2][3] = -1.0f;
    p[2][2] = kAtmosphereNear / (kAtmosphereFar - kAtmosphereNear);
    p[3][2] = kAtmosphereFar * kAtmosphereNear / (kAtmosphereFar - kAtmosphereNear);
    camera.projection = p;
    return camera;
}

postfx::Vec3 atmosphereToSun(const AtmosphereView& view, double elevationOffset) {
    const double e = glm::radians(view.sunElevationDeg) + elevationOffset,
                 a = glm::radians(view.sunAzimuthDeg);
    return postfx::Vec3(glm::dvec3(std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)));
}

postfx::DVec3 atmospherePixelDirection(const postfx::CameraInput& camera, double i, double j, uint32_t width,
                                       uint32_t height) {
    glm::dmat4 rotation(camera.view);
    rotation[3] = glm::dvec4(0, 0, 0, 1);
    const glm::dmat4 clipToView = glm::inverse(glm::dmat4(camera.projection) * rotation);
    const glm::dvec4 p =
        clipToView * glm::dvec4((i + 0.5) / width * 2.0 - 1.0, (j + 0.5) / height * 2.0 - 1.0, 0.5, 1.0);
    return glm::normalize(glm::dvec3(p) / p.w);
}

void atmosphereImages(const AtmosphereView& view, const postfx::CameraInput& camera, uint32_t width,
                      uint32_t height, std::vector<float>& depth, std::vector<float>& color) {
    depth.assign(size_t(width) * height, 0.0f);
    color.assign(size_t(width) * height * 4, 0.0f);
    glm::dmat4 rotation(camera.view);
    rotation[3] = glm::dvec4(0, 0, 0, 1);
    const glm::dmat4 viewToClip = glm::dmat4(camera.projection) * rotation;
    for (uint32_t j = 0; j < height; ++j) {
        for (uint32_t i = 0; i < width; ++i) {
            const size_t k = size_t(j) * width + i;
            color[k * 4 + 3] = 1.0f;
            if (view.terrainDistance <= 0.0) continue;
            const glm::dvec3 d = atmospherePixelDirection(camera, i, j, width, height);
            if (d.y >= 0.0) continue;
            const double t = view.altitude / -d.y;  // the plane y = 0
            if (t > view.terrainDistance) continue;
            const glm::dvec4 clip = viewToClip * glm::dvec4(d * t, 1.0);
            depth[k] = float(clip.z / clip.w);
            for (int c = 0; c < 3; ++c)
                color[k * 4 + c] = kTerrainRadiance;
        }
    }
}

const char* situationName(AtmosphereSituation situation) {
    switch (situation) {
        case AtmosphereSituation::Still:
            return "still";
        case AtmosphereSituation::Camera:
            return "camera";
        case AtmosphereSituation::Sun:
            return "sun";
        case AtmosphereSituation::Media:
            return "media";
    }
    return "?";
}

const std::vector<std::string>& atmosphereKnobs() {
    static const std::vector<std::string> knobs = {"transmittance_size",
                                                   "transmittance_steps",
                                                   "multiple_scattering",
                                                   "orders_size",
                                                   "orders_azimuths",
                                                   "orders_directions",
                                                   "orders_steps",
                                                   "orders",
                                                   "ms_size",
                                                   "ms_directions",
                                                   "ms_steps",
                                                   "sky_view_size",
                                                   "sky_view_steps",
                                                   "ap_size",
                                                   "ap_steps_per_slice"};
    return knobs;
}

AtmosphereSweepOptions defaultAtmosphereSweep(bool quick) {
    AtmosphereSweepOptions o;
    if (quick) {
        o.values = {{"transmittance_size", {"64x16"}},     {"transmittance_steps", {"10"}},
                    {"multiple_scattering", {"hillaire"}}, {"ms_directions", {"16"}},
                    {"sky_view_size", {"96x54"}},          {"ap_size", {"16"}}};
        return o;
    }
    o.values = {{"transmittance_size", {"64x16", "128x32", "256x64", "512x128"}},
                {"transmittance_steps", {"10", "20", "40", "80"}},
                {"multiple_scattering", {"off", "hillaire", "orders"}},
                {"orders_size", {"16", "32", "64"}},
                {"orders_azimuths", {"4", "8", "16"}},
                {"orders_directions", {"144", "256", "576"}},
                {"orders_steps", {"16", "32", "64"}},
                {"orders", {"4", "8", "16"}},
                {"ms_size", {"16", "32", "64"}},
                {"ms_directions", {"16", "64", "256"}},
                {"ms_steps", {"10", "20", "40"}},
                {"sky_view_size", {"96x54", "192x108", "384x216"}},
                {"sky_view_steps", {"10", "30", "60"}},
                {"ap_size", {"16", "32", "64"}},
                {"ap_steps_per_slice", {"1", "2", "4"}}};
    return o;
}

bool applyAtmosphereKnob(postfx::AtmosphereSettings& s, const std::string& knob, const std::string& value,
                         std::string& error) {
    uint32_t n = 0;
    postfx::UVec2 size(0);
    bool ok = false;
    if (knob == "transmittance_size") {
        ok = parseSize2(value, size);
        if (ok) s.transmittanceLutSize = size;
    } else if (knob == "sky_view_size") {
        ok = parseSize2(value, size);
        if (ok) s.skyViewLutSize = size;
    } else if (knob == "multiple_scattering") {
        using M = postfx::AtmosphereMultipleScattering;
        ok = value == "off" || value == "hillaire" || value == "orders";
        if (ok)
            s.multipleScattering = value == "off" ? M::Off : value == "hillaire" ? M::Hillaire : M::Orders;
    } else if (knob == "orders_size") {
        ok = parseUint(value, n);
        if (ok) s.scatteringOrdersLutSize = postfx::UVec3(n, n, n / 2);
    } else if (knob == "orders" || knob == "orders_azimuths" || knob == "orders_directions" ||
               knob == "orders_steps") {
        ok = parseUint(value, n);
        if (ok) {
            uint32_t& field = knob == "orders"              ? s.scatteringOrders
                              : knob == "orders_azimuths"   ? s.scatteringOrdersAzimuthSize
                              : knob == "orders_directions" ? s.scatteringOrdersDirections
                                                            : s.scatteringOrdersSteps;
            field = n;
        }
    } else if (knob == "ms_size") {  // the ms_* knobs set Hillaire's model, whose LUT they size
        ok = parseUint(value, n);
        if (ok) s.multipleScatteringLutSize = postfx::UVec2(n);
        s.multipleScattering = postfx::AtmosphereMultipleScattering::Hillaire;
    } else if (knob == "ap_size") {
        ok = parseUint(value, n);
        if (ok) s.aerialPerspectiveLutSize = postfx::UVec3(n);
    } else if (knob == "transmittance_steps" || knob == "ms_directions" || knob == "ms_steps" ||
               knob == "sky_view_steps" || knob == "ap_steps_per_slice") {
        ok = parseUint(value, n);
        if (ok) {
            if (knob == "ms_directions" || knob == "ms_steps")
                s.multipleScattering = postfx::AtmosphereMultipleScattering::Hillaire;
            uint32_t& field = knob == "transmittance_steps" ? s.transmittanceSteps
                              : knob == "ms_directions"     ? s.multipleScatteringDirections
                              : knob == "ms_steps"          ? s.multipleScatteringSteps
                              : knob == "sky_view_steps"    ? s.skyViewSteps
                                                            : s.aerialPerspectiveStepsPerSlice;
            field = n;
        }
    } else {
        error = "unknown knob '" + knob + "'";
        return false;
    }
    if (!ok) {
        const bool two = knob == "transmittance_size" || knob == "sky_view_size";
        error = knob + " '" + value + "': expected " + (two ? "WxH" : "an integer");
        return false;
    }
    return true;
}

std::string atmosphereKnobValue(const postfx::AtmosphereSettings& s, const std::string& knob) {
    if (knob == "transmittance_size") return size2(s.transmittanceLutSize);
    if (knob == "sky_view_size") return size2(s.skyViewLutSize);
    if (knob == "multiple_scattering") {
        using M = postfx::AtmosphereMultipleScattering;
        return s.multipleScattering == M::Off        ? "off"
               : s.multipleScattering == M::Hillaire ? "hillaire"
                                                     : "orders";
    }
    if (knob == "orders_size") return std::to_string(s.scatteringOrdersLutSize.x);
    if (knob == "orders") return std::to_string(s.scatteringOrders);
    if (knob == "orders_azimuths") return std::to_string(s.scatteringOrdersAzimuthSize);
    if (knob == "orders_directions") return std::to_string(s.scatteringOrdersDirections);
    if (knob == "orders_steps") return std::to_string(s.scatteringOrdersSteps);
    if (knob == "ms_size") return std::to_string(s.multipleScatteringLutSize.x);
    if (knob == "ap_size") return std::to_string(s.aerialPerspectiveLutSize.x);
    if (knob == "transmittance_steps") return std::to_string(s.transmittanceSteps);
    if (knob == "ms_directions") return std::to_string(s.multipleScatteringDirections);
    if (knob == "ms_steps") return std::to_string(s.multipleScatteringSteps);
    if (knob == "sky_view_steps") return std::to_string(s.skyViewSteps);
    if (knob == "ap_steps_per_slice") return std::to_string(s.aerialPerspectiveStepsPerSlice);
    return "";
}

bool atmosphereSweep(const AtmosphereSweepOptions& options, std::vector<AtmospherePoint>& out,
                     std::string& error) {
    out.clear();
    AtmospherePoint base;
    base.knob = "default";
    base.settings = options.base;
    base.settings.enabled = true;
    out.push_back(base);
    for (const std::string& knob : atmosphereKnobs()) {
        for (const auto& [name, values] : options.values) {
            if (name != knob) continue;
            for (const std::string& value : values) {
                AtmospherePoint p = base;
                p.knob = knob;
                if (!applyAtmosphereKnob(p.settings, knob, value, error)) return false;
                p.value = atmosphereKnobValue(p.settings, knob);
                if (p.value == atmosphereKnobValue(base.settings, knob)) continue;  // the default row
                if (const postfx::Status s = postfx::validateAtmosphereSettings(p.settings); !s.ok()) {
                    error = knob + " " + value + ": " + s.message;
                    return false;
                }
                out.push_back(p);
            }
        }
    }
    for (const auto& [name, values] : options.values)
        if (std::find(atmosphereKnobs().begin(), atmosphereKnobs().end(), name) == atmosphereKnobs().end()) {
            error = "unknown knob '" + name + "'";
            return false;
        }
    return true;
}

}  // namespace bench
