// The atmosphere model's equations in double precision (docs/effects/atmosphere.md, "Model" and
// "Parameterisations").
#include "atmosphere/atmosphere_model.h"

#include "atmosphere/atmosphere_shared.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace postfx::atmosphere {
namespace {

constexpr double kPi = std::numbers::pi;

glm::dvec3 toDouble(const Vec3& v) {
    return {double(v.x), double(v.y), double(v.z)};
}

double clamp01(double x) {
    return std::clamp(x, 0.0, 1.0);
}

double safeSqrt(double x) {
    return std::sqrt(std::max(0.0, x));
}

}  // namespace

Model modelFrom(const AtmosphereSettings& s) {
    Model m;
    m.groundRadius = s.groundRadius;
    m.topRadius = s.topRadius;
    m.rayleighScattering = toDouble(s.rayleighScattering);
    m.rayleighScaleHeight = s.rayleighScaleHeight;
    m.mieScattering = s.mieScattering;
    m.mieAbsorption = s.mieAbsorption;
    m.mieScaleHeight = s.mieScaleHeight;
    m.mieAnisotropy = s.mieAnisotropy;
    m.ozoneAbsorption = toDouble(s.ozoneAbsorption);
    m.ozoneCenterHeight = s.ozoneCenterHeight;
    m.ozoneHalfWidth = s.ozoneHalfWidth;
    m.groundAlbedo = toDouble(s.groundAlbedo);
    return m;
}

Densities densitiesAt(const Model& m, double altitude) {
    const double h = std::max(0.0, altitude);
    Densities d;
    d.rayleigh = std::exp(-h / m.rayleighScaleHeight);
    d.mie = std::exp(-h / m.mieScaleHeight);
    d.ozone = std::max(0.0, 1.0 - std::abs(h - m.ozoneCenterHeight) / m.ozoneHalfWidth);
    return d;
}

Medium mediumAt(const Model& m, double altitude) {
    const Densities d = densitiesAt(m, altitude);
    Medium md;
    md.rayleighScattering = m.rayleighScattering * d.rayleigh;
    md.mieScattering = m.mieScattering * d.mie;
    md.scattering = md.rayleighScattering + md.mieScattering;
    md.extinction = md.scattering + m.mieAbsorption * d.mie + m.ozoneAbsorption * d.ozone;
    return md;
}

AtmosphereSegment atmosphereSegment(const Model& m, const glm::dvec3& o, const glm::dvec3& d) {
    AtmosphereSegment seg;
    const SphereHit top = raySphere(o, d, m.topRadius);
    if (!top.hit || top.tFar <= 0.0) return seg;  // misses the atmosphere, or it is behind
    seg.tBegin = std::max(0.0, top.tNear);
    seg.tEnd = top.tFar;
    const SphereHit ground = raySphere(o, d, m.groundRadius);
    // The ground ends the segment where the ray enters it ahead (a tangent ray grazes it: not blocked).
    if (ground.hit && ground.tNear < ground.tFar && ground.tNear >= 0.0 && ground.tNear < seg.tEnd) {
        seg.tEnd = ground.tNear;
        seg.hitsGround = true;
    }
    return seg;
}

bool rayIntersectsGround(const Model& m, double r, double mu) {
    if (r <= m.groundRadius) return mu < 0.0;
    return mu < 0.0 && r * r * (mu * mu - 1.0) + m.groundRadius * m.groundRadius >= 0.0;
}

double distanceToTop(const Model& m, double r, double mu) {
    const double disc = r * r * (mu * mu - 1.0) + m.topRadius * m.topRadius;
    return std::max(0.0, -r * mu + safeSqrt(disc));
}

double rayleighPhase(double c) {
    return 3.0 / (16.0 * kPi) * (1.0 + c * c);
}

double cornetteShanksPhase(double c, double g) {
    const double g2 = g * g;
    const double denom = 1.0 + g2 - 2.0 * g * c;
    return 3.0 / (8.0 * kPi) * (1.0 - g2) * (1.0 + c * c) / ((2.0 + g2) * denom * std::sqrt(denom));
}

double unitToTexelUv(double x, uint32_t n) {
    return 0.5 / n + x * (1.0 - 1.0 / n);
}

double texelUvToUnit(double u, uint32_t n) {
    return (u - 0.5 / n) / (1.0 - 1.0 / n);
}

// Bruneton 2017, GetTransmittanceTextureUvFromRMu, without the texel-centre step.
glm::dvec2 transmittanceUnitFromParams(const Model& m, double r, double mu) {
    const double g = m.groundRadius, t = m.topRadius;
    r = std::clamp(r, g, t);
    const double H = safeSqrt(t * t - g * g);
    const double rho = safeSqrt(r * r - g * g);
    const double d = distanceToTop(m, r, mu);
    const double dMin = t - r, dMax = rho + H;
    return {(d - dMin) / (dMax - dMin), rho / H};
}

RadiusCosine transmittanceParamsFromUnit(const Model& m, const glm::dvec2& unit) {
    const double g = m.groundRadius, t = m.topRadius;
    const double H = safeSqrt(t * t - g * g);
    const double rho = H * unit.y;
    RadiusCosine p;
    p.r = std::sqrt(rho * rho + g * g);
    const double dMin = t - p.r, dMax = rho + H;
    const double d = dMin + unit.x * (dMax - dMin);
    // Law of cosines in the triangle (centre, point, exit point): top² = r² + d² + 2rdμ.
    p.mu = d == 0.0 ? 1.0 : std::clamp((H * H - rho * rho - d * d) / (2.0 * p.r * d), -1.0, 1.0);
    return p;
}

glm::dvec2 transmittanceUvFromParams(const Model& m, double r, double mu, const glm::uvec2& size) {
    const glm::dvec2 x = transmittanceUnitFromParams(m, r, mu);
    return {unitToTexelUv(x.x, size.x), unitToTexelUv(x.y, size.y)};
}

RadiusCosine transmittanceParamsFromUv(const Model& m, const glm::dvec2& uv, const glm::uvec2& size) {
    return transmittanceParamsFromUnit(m, {texelUvToUnit(uv.x, size.x), texelUvToUnit(uv.y, size.y)});
}

glm::dvec2 multipleScatteringUvFromParams(const Model& m, double muS, double r, const glm::uvec2& size) {
    const double x = clamp01(0.5 * muS + 0.5);
    const double y = clamp01((r - m.groundRadius) / (m.topRadius - m.groundRadius));
    return {unitToTexelUv(x, size.x), unitToTexelUv(y, size.y)};
}

SunCosineRadius multipleScatteringParamsFromUv(const Model& m, const glm::dvec2& uv, const glm::uvec2& size) {
    const double x = clamp01(texelUvToUnit(uv.x, size.x)), y = clamp01(texelUvToUnit(uv.y, size.y));
    return {2.0 * x - 1.0, m.groundRadius + y * (m.topRadius - m.groundRadius)};
}

double skyViewHorizonBeta(const Model& m, double r) {
    r = std::max(r, m.groundRadius);
    return std::acos(std::clamp(safeSqrt(r * r - m.groundRadius * m.groundRadius) / r, -1.0, 1.0));
}

double skyViewSpaceWeight(const Model& m, double r) {
    const double fraction = (r - m.groundRadius) / (m.topRadius - m.groundRadius);
    return std::clamp((fraction - 1.0) / (gpu::kAtmosphereSpaceViewMinAltitude - 1.0), 0.0, 1.0);
}

double skyViewSkySpan(const Model& m, double r) {
    r = std::max(r, m.groundRadius);
    const double beta = skyViewHorizonBeta(m, r), zenithHorizon = kPi - beta;
    const double w = skyViewSpaceWeight(m, r);
    if (w <= 0.0) return zenithHorizon;
    const double alphaTop = std::asin(std::min(1.0, m.topRadius / r));
    return (1.0 - w) * zenithHorizon + w * (alphaTop - beta);
}

glm::dvec2 skyViewUnitFromParams(const Model& m, double r, const SkyViewParams& p) {
    const double beta = skyViewHorizonBeta(m, r), span = skyViewSkySpan(m, r);
    const double zenithHorizon = kPi - beta;
    const double theta = std::acos(std::clamp(p.cosViewZenith, -1.0, 1.0));
    double v;
    if (theta < zenithHorizon) {
        v = 0.5 * (1.0 - std::sqrt(clamp01((zenithHorizon - theta) / span)));
    } else {
        v = 0.5 + 0.5 * std::sqrt(clamp01((theta - zenithHorizon) / beta));
    }
    const double u = std::sqrt(clamp01(0.5 - 0.5 * p.cosAzimuth));
    return {u, v};
}

SkyViewParams skyViewParamsFromUnit(const Model& m, double r, const glm::dvec2& unit) {
    const double beta = skyViewHorizonBeta(m, r), span = skyViewSkySpan(m, r);
    const double zenithHorizon = kPi - beta;
    SkyViewParams p;
    if (unit.y < 0.5) {
        const double c = 1.0 - 2.0 * unit.y;  // √((Z - θ)/D)
        p.cosViewZenith = std::cos(zenithHorizon - span * c * c);
    } else {
        const double c = 2.0 * unit.y - 1.0;  // √((θ - Z)/β)
        p.cosViewZenith = std::cos(zenithHorizon + beta * c * c);
    }
    p.cosAzimuth = 1.0 - 2.0 * unit.x * unit.x;
    return p;
}

glm::dvec2 skyViewUvFromParams(const Model& m, double r, const SkyViewParams& p, const glm::uvec2& size) {
    const glm::dvec2 x = skyViewUnitFromParams(m, r, p);
    return {unitToTexelUv(x.x, size.x), unitToTexelUv(x.y, size.y)};
}

SkyViewParams skyViewParamsFromUv(const Model& m, double r, const glm::dvec2& uv, const glm::uvec2& size) {
    return skyViewParamsFromUnit(m, r, {texelUvToUnit(uv.x, size.x), texelUvToUnit(uv.y, size.y)});
}

}  // namespace postfx::atmosphere
