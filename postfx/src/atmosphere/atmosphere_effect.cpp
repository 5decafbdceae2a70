#include "atmosphere/atmosphere_effect.h"

#include "atmosphere/atmosphere_model.h"
#include "atmosphere/atmosphere_settings.h"
#include "common/air.h"
#include "common/shared_resources.h"
#include "core/camera_math.h"
#include "core/exposure.h"
#include "core/lookup_volume.h"
#include "core/temporal.h"
#include "postfx_objects_spirv.h"

#include "atmosphere/atmosphere_shared.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace postfx::atmosphere {
namespace {

using core::SamplerKind;
using core::Use;

constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
constexpr VkDescriptorType kSampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;

// Each kernel's descriptor layout: exactly the bindings it reads or writes (atmosphere_shared.h).
constexpr core::Binding kUniformBuffer{gpu::kAtmosphereBindingUniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};
constexpr core::Binding kTransmittanceOut{gpu::kAtmosphereBindingTransmittance, kStorage};
constexpr core::Binding kTransmittanceIn{gpu::kAtmosphereBindingTransmittance, kSampled};
constexpr core::Binding kMultiScatteringOut{gpu::kAtmosphereBindingMultiScattering, kStorage};
constexpr core::Binding kMultiScatteringIn{gpu::kAtmosphereBindingMultiScattering, kSampled};
constexpr core::Binding kSkyViewOut{gpu::kAtmosphereBindingSkyView, kStorage};
constexpr core::Binding kSkyViewIn{gpu::kAtmosphereBindingSkyView, kSampled};
constexpr core::Binding kApScatteringOut{gpu::kAtmosphereBindingApScattering, kStorage};
constexpr core::Binding kApScatteringIn{gpu::kAtmosphereBindingApScattering, kSampled};
constexpr core::Binding kApTransmittanceOut{gpu::kAtmosphereBindingApTransmittance, kStorage};
constexpr core::Binding kApTransmittanceIn{gpu::kAtmosphereBindingApTransmittance, kSampled};
constexpr core::Binding kColorIn{gpu::kAtmosphereBindingColorIn, kStorage};
constexpr core::Binding kColorOut{gpu::kAtmosphereBindingColorOut, kStorage};
constexpr core::Binding kDepth{gpu::kAtmosphereBindingDepth, kSampled};
constexpr core::Binding kOrdersIn{gpu::kAtmosphereBindingOrdersIn, kSampled};
constexpr core::Binding kOrdersOut{gpu::kAtmosphereBindingOrdersOut, kStorage};

constexpr core::Binding kTransmittanceBindings[] = {kUniformBuffer, kTransmittanceOut};
constexpr core::Binding kMultiScatteringBindings[] = {kUniformBuffer, kTransmittanceIn, kMultiScatteringOut};
constexpr core::Binding kOrdersBindings[] = {kUniformBuffer, kTransmittanceIn, kMultiScatteringOut, kOrdersIn,
                                             kOrdersOut};
constexpr core::Binding kSkyViewBindings[] = {kUniformBuffer, kTransmittanceIn, kMultiScatteringIn,
                                              kSkyViewOut};
constexpr core::Binding kApBindings[] = {kUniformBuffer, kTransmittanceIn, kMultiScatteringIn,
                                         kApScatteringOut, kApTransmittanceOut};
constexpr core::Binding kApplyBindings[] = {kUniformBuffer, kTransmittanceIn, kMultiScatteringIn,
                                            kSkyViewIn,     kApScatteringIn,  kApTransmittanceIn,
                                            kColorIn,       kColorOut,        kDepth};
constexpr core::Binding kLookupBindings[] = {kUniformBuffer,
                                             kTransmittanceIn,
                                             kMultiScatteringIn,
                                             kApScatteringIn,
                                             kApTransmittanceIn,
                                             core::kLookupUniformsBinding,
                                             core::kLookupScatteringBinding,
                                             core::kLookupTransmittanceBinding};

const core::ComputePipelineDesc kTransmittancePass{
    "atmosphere.transmittance", spirv::atmosphere_transmittance_comp, kTransmittanceBindings};
const core::ComputePipelineDesc kMultiScatteringPass{
    "atmosphere.multiple_scattering", spirv::atmosphere_multiple_scattering_comp, kMultiScatteringBindings};
const core::ComputePipelineDesc kOrdersPass{"atmosphere.scattering_orders",
                                            spirv::atmosphere_scattering_orders_comp, kOrdersBindings,
                                            sizeof(gpu::AtmosphereOrderConstants)};
const core::ComputePipelineDesc kSkyViewPass{"atmosphere.sky_view", spirv::atmosphere_sky_view_comp,
                                             kSkyViewBindings};
const core::ComputePipelineDesc kApPass{"atmosphere.aerial_perspective",
                                        spirv::atmosphere_aerial_perspective_comp, kApBindings};
// [rgba32]: the color format.
// The volumetrics lookup's part (core/lookup_volume.h).
const core::ComputePipelineDesc kLookupPass{"atmosphere.lookup", spirv::atmosphere_lookup_comp,
                                            kLookupBindings, core::kLookupPushBytes};
const core::ComputePipelineDesc kApplyPass[2] = {
    {"atmosphere.apply", spirv::atmosphere_apply_comp, kApplyBindings},
    {"atmosphere.apply", spirv::atmosphere_apply_comp_COLOR_RGBA32F, kApplyBindings}};

uint32_t groupsFor(uint32_t size, uint32_t groupSize = gpu::kAtmosphereGroupSize) {
    return (size + groupSize - 1) / groupSize;
}

// The keys of what each LUT is built from (core/frame_graph.h, persistentImage): every setting it reads.
// Transmittance: the extinction (radii, coefficients, heights), its size and steps.
uint64_t transmittanceKey(const AtmosphereSettings& s) {
    using core::hashValue;
    uint64_t h = hashValue(0x61746d6fu, s.groundRadius);
    h = hashValue(h, s.topRadius);
    for (int c = 0; c < 3; ++c) {
        h = hashValue(h, s.rayleighScattering[c]);
        h = hashValue(h, s.ozoneAbsorption[c]);
    }
    h = hashValue(h, s.rayleighScaleHeight);
    h = hashValue(h, s.mieScattering);
    h = hashValue(h, s.mieAbsorption);
    h = hashValue(h, s.mieScaleHeight);
    h = hashValue(h, s.ozoneCenterHeight);
    h = hashValue(h, s.ozoneHalfWidth);
    h = hashValue(h, s.transmittanceLutSize.x);
    h = hashValue(h, s.transmittanceLutSize.y);
    return hashValue(h, s.transmittanceSteps);
}
// Multiple scattering: the transmittance's, the ground's albedo and the model; Hillaire's: its size,
// directions and steps (its phase is isotropic: not g); the orders': Mie's g, its sizes, directions, steps
// and orders.
uint64_t multipleScatteringKey(const AtmosphereSettings& s) {
    using core::hashValue;
    uint64_t h = hashValue(transmittanceKey(s), uint32_t(s.multipleScattering));
    for (int c = 0; c < 3; ++c)
        h = hashValue(h, s.groundAlbedo[c]);
    if (s.multipleScattering == AtmosphereMultipleScattering::Hillaire) {
        h = hashValue(h, s.multipleScatteringLutSize.x);
        h = hashValue(h, s.multipleScatteringLutSize.y);
        h = hashValue(h, s.multipleScatteringDirections);
        h = hashValue(h, s.multipleScatteringSteps);
    } else if (s.multipleScattering == AtmosphereMultipleScattering::Orders) {
        h = hashValue(h, s.mieAnisotropy);
        for (int a = 0; a < 3; ++a)
            h = hashValue(h, s.scatteringOrdersLutSize[a]);
        h = hashValue(h, s.scatteringOrdersAzimuthSize);
        h = hashValue(h, s.scatteringOrdersDirections);
        h = hashValue(h, s.scatteringOrdersSteps);
        h = hashValue(h, s.scatteringOrders);
    }
    return h;
}
// Sky view and aerial perspective: the multiple scattering's, Mie's g, their sizes and steps.
uint64_t skyViewSettingsKey(const AtmosphereSettings& s) {
    using core::hashValue;
    uint64_t h = hashValue(multipleScatteringKey(s), s.mieAnisotropy);
    h = hashValue(h, s.skyViewLutSize.x);
    h = hashValue(h, s.skyViewLutSize.y);
    return hashValue(h, s.skyViewSteps);
}
uint64_t aerialSettingsKey(const AtmosphereSettings& s) {
    using core::hashValue;
    uint64_t h = hashValue(multipleScatteringKey(s), s.mieAnisotropy);
    for (int a = 0; a < 3; ++a)
        h = hashValue(h, s.aerialPerspectiveLutSize[a]);
    h = hashValue(h, s.aerialPerspectiveDistance);
    return hashValue(h, s.aerialPerspectiveStepsPerSlice);
}
uint64_t viewKey(const LutView& v) {
    uint64_t h = core::hashValue(v.settingsKey, v.camera);
    h = core::hashValue(h, v.toSun);
    return core::hashValue(h, v.viewToClip);
}

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    // atan2(|a×b|, a·b): accurate for small angles, where acos of the dot product is not.
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// The largest angle between the view rays of two cameras through the image's corners and centre.
double frustumAngle(const glm::dmat4& viewToClipA, const glm::dmat4& viewToClipB) {
    const glm::dmat4 a = glm::inverse(viewToClipA), b = glm::inverse(viewToClipB);
    double largest = 0.0;
    for (const glm::dvec2 ndc :
         {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(-1, 1), glm::dvec2(1, 1), glm::dvec2(0, 0)}) {
        const glm::dvec4 pa = a * glm::dvec4(ndc, 0.5, 1.0), pb = b * glm::dvec4(ndc, 0.5, 1.0);
        largest = std::max(largest, angleBetween(glm::dvec3(pa) / pa.w, glm::dvec3(pb) / pb.w));
    }
    return largest;
}

double sunZenithAngle(const LutView& v) {
    return angleBetween(v.camera, v.toSun);
}

gpu::AtmosphereUniforms buildUniforms(const FrameInfo& frame, const DepthConvention& depth,
                                      const AtmosphereEffect::Views& v, const glm::dvec3& camera) {
    const AtmosphereSettings& s = frame.atmosphere;
    gpu::AtmosphereUniforms u{};
    const glm::dmat4 viewToClip = glm::dmat4(frame.camera.projection) * core::rotationOnly(frame.camera.view);
    u.clipToView = glm::mat4(glm::inverse(viewToClip));
    u.apViewToClip = glm::mat4(v.aerial.viewToClip);
    u.apClipToView = glm::mat4(glm::inverse(v.aerial.viewToClip));
    const double g = s.groundRadius, t = s.topRadius;
    // The sky-view LUT's radius (clamped onto the ground).
    const double skyRadius = std::max(glm::length(v.skyView.camera), g);
    u.radii = glm::vec4(float(g), float(t), float((t - g) * (t + g)), float(ordersStorageScale(s)));
    // A scale height below 1/FLT_MAX m (a denormal float) would give an infinite 1/H, and 0·Inf = NaN at
    // the ground: FLT_MAX instead (the density falls to 0 within 1e-38 m either way). A denormal half width
    // may be flushed to 0 on the device (0/0 at the tent's peak): the smallest normal float instead.
    const auto reciprocal = [](double h) { return float(std::min(1.0 / h, double(FLT_MAX))); };
    u.rayleigh = glm::vec4(s.rayleighScattering, reciprocal(s.rayleighScaleHeight));
    u.mie = glm::vec4(s.mieScattering, s.mieAbsorption, reciprocal(s.mieScaleHeight), s.mieAnisotropy);
    u.ozone = glm::vec4(s.ozoneAbsorption, s.ozoneCenterHeight);
    u.albedo = glm::vec4(s.groundAlbedo, std::max(s.ozoneHalfWidth, FLT_MIN));
    u.camera = glm::vec4(glm::vec3(camera), float(glm::length(camera)));
    u.apCamera = glm::vec4(glm::vec3(v.aerial.camera), s.aerialPerspectiveDistance);
    u.apOffset =
        glm::vec4(glm::vec3(camera - v.aerial.camera), glm::length(v.aerial.camera) >= t ? 1.0f : 0.0f);
    const glm::dvec3 toSun = glm::normalize(glm::dvec3(frame.sun.toSun));
    // The disk: cos α, and 1 / its solid angle 2π(1 - cos α) = 4π sin²(α/2) (no cancellation); none for α =
    // 0.
    const double alpha = glm::radians(double(s.sunAngularRadiusDeg));
    const double halfSin = std::sin(0.5 * alpha);
    u.toSun = glm::vec4(glm::vec3(toSun), alpha > 0.0 ? float(std::cos(alpha)) : 2.0f);
    u.sun = glm::vec4(core::preExposed(frame.sun.illuminance, frame.preExposure),
                      alpha > 0.0 ? float(1.0 / (4.0 * M_PI * halfSin * halfSin)) : 0.0f);
    const double muS = glm::dot(glm::normalize(v.skyView.camera), v.skyView.toSun);
    u.skyView =
        glm::vec4(float(skyRadius), float(muS), depth.reversedZ ? 0.0f : 1.0f, float(lutStorageScale(s)));
    // The sky-view LUT's mapping at its radius (atmosphere_model.h, skyViewSkySpan): β, Z = π - β and the
    // sky half's span D.
    const Model model = modelFrom(s);
    const double beta = skyViewHorizonBeta(model, skyRadius), span = skyViewSkySpan(model, skyRadius);
    u.skyHorizon = glm::vec4(float(beta), float(M_PI - beta), float(span), 0.0f);
    const glm::dvec3 up = glm::normalize(camera);
    const glm::dvec3 sunAcross = toSun - up * glm::dot(toSun, up);
    const double across = glm::length(sunAcross);
    u.sunHorizontal = across > 1e-9 ? glm::vec4(glm::vec3(sunAcross / across), 1.0f) : glm::vec4(0.0f);
    u.transmittanceLut =
        glm::uvec4(s.transmittanceLutSize.x, s.transmittanceLutSize.y, s.transmittanceSteps, 0u);
    const auto side = uint32_t(std::lround(std::sqrt(double(s.multipleScatteringDirections))));
    u.msLut = glm::uvec4(s.multipleScatteringLutSize.x, s.multipleScatteringLutSize.y, side,
                         s.multipleScatteringSteps);
    u.ordersLut = glm::uvec4(s.scatteringOrdersLutSize.x, s.scatteringOrdersLutSize.y,
                             s.scatteringOrdersLutSize.z, s.scatteringOrdersAzimuthSize);
    u.ordersMarch = glm::uvec4(uint32_t(std::lround(std::sqrt(double(s.scatteringOrdersDirections)))),
                               s.scatteringOrdersSteps, s.scatteringOrders, 0u);
    u.skyViewLut = glm::uvec4(s.skyViewLutSize.x, s.skyViewLutSize.y, s.skyViewSteps, 0u);
    u.apLut = glm::uvec4(s.aerialPerspectiveLutSize.x, s.aerialPerspectiveLutSize.y,
                         s.aerialPerspectiveLutSize.z, s.aerialPerspectiveStepsPerSlice);
    u.extent = glm::uvec4(frame.color.extent.width, frame.color.extent.height, 0u, 0u);
    const glm::dvec2 extent(std::max(1u, frame.color.extent.width), std::max(1u, frame.color.extent.height));
    u.applyNdc = glm::vec4(glm::vec2(2.0 / extent), glm::vec2(1.0 / extent - 1.0));
    const auto inverse = [](double x) { return x > 0.0 ? float(1.0 / x) : 0.0f; };
    u.applySkyView = glm::vec4(inverse(span), inverse(beta), 0.0f, 0.0f);
    const glm::dvec2 skySize(std::max(1u, s.skyViewLutSize.x), std::max(1u, s.skyViewLutSize.y));
    u.applySkyTexel = glm::vec4(glm::vec2(1.0 - 1.0 / skySize), glm::vec2(0.5 / skySize));
    // z: the largest μ of a view ray that meets the atmosphere: -cos αt = -√(r² - top²) / r above the top,
    // none (2) inside it.
    const double radius = glm::length(camera);
    const float missCos = radius > t ? float(-std::sqrt((radius - t) * (radius + t)) / radius) : 2.0f;
    u.applyScale = glm::vec4(inverse(radius), inverse(lutStorageScale(s)), missCos, 0.0f);
    const double slices = std::max(1u, s.aerialPerspectiveLutSize.z);
    u.applyAp = glm::vec4(inverse(s.aerialPerspectiveDistance), float(slices), float(0.5 / slices),
                          float(s.aerialPerspectiveDistance / slices));
    const uint32_t msModel = s.multipleScattering == AtmosphereMultipleScattering::Hillaire
                                 ? gpu::kAtmosphereFlagMultipleScattering
                             : s.multipleScattering == AtmosphereMultipleScattering::Orders
                                 ? gpu::kAtmosphereFlagScatteringOrders
                                 : 0u;
    u.flags = glm::uvec4(msModel | (depth.reversedZ ? gpu::kAtmosphereFlagDepthReversedZ : 0u), 0u, 0u, 0u);
    return u;
}

// The planet-centred camera, clamped onto the ground when below it (docs/effects/atmosphere.md).
glm::dvec3 planetCamera(const FrameInfo& frame) {
    const double g = frame.atmosphere.groundRadius;
    const glm::dvec3 p = glm::dvec3(frame.camera.position) + glm::dvec3(0.0, g, 0.0);
    const double r = glm::length(p);
    if (r >= g) return p;
    return r > 0.0 ? p * (g / r) : glm::dvec3(0.0, g, 0.0);
}

// A LUT's image; `sizedBy`: the key of its size (ImageDesc::sizedBy).
core::ImageDesc lutDesc(const char* sizedBy, VkImageType type, uint32_t x, uint32_t y, uint32_t z = 1) {
    core::ImageDesc d;
    d.sizedBy = sizedBy;
    d.type = type;
    d.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    d.extent = {x, y, z};
    d.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    return d;
}

}  // namespace

}  // namespace postfx::atmosphere

namespace postfx::common {

uint64_t airViewSettingsKey(const AtmosphereSettings& settings) {
    return atmosphere::skyViewSettingsKey(settings);
}

}  // namespace postfx::common

namespace postfx::atmosphere {

double lutStorageScale(const AtmosphereSettings& s) {
    double tau = 0.0;
    for (int c = 0; c < 3; ++c)
        tau = std::max(tau, double(s.rayleighScattering[c]) * s.rayleighScaleHeight +
                                double(s.mieScattering) * s.mieScaleHeight);
    return std::clamp(1.0 / std::max(tau, 1e-30), 1e-3, 1e6);
}

double ordersStorageScale(const AtmosphereSettings& s) {
    return std::max(1.0, lutStorageScale(s));
}

AtmosphereEffect::AtmosphereEffect(const core::Gpu&) {}

Status AtmosphereEffect::validate(const FrameInfo& frame) const {
    if (!frame.atmosphere.enabled) return Status::success();
    return validateSettings(frame.atmosphere);
}

AtmosphereEffect::Views AtmosphereEffect::views(const FrameInfo& frame) const {
    const AtmosphereSettings& s = frame.atmosphere;
    Views v;
    LutView now;
    now.valid = true;
    now.camera = planetCamera(frame);
    now.toSun = glm::normalize(glm::dvec3(frame.sun.toSun));
    now.viewToClip = glm::dmat4(frame.camera.projection) * core::rotationOnly(frame.camera.view);
    const double distance = gpu::kAtmosphereRebuildDistance, angle = gpu::kAtmosphereRebuildAngle;

    // Sky view: a function of the camera's radius and the sun's zenith angle alone.
    v.skyView = now;
    v.skyView.settingsKey = skyViewSettingsKey(s);
    v.skyView.viewToClip = glm::dmat4(1.0);
    const LutView& sky = built_.skyView;
    if (sky.valid && sky.settingsKey == v.skyView.settingsKey &&
        std::abs(glm::length(sky.camera) - glm::length(now.camera)) < distance &&
        std::abs(sunZenithAngle(sky) - sunZenithAngle(now)) < angle)
        v.skyView = sky;

    // Aerial perspective: the camera's position and frustum, and the sun.
    v.aerial = now;
    v.aerial.settingsKey = aerialSettingsKey(s);
    const LutView& ap = built_.aerial;
    if (ap.valid && ap.settingsKey == v.aerial.settingsKey &&
        glm::length(ap.camera - now.camera) < distance && angleBetween(ap.toSun, now.toSun) < angle &&
        frustumAngle(ap.viewToClip, now.viewToClip) < angle)
        v.aerial = ap;
    return v;
}

Status AtmosphereEffect::declare(core::FrameBuilder& b) const {
    const FrameInfo& frame = b.frame();
    const AtmosphereSettings& s = frame.atmosphere;
    const bool rgba32 = frame.color.format == VK_FORMAT_R32G32B32A32_SFLOAT;
    const Views v = views(frame);
    const glm::dvec3 camera = planetCamera(frame);
    const core::DepthInput depth = b.depthInput();
    gpu::AtmosphereUniforms u = buildUniforms(frame, b.depthConvention(), v, camera);
    if (depth.distance) u.flags.x |= gpu::kAtmosphereFlagViewDistance;
    const core::BufferRef uniforms = b.uniforms(common::kAirUniforms.id, &u, sizeof u);

    const core::ImageRef transmittance =
        b.persistentImage(common::kSunTransmittanceLut.id,
                          lutDesc("atmosphere.transmittance_lut_size", VK_IMAGE_TYPE_2D,
                                  s.transmittanceLutSize.x, s.transmittanceLutSize.y),
                          transmittanceKey(s));
    b.pass(kTransmittancePass, groupsFor(s.transmittanceLutSize.x), groupsFor(s.transmittanceLutSize.y), 1)
        .bind(gpu::kAtmosphereBindingUniforms, uniforms)
        .bind(gpu::kAtmosphereBindingTransmittance, transmittance, Use::StorageWrite);

    // Without multiple scattering a 1×1×1 image stands in at the binding, never read.
    core::ImageRef multiScattering;
    Use multiScatteringUse = Use::BoundOnly;
    if (s.multipleScattering == AtmosphereMultipleScattering::Off) {
        multiScattering = b.transientImage(common::kAirMultipleScatteringStandIn.id,
                                           lutDesc(nullptr, VK_IMAGE_TYPE_3D, 1, 1, 1));
    } else if (s.multipleScattering == AtmosphereMultipleScattering::Hillaire) {
        multiScattering =
            b.persistentImage(common::kAirMultipleScatteringLut.id,
                              lutDesc("atmosphere.multiple_scattering_lut_size", VK_IMAGE_TYPE_3D,
                                      s.multipleScatteringLutSize.x, s.multipleScatteringLutSize.y),
                              multipleScatteringKey(s));
        multiScatteringUse = Use::Sampled;
        b.pass(kMultiScatteringPass, s.multipleScatteringLutSize.x, s.multipleScatteringLutSize.y, 1)
            .bind(gpu::kAtmosphereBindingUniforms, uniforms)
            .bind(gpu::kAtmosphereBindingTransmittance, transmittance, Use::Sampled, SamplerKind::LinearClamp)
            .bind(gpu::kAtmosphereBindingMultiScattering, multiScattering, Use::StorageWrite);
    } else if (s.multipleScattering == AtmosphereMultipleScattering::Orders) {
        // One pass per order, each reading the order before from one working image and writing its own
        // to the other, and adding it to the LUT (scattering_orders.comp).
        const UVec3 n = s.scatteringOrdersLutSize;
        const core::ImageDesc desc = lutDesc("atmosphere.scattering_orders_lut_size", VK_IMAGE_TYPE_3D,
                                             n.x * s.scatteringOrdersAzimuthSize, n.y, 2 * n.z + 1);
        multiScattering =
            b.persistentImage(common::kAirMultipleScatteringLut.id, desc, multipleScatteringKey(s));
        multiScatteringUse = Use::Sampled;
        const core::ImageRef work[2] = {b.transientImage(kScatteringOrderA, desc),
                                        b.transientImage(kScatteringOrderB, desc)};
        for (uint32_t order = 1; order <= s.scatteringOrders; ++order) {
            const gpu::AtmosphereOrderConstants constants{order, order == s.scatteringOrders ? 1u : 0u};
            b.pass(kOrdersPass, n.y, n.z, 1)
                .push(&constants, sizeof constants)
                .bind(gpu::kAtmosphereBindingUniforms, uniforms)
                .bind(gpu::kAtmosphereBindingTransmittance, transmittance, Use::Sampled,
                      SamplerKind::LinearClamp)
                .bind(gpu::kAtmosphereBindingOrdersIn, work[(order + 1) % 2],
                      order == 1 ? Use::BoundOnly : Use::Sampled, SamplerKind::LinearClamp)
                .bind(gpu::kAtmosphereBindingOrdersOut, work[order % 2], Use::StorageReadWrite)
                .bind(gpu::kAtmosphereBindingMultiScattering, multiScattering,
                      order == 1 ? Use::StorageWrite : Use::StorageReadWrite);
        }
    }
    auto bindLuts = [&] {
        b.bind(gpu::kAtmosphereBindingUniforms, uniforms)
            .bind(gpu::kAtmosphereBindingTransmittance, transmittance, Use::Sampled, SamplerKind::LinearClamp)
            .bind(gpu::kAtmosphereBindingMultiScattering, multiScattering, multiScatteringUse,
                  SamplerKind::LinearClamp);
    };

    // The sky-view LUT: its mapping follows the camera's radius (skyViewSkySpan), which its key holds.
    const core::ImageRef skyView = b.persistentImage(
        kSkyViewLut,
        lutDesc("atmosphere.sky_view_lut_size", VK_IMAGE_TYPE_2D, s.skyViewLutSize.x, s.skyViewLutSize.y),
        viewKey(v.skyView));
    b.pass(kSkyViewPass, groupsFor(s.skyViewLutSize.x), groupsFor(s.skyViewLutSize.y), 1);
    bindLuts();
    b.bind(gpu::kAtmosphereBindingSkyView, skyView, Use::StorageWrite);

    const UVec3 ap = s.aerialPerspectiveLutSize;
    // The in-scattering is filtered across slices (a 3D image); the transmittance is read at one slice's end
    // and extended analytically (apply.comp, aerialPerspective), so it is a 2D array of a layer per slice.
    core::ImageDesc apTransmittanceDesc =
        lutDesc("atmosphere.aerial_perspective_lut_size", VK_IMAGE_TYPE_2D, ap.x, ap.y);
    apTransmittanceDesc.layers = ap.z;
    const uint64_t apKey = viewKey(v.aerial);
    const core::ImageRef apScattering = b.persistentImage(
        common::kAerialPerspectiveLut.id,
        lutDesc("atmosphere.aerial_perspective_lut_size", VK_IMAGE_TYPE_3D, ap.x, ap.y, ap.z), apKey);
    const core::ImageRef apTransmittance =
        b.persistentImage(common::kAerialTransmittanceLut.id, apTransmittanceDesc, apKey);
    b.pass(kApPass, ap.x, ap.y, 1);
    bindLuts();
    b.bind(gpu::kAtmosphereBindingApScattering, apScattering, Use::StorageWrite)
        .bind(gpu::kAtmosphereBindingApTransmittance, apTransmittance, Use::StorageWrite);

    const core::ImageRef source = b.compositeSource(), target = b.compositeTarget();
    b.pass(kApplyPass[rgba32], groupsFor(frame.color.extent.width, gpu::kAtmosphereApplyGroupX),
           groupsFor(frame.color.extent.height, gpu::kAtmosphereApplyGroupY * gpu::kAtmosphereApplyRows), 1);
    bindLuts();
    b.bind(gpu::kAtmosphereBindingSkyView, skyView, Use::Sampled, SamplerKind::LinearClamp)
        .bind(gpu::kAtmosphereBindingApScattering, apScattering, Use::Sampled, SamplerKind::LinearClamp)
        .bind(gpu::kAtmosphereBindingApTransmittance, apTransmittance, Use::Sampled, SamplerKind::LinearClamp)
        .bind(gpu::kAtmosphereBindingColorIn, source, Use::StorageRead)
        .bind(gpu::kAtmosphereBindingDepth, depth.image, Use::Sampled)
        .bind(gpu::kAtmosphereBindingColorOut, target, Use::StorageWrite);

    if (const core::LookupTarget lookup = b.lookupTarget(); lookup.valid()) {
        uint32_t g[3];
        core::lookupGroups(lookup, false, g);
        b.pass(kLookupPass, g[0], g[1], g[2]);
        bindLuts();
        b.bind(gpu::kAtmosphereBindingApScattering, apScattering, Use::Sampled, SamplerKind::LinearClamp)
            .bind(gpu::kAtmosphereBindingApTransmittance, apTransmittance, Use::Sampled,
                  SamplerKind::LinearClamp);
        core::bindLookup(b, lookup);
    }
    return Status::success();
}

void AtmosphereEffect::recorded(const FrameInfo& frame, bool active) {
    if (!active) {
        built_ = {};
        return;
    }
    const Views v = views(frame);
    built_.aerial = v.aerial;
    built_.skyView = v.skyView;
}

void AtmosphereEffect::adjusted(const FrameInfo& frame, std::vector<std::string>& out) const {
    const glm::dvec3 p =
        glm::dvec3(frame.camera.position) + glm::dvec3(0.0, frame.atmosphere.groundRadius, 0.0);
    if (glm::length(p) < frame.atmosphere.groundRadius)
        out.push_back(
            "atmosphere: FrameInfo.camera.position is below the ground (the planet's surface): the sky "
            "and the aerial perspective are drawn from the ground above it");
}

}  // namespace postfx::atmosphere
