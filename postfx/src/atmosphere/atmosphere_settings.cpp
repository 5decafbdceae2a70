#include "atmosphere/atmosphere_settings.h"

#include "core/checks.h"
#include "core/settings_check.h"

#include <postfx/settings_table.h>

#include <cmath>
#include <string>

namespace postfx::atmosphere {
namespace {

constexpr const char* kPrefix = "FrameInfo.atmosphere";

Status bad(const char* member, const std::string& why) {
    return core::invalid(std::string(kPrefix) + "." + member + ": " + why);
}

bool perfectSquare(uint32_t v) {
    const auto s = uint32_t(std::lround(std::sqrt(double(v))));
    return s * s == v;
}

}  // namespace

Status validateSettings(const AtmosphereSettings& s) {
    if (Status r = core::checkSettings(atmosphereSettingsTable(), &s, kPrefix); !r) return r;
    // The rules beside the table's ranges.
    if (!(s.topRadius > s.groundRadius))
        return bad("topRadius", core::numberText(s.topRadius) + " must be greater than groundRadius (" +
                                    core::numberText(s.groundRadius) + ")");
    if (!perfectSquare(s.multipleScatteringDirections))
        return bad("multipleScatteringDirections", std::to_string(s.multipleScatteringDirections) +
                                                       " is not a perfect square (n×n directions)");
    const uint32_t ordersMax[3] = {kMaxOrdersViewSide, kMaxOrdersSunSide, kMaxOrdersHeightSide};
    for (int a = 0; a < 3; ++a) {
        const uint32_t v = s.scatteringOrdersLutSize[a];
        if (v < kMinLutSide || v > ordersMax[a])
            return core::invalid(std::string(kPrefix) + ".scatteringOrdersLutSize[" + std::to_string(a) +
                                 "]: " + std::to_string(v) + " is outside [" + std::to_string(kMinLutSide) +
                                 ", " + std::to_string(ordersMax[a]) + "]");
    }
    if (!perfectSquare(s.scatteringOrdersDirections))
        return bad("scatteringOrdersDirections", std::to_string(s.scatteringOrdersDirections) +
                                                     " is not a perfect square (n×n directions)");
    if (s.multipleScattering == AtmosphereMultipleScattering::Orders &&
        scatteringOrdersWork(s) > kMaxOrdersWork) {
        const UVec3& n = s.scatteringOrdersLutSize;
        return bad("scatteringOrders",
                   std::to_string(s.scatteringOrders) + " orders with scatteringOrdersLutSize (" +
                       std::to_string(n.x) + ", " + std::to_string(n.y) + ", " + std::to_string(n.z) +
                       "), scatteringOrdersAzimuthSize " + std::to_string(s.scatteringOrdersAzimuthSize) +
                       ", scatteringOrdersDirections " + std::to_string(s.scatteringOrdersDirections) +
                       " and scatteringOrdersSteps " + std::to_string(s.scatteringOrdersSteps) + " take " +
                       core::numberText(scatteringOrdersWork(s)) + " samples, more than " +
                       core::numberText(kMaxOrdersWork) + " (28 times the defaults'): lower one of them");
    }
    return Status::success();
}

double scatteringOrdersWork(const AtmosphereSettings& s) {
    const UVec3& n = s.scatteringOrdersLutSize;
    return double(s.scatteringOrders) * n.y * (2.0 * n.z + 1.0) * s.scatteringOrdersDirections *
           (double(s.scatteringOrdersSteps) + double(n.x) * s.scatteringOrdersAzimuthSize);
}

}  // namespace postfx::atmosphere

namespace postfx {
Status validateAtmosphereSettings(const AtmosphereSettings& settings) {
    return atmosphere::validateSettings(settings);
}
}  // namespace postfx
