#include "atmosphere/atmosphere_settings.h"

#include "core/checks.h"

#include <cmath>
#include <string>

namespace postfx::atmosphere {
namespace {

using core::checkRange;

constexpr const char* kPrefix = "atmosphere.";

std::string key(const char* name) {
    return std::string(kPrefix) + name;
}

Status bad(const char* name, const std::string& why) {
    return core::invalid(key(name) + ": " + why);
}

// v in [lo, hi], finite.
Status range(const char* name, double v, double lo, double hi) {
    return checkRange(key(name).c_str(), v, lo, hi);
}

// v in (0, hi], finite.
Status positive(const char* name, double v, double hi) {
    if (Status r = range(name, v, 0.0, hi); !r) return r;
    if (v <= 0.0) return bad(name, "must be > 0");
    return Status::success();
}

Status rgb(const char* name, const Vec3& v, double lo, double hi) {
    for (int c = 0; c < 3; ++c)
        if (Status r = range(name, v[c], lo, hi); !r) return r;
    return Status::success();
}

Status count(const char* name, uint32_t v, uint32_t lo, uint32_t hi) {
    if (v < lo || v > hi)
        return bad(
            name, std::to_string(v) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return Status::success();
}

template <class V>
Status size(const char* name, const V& v, uint32_t hi) {
    for (glm::length_t i = 0; i < V::length(); ++i)
        if (Status r = count(name, v[i], kMinLutSide, hi); !r) return r;
    return Status::success();
}

bool perfectSquare(uint32_t v) {
    const auto s = uint32_t(std::lround(std::sqrt(double(v))));
    return s * s == v;
}

}  // namespace

Status validateSettings(const AtmosphereSettings& s) {
    if (Status r = range("ground_radius", s.groundRadius, kMinGroundRadius, kMaxRadius); !r) return r;
    if (Status r = range("top_radius", s.topRadius, 0.0, kMaxRadius); !r) return r;
    if (!(s.topRadius > s.groundRadius))
        return bad("top_radius", core::numberText(s.topRadius) + " must be greater than ground_radius (" +
                                     core::numberText(s.groundRadius) + ")");
    if (Status r = rgb("rayleigh_scattering", s.rayleighScattering, 0.0, kMaxCoefficient); !r) return r;
    if (Status r = positive("rayleigh_scale_height", s.rayleighScaleHeight, kMaxHeight); !r) return r;
    if (Status r = range("mie_scattering", s.mieScattering, 0.0, kMaxCoefficient); !r) return r;
    if (Status r = range("mie_absorption", s.mieAbsorption, 0.0, kMaxCoefficient); !r) return r;
    if (Status r = positive("mie_scale_height", s.mieScaleHeight, kMaxHeight); !r) return r;
    if (std::isnan(s.mieAnisotropy)) return bad("mie_anisotropy", "is NaN");
    if (!(std::abs(s.mieAnisotropy) < 1.0f))
        return bad("mie_anisotropy", core::numberText(s.mieAnisotropy) + " is outside (-1, 1)");
    if (Status r = rgb("ozone_absorption", s.ozoneAbsorption, 0.0, kMaxCoefficient); !r) return r;
    if (Status r = range("ozone_center_height", s.ozoneCenterHeight, 0.0, kMaxHeight); !r) return r;
    if (Status r = positive("ozone_half_width", s.ozoneHalfWidth, kMaxHeight); !r) return r;
    if (Status r = rgb("ground_albedo", s.groundAlbedo, 0.0, 1.0); !r) return r;
    if (Status r = range("sun_angular_radius_deg", s.sunAngularRadiusDeg, 0.0, kMaxSunAngularRadiusDeg); !r)
        return r;

    if (Status r = size("transmittance_lut_size", s.transmittanceLutSize, kMaxLut2dSide); !r) return r;
    if (Status r = count("transmittance_steps", s.transmittanceSteps, 1, kMaxSteps); !r) return r;
    if (Status r =
            size("multiple_scattering_lut_size", s.multipleScatteringLutSize, kMaxMultipleScatteringSide);
        !r)
        return r;
    if (Status r = count("multiple_scattering_directions", s.multipleScatteringDirections, kMinDirections,
                         kMaxDirections);
        !r)
        return r;
    if (!perfectSquare(s.multipleScatteringDirections))
        return bad("multiple_scattering_directions", std::to_string(s.multipleScatteringDirections) +
                                                         " is not a perfect square (n×n directions)");
    if (Status r = count("multiple_scattering_steps", s.multipleScatteringSteps, 1, kMaxSteps); !r) return r;
    if (uint32_t(s.multipleScattering) > uint32_t(AtmosphereMultipleScattering::Orders))
        return bad("multiple_scattering",
                   std::to_string(uint32_t(s.multipleScattering)) + " is not off, hillaire or orders");
    const UVec3 orders = s.scatteringOrdersLutSize;
    if (Status r = count("scattering_orders_lut_size", orders.x, kMinLutSide, kMaxOrdersViewSide); !r)
        return r;
    if (Status r = count("scattering_orders_lut_size", orders.y, kMinLutSide, kMaxOrdersSunSide); !r)
        return r;
    if (Status r = count("scattering_orders_lut_size", orders.z, kMinLutSide, kMaxOrdersHeightSide); !r)
        return r;
    if (Status r = count("scattering_orders_azimuth_size", s.scatteringOrdersAzimuthSize, kMinOrdersAzimuths,
                         kMaxOrdersAzimuths);
        !r)
        return r;
    if (Status r = count("scattering_orders_directions", s.scatteringOrdersDirections, kMinDirections,
                         kMaxOrdersDirections);
        !r)
        return r;
    if (!perfectSquare(s.scatteringOrdersDirections))
        return bad("scattering_orders_directions", std::to_string(s.scatteringOrdersDirections) +
                                                       " is not a perfect square (n×n directions)");
    if (Status r = count("scattering_orders_steps", s.scatteringOrdersSteps, 1, kMaxSteps); !r) return r;
    if (Status r = count("scattering_orders", s.scatteringOrders, 1, kMaxScatteringOrders); !r) return r;
    if (Status r = size("sky_view_lut_size", s.skyViewLutSize, kMaxLut2dSide); !r) return r;
    if (Status r = count("sky_view_steps", s.skyViewSteps, 1, kMaxSteps); !r) return r;
    if (Status r = size("aerial_perspective_lut_size", s.aerialPerspectiveLutSize, kMaxAerialPerspectiveSide);
        !r)
        return r;
    if (Status r = positive("aerial_perspective_distance", s.aerialPerspectiveDistance, kMaxHeight); !r)
        return r;
    if (Status r = count("aerial_perspective_steps_per_slice", s.aerialPerspectiveStepsPerSlice, 1,
                         kMaxStepsPerSlice);
        !r)
        return r;
    return Status::success();
}

}  // namespace postfx::atmosphere

namespace postfx {
Status validateAtmosphereSettings(const AtmosphereSettings& settings) {
    return atmosphere::validateSettings(settings);
}
}  // namespace postfx
