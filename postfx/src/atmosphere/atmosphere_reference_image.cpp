// Reference (a) of the atmosphere (docs/effects/atmosphere.md, "Reference"): the model the GPU renders,
// without LUTs, in double, per pixel with fine midpoint steps (integrateViewRay), the sun's transmittance
// and Ψ from fine tables (atmosphere_reference.h). Pixel rays and sky pixels as the fog references'
// (common/reference_image.h); multithreaded over rows.
#include "atmosphere/atmosphere_orders.h"
#include "atmosphere/atmosphere_reference.h"
#include "atmosphere/atmosphere_settings.h"
#include "common/parallel.h"
#include "common/reference_image.h"
#include "core/checks.h"

#include <postfx/reference.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <new>
#include <numbers>
#include <string>

namespace postfx::reference {
namespace {

using glm::dvec3;

using core::invalid;
using detail::checkCount;

constexpr uint32_t kMaxStepsPerPixel = 1u << 20;

Status validate(const AtmosphereInputs& in) {
    if (Status s = detail::checkImage("AtmosphereInputs", in.width, in.height, in.color, in.depth); !s)
        return s;
    if (Status s = validateAtmosphereSettings(in.settings); !s) return s;
    if (Status s = core::checkLighting(in.sun, Vec3(0.0f), ""); !s) return s;
    if (Status s = core::checkCamera(in.camera, "camera"); !s) return s;
    if (!core::allFinite(detail::clipToView(in.camera)))
        return invalid("camera.projection: projection · view rotation is not invertible");
    if (in.stepsPerPixel == 0 || in.stepsPerPixel > kMaxStepsPerPixel)
        return invalid("AtmosphereInputs.stepsPerPixel: " + std::to_string(in.stepsPerPixel) +
                       " is outside [1, " + std::to_string(kMaxStepsPerPixel) + "]");
    const auto n = uint32_t(std::lround(std::sqrt(double(in.psiDirections))));
    if (in.psiDirections < atmosphere::kMinDirections || in.psiDirections > 65536 ||
        n * n != in.psiDirections)
        return invalid("AtmosphereInputs.psiDirections: " + std::to_string(in.psiDirections) +
                       " is not a perfect square in [4, 65536]");
    if (in.psiSteps == 0 || in.psiSteps > 4096)
        return invalid("AtmosphereInputs.psiSteps: " + std::to_string(in.psiSteps) + " is outside [1, 4096]");
    if (in.psiTableMuS < 2 || in.psiTableMuS > 4096 || in.psiTableHeights < 2 || in.psiTableHeights > 4096)
        return invalid("AtmosphereInputs.psiTableMuS/psiTableHeights: " + std::to_string(in.psiTableMuS) +
                       "x" + std::to_string(in.psiTableHeights) + " is outside [2, 4096]²");
    return Status::success();
}

// out.rgb = color.rgb·T + L per channel, out.a = color.a (detail::composite with a coloured T): ±Inf color
// counts as ±FLT_MAX, the result is clamped to ±FLT_MAX, a NaN channel stays NaN. `occluded`: the color
// is hidden (out.rgb = L).
void composite(const dvec3& L, const dvec3& T, bool occluded, const float* color, float* out) {
    constexpr double kMax = std::numeric_limits<float>::max();
    for (int c = 0; c < 3; ++c) {
        if (occluded) {
            out[c] = float(std::min(L[c], kMax));
            continue;
        }
        if (std::isnan(color[c])) {
            out[c] = color[c];
            continue;
        }
        const double bounded = std::clamp(double(color[c]), -kMax, kMax);
        out[c] = float(std::clamp(bounded * T[c] + L[c], -kMax, kMax));
    }
    out[3] = color[3];
}

}  // namespace

Status renderAtmosphere(const AtmosphereInputs& in, std::vector<float>& out) {
    if (Status s = validate(in); !s) return s;
    std::vector<float> result;  // not `out` directly: `in.color` may view it
    try {
        result.assign(in.color.begin(), in.color.end());
    } catch (const std::bad_alloc&) {
        return {Result::OutOfMemory, "reference::renderAtmosphere: cannot allocate the output image"};
    }
    if (!in.settings.enabled) {
        out.swap(result);
        return Status::success();
    }
    const atmosphere::Model m = atmosphere::modelFrom(in.settings);
    std::shared_ptr<const atmosphere::TransmittanceTable> transmittance;
    std::shared_ptr<const atmosphere::PsiTable> psi;
    std::shared_ptr<const atmosphere::OrdersTable> orders;
    try {
        transmittance = atmosphere::sharedTransmittanceTable(m);
        if (in.settings.multipleScattering == AtmosphereMultipleScattering::Orders) {
            orders = atmosphere::sharedOrdersTable(m, atmosphere::ordersOptionsFrom(in));
        } else if (in.settings.multipleScattering == AtmosphereMultipleScattering::Hillaire) {
            atmosphere::PsiTableOptions po;
            po.muSSize = in.psiTableMuS;
            po.heightSize = in.psiTableHeights;
            po.psi.directions = in.psiDirections;
            po.psi.steps = in.psiSteps;
            po.threads = in.threads;
            psi = atmosphere::sharedPsiTable(m, po);
        }
    } catch (const std::bad_alloc&) {
        return {Result::OutOfMemory, "reference::renderAtmosphere: cannot allocate the reference's tables"};
    }

    const glm::dmat4 clipToView = detail::clipToView(in.camera);
    const double farDepth = in.depthConvention.reversedZ ? 0.0 : 1.0;
    const dvec3 origin =
        atmosphere::clampAboveGround(m, atmosphere::planetCentred(m, dvec3(in.camera.position)));
    atmosphere::Sun sun;
    sun.toSun = glm::normalize(dvec3(in.sun.toSun));
    sun.illuminance = dvec3(in.sun.illuminance);
    // The disk: radiance E/Ω with Ω = 2π(1 - cos α) = 4π·sin²(α/2), where dot(d, toSun) >= cos α.
    const double alpha = double(in.settings.sunAngularRadiusDeg) * std::numbers::pi / 180.0;
    const double cosAlpha = std::cos(alpha);
    const double solidAngle = 4.0 * std::numbers::pi * std::sin(0.5 * alpha) * std::sin(0.5 * alpha);
    const dvec3 diskRadiance = solidAngle > 0.0 ? sun.illuminance / solidAngle : dvec3(0.0);

    atmosphere::ViewRayOptions base;
    base.steps = in.stepsPerPixel;
    base.multipleScattering = in.settings.multipleScattering != AtmosphereMultipleScattering::Off;
    base.transmittanceTable = transmittance.get();
    base.psiTable = psi.get();
    base.ordersTable = orders.get();

    common::parallelFor(in.height, in.threads, [&](uint32_t j) {
        for (uint32_t i = 0; i < in.width; ++i) {
            const size_t p = size_t(j) * in.width + i;
            const detail::PixelRay ray =
                detail::pixelRay(clipToView, farDepth, in.width, in.height, i, j, in.depth[p]);
            atmosphere::ViewRayOptions o = base;
            const bool sky = std::isinf(ray.distance);
            if (sky) {
                o.ground = true;
            } else {
                o.maxDistance = ray.distance;
                o.throughGround = true;
            }
            const atmosphere::ViewRayResult res = atmosphere::integrateViewRay(m, origin, ray.d, sun, o);
            dvec3 L = res.luminance;
            bool occluded = false;
            if (sky) {
                occluded = atmosphere::atmosphereSegment(m, origin, ray.d).hitsGround;
                if (!occluded && solidAngle > 0.0 && glm::dot(ray.d, sun.toSun) >= cosAlpha)
                    L += diskRadiance * res.transmittance;
            }
            composite(L, res.transmittance, occluded, &in.color[p * 4], &result[p * 4]);
        }
    });
    out.swap(result);
    return Status::success();
}

}  // namespace postfx::reference
