// Scene files: `effects.atmosphere` <-> postfx::AtmosphereSettings. Keep
// docs/scene-format.md#effectsatmosphere in sync.
#include "scene/atmosphere_json.h"

#include "scene/json_read.h"
#include "scene/medium_json.h"

namespace demo {
namespace {

using namespace json_read;

constexpr const char* kAtmosphereKeys[] = {"enabled",
                                           "ground_radius",
                                           "top_radius",
                                           "rayleigh_scattering",
                                           "rayleigh_scale_height",
                                           "mie_scattering",
                                           "mie_absorption",
                                           "mie_scale_height",
                                           "mie_anisotropy",
                                           "ozone_absorption",
                                           "ozone_center_height",
                                           "ozone_half_width",
                                           "ground_albedo",
                                           "multiple_scattering",
                                           "sun_angular_radius_deg",
                                           "ambient_from_sky",
                                           "transmittance_lut_size",
                                           "transmittance_steps",
                                           "multiple_scattering_lut_size",
                                           "multiple_scattering_directions",
                                           "multiple_scattering_steps",
                                           "scattering_orders_lut_size",
                                           "scattering_orders_azimuth_size",
                                           "scattering_orders_directions",
                                           "scattering_orders_steps",
                                           "scattering_orders",
                                           "sky_view_lut_size",
                                           "sky_view_steps",
                                           "aerial_perspective_lut_size",
                                           "aerial_perspective_distance",
                                           "aerial_perspective_steps_per_slice"};

json rgb(const postfx::Vec3& v) {
    return vec3(glm::vec3(v));
}

// "off", "hillaire" or "orders"; true and false (older scene files) read as "orders" and "off".
postfx::AtmosphereMultipleScattering readModel(const json& j, const std::string& path) {
    using M = postfx::AtmosphereMultipleScattering;
    if (j == "off" || j == false) return M::Off;
    if (j == "hillaire") return M::Hillaire;
    if (j == "orders" || j == true) return M::Orders;
    fail(path, "expected \"off\", \"hillaire\" or \"orders\"" + got(j));
}

const char* modelName(postfx::AtmosphereMultipleScattering m) {
    using M = postfx::AtmosphereMultipleScattering;
    return m == M::Off ? "off" : m == M::Hillaire ? "hillaire" : "orders";
}

}  // namespace

postfx::AtmosphereSettings readAtmosphere(const json& j, const std::string& path) {
    expectObject(j, path);
    checkKeys(j, path, kAtmosphereKeys);
    postfx::AtmosphereSettings s;
    s.enabled = true;  // the object's presence turns the atmosphere on unless it says otherwise
    readOptional(j, path, "enabled", s.enabled);
    readOptional(j, path, "ground_radius", s.groundRadius);
    readOptional(j, path, "top_radius", s.topRadius);
    readOptional(j, path, "rayleigh_scattering", s.rayleighScattering);
    readOptional(j, path, "rayleigh_scale_height", s.rayleighScaleHeight);
    readOptional(j, path, "mie_scattering", s.mieScattering);
    readOptional(j, path, "mie_absorption", s.mieAbsorption);
    readOptional(j, path, "mie_scale_height", s.mieScaleHeight);
    readOptional(j, path, "mie_anisotropy", s.mieAnisotropy);
    readOptional(j, path, "ozone_absorption", s.ozoneAbsorption);
    readOptional(j, path, "ozone_center_height", s.ozoneCenterHeight);
    readOptional(j, path, "ozone_half_width", s.ozoneHalfWidth);
    readOptional(j, path, "ground_albedo", s.groundAlbedo);
    if (const json* v = find(j, "multiple_scattering"))
        s.multipleScattering = readModel(*v, child(path, "multiple_scattering"));
    readOptional(j, path, "sun_angular_radius_deg", s.sunAngularRadiusDeg);
    readOptional(j, path, "ambient_from_sky", s.ambientFromSky);
    readOptional(j, path, "transmittance_lut_size", s.transmittanceLutSize);
    readOptional(j, path, "transmittance_steps", s.transmittanceSteps);
    readOptional(j, path, "multiple_scattering_lut_size", s.multipleScatteringLutSize);
    readOptional(j, path, "multiple_scattering_directions", s.multipleScatteringDirections);
    readOptional(j, path, "multiple_scattering_steps", s.multipleScatteringSteps);
    readOptional(j, path, "scattering_orders_lut_size", s.scatteringOrdersLutSize);
    readOptional(j, path, "scattering_orders_azimuth_size", s.scatteringOrdersAzimuthSize);
    readOptional(j, path, "scattering_orders_directions", s.scatteringOrdersDirections);
    readOptional(j, path, "scattering_orders_steps", s.scatteringOrdersSteps);
    readOptional(j, path, "scattering_orders", s.scatteringOrders);
    readOptional(j, path, "sky_view_lut_size", s.skyViewLutSize);
    readOptional(j, path, "sky_view_steps", s.skyViewSteps);
    readOptional(j, path, "aerial_perspective_lut_size", s.aerialPerspectiveLutSize);
    readOptional(j, path, "aerial_perspective_distance", s.aerialPerspectiveDistance);
    readOptional(j, path, "aerial_perspective_steps_per_slice", s.aerialPerspectiveStepsPerSlice);
    // Ranges: postfx's own check (whether or not enabled), which names the field "atmosphere.<key>"; it
    // becomes "effects.atmosphere.<key>".
    medium_json::throwIfInvalid(postfx::validateAtmosphereSettings(s), "atmosphere", path);
    return s;
}

json atmosphereToJson(const postfx::AtmosphereSettings& s) {
    return json{
        {"enabled", s.enabled},
        {"ground_radius", number(s.groundRadius)},
        {"top_radius", number(s.topRadius)},
        {"rayleigh_scattering", rgb(s.rayleighScattering)},
        {"rayleigh_scale_height", number(s.rayleighScaleHeight)},
        {"mie_scattering", number(s.mieScattering)},
        {"mie_absorption", number(s.mieAbsorption)},
        {"mie_scale_height", number(s.mieScaleHeight)},
        {"mie_anisotropy", number(s.mieAnisotropy)},
        {"ozone_absorption", rgb(s.ozoneAbsorption)},
        {"ozone_center_height", number(s.ozoneCenterHeight)},
        {"ozone_half_width", number(s.ozoneHalfWidth)},
        {"ground_albedo", rgb(s.groundAlbedo)},
        {"multiple_scattering", modelName(s.multipleScattering)},
        {"sun_angular_radius_deg", number(s.sunAngularRadiusDeg)},
        {"ambient_from_sky", s.ambientFromSky},
        {"transmittance_lut_size", {s.transmittanceLutSize.x, s.transmittanceLutSize.y}},
        {"transmittance_steps", s.transmittanceSteps},
        {"multiple_scattering_lut_size", {s.multipleScatteringLutSize.x, s.multipleScatteringLutSize.y}},
        {"multiple_scattering_directions", s.multipleScatteringDirections},
        {"multiple_scattering_steps", s.multipleScatteringSteps},
        {"scattering_orders_lut_size",
         {s.scatteringOrdersLutSize.x, s.scatteringOrdersLutSize.y, s.scatteringOrdersLutSize.z}},
        {"scattering_orders_azimuth_size", s.scatteringOrdersAzimuthSize},
        {"scattering_orders_directions", s.scatteringOrdersDirections},
        {"scattering_orders_steps", s.scatteringOrdersSteps},
        {"scattering_orders", s.scatteringOrders},
        {"sky_view_lut_size", {s.skyViewLutSize.x, s.skyViewLutSize.y}},
        {"sky_view_steps", s.skyViewSteps},
        {"aerial_perspective_lut_size",
         {s.aerialPerspectiveLutSize.x, s.aerialPerspectiveLutSize.y, s.aerialPerspectiveLutSize.z}},
        {"aerial_perspective_distance", number(s.aerialPerspectiveDistance)},
        {"aerial_perspective_steps_per_slice", s.aerialPerspectiveStepsPerSlice}};
}

}  // namespace demo
