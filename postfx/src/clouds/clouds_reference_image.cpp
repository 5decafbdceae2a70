// The clouds' CPU reference (docs/effects/clouds.md, "Reference"): the model of clouds_model.h per pixel
// with fine steps, in double, or with pathTraced the path tracer's radiance (clouds_path_tracer.h); pixel
// rays and the composite as the fogs' references (common/reference_image.h), the aerial perspective in
// front of the clouds from the air's view segments (common/air.h).
#include "clouds/clouds_effect.h"
#include "clouds/clouds_model.h"
#include "clouds/clouds_path_tracer.h"
#include "common/air.h"
#include "common/noise_cpu.h"
#include "common/parallel.h"
#include "common/reference_image.h"
#include "core/checks.h"

#include <postfx/reference.h>

#include <cmath>
#include <new>
#include <string>

namespace postfx::reference {
namespace {

using core::invalid;
using detail::checkCount;
using glm::dvec3;

constexpr uint32_t kMaxSteps = 1u << 20;
constexpr uint32_t kMaxPathSamples = 1u << 24;
constexpr uint32_t kMaxScatteringOrders = 1000000;

Status validate(const CloudInputs& in) {
    if (Status s = detail::checkImage("CloudInputs", in.width, in.height, in.color, in.depth); !s) return s;
    if (Status s = validateCloudSettings(in.settings); !s) return s;
    if (in.atmosphere.enabled)
        if (Status s = validateAtmosphereSettings(in.atmosphere); !s) return s;
    if (Status s = core::checkLighting(in.sun, in.ambient, ""); !s) return s;
    if (Status s = core::checkCamera(in.camera, "camera"); !s) return s;
    if (!core::allFinite(detail::clipToView(in.camera)))
        return invalid("camera.projection: projection · view rotation is not invertible");
    if (in.stepsPerPixel == 0 || in.stepsPerPixel > kMaxSteps)
        return invalid("CloudInputs.stepsPerPixel: " + std::to_string(in.stepsPerPixel) + " is outside [1, " +
                       std::to_string(kMaxSteps) + "]");
    if (in.lightSteps == 0 || in.lightSteps > kMaxSteps)
        return invalid("CloudInputs.lightSteps: " + std::to_string(in.lightSteps) + " is outside [1, " +
                       std::to_string(kMaxSteps) + "]");
    if (in.pathTraced && (in.pathSamples < 2 || in.pathSamples > kMaxPathSamples))
        return invalid("CloudInputs.pathSamples: " + std::to_string(in.pathSamples) + " is outside [2, " +
                       std::to_string(kMaxPathSamples) + "]");
    if (in.pathTraced && in.maxScatteringOrders > kMaxScatteringOrders)
        return invalid("CloudInputs.maxScatteringOrders: " + std::to_string(in.maxScatteringOrders) +
                       " is outside [0, " + std::to_string(kMaxScatteringOrders) + "] (0: all)");
    const CloudNoiseSettings& n = in.settings.noise;
    const uint64_t base = in.baseNoiseSize ? in.baseNoiseSize : n.baseSize;
    const uint64_t detailSize = in.detailNoiseSize ? in.detailNoiseSize : n.detailSize;
    if (n.enabled && !in.baseNoise.empty())
        if (Status s = checkCount("CloudInputs.baseNoise", in.baseNoise.size(), base * base * base,
                                  "baseNoiseSize³ (or noise.base_size³)");
            !s)
            return s;
    if (n.enabled && !in.detailNoise.empty())
        if (Status s =
                checkCount("CloudInputs.detailNoise", in.detailNoise.size(),
                           detailSize * detailSize * detailSize, "detailNoiseSize³ (or noise.detail_size³)");
            !s)
            return s;
    if (!in.coverageMap.empty())
        if (Status s = checkCount("CloudInputs.coverageMap", in.coverageMap.size(),
                                  uint64_t(in.coverageMapWidth) * in.coverageMapHeight,
                                  "coverageMapWidth · coverageMapHeight");
            !s)
            return s;
    return Status::success();
}

std::vector<float> unorm(const std::vector<uint8_t>& bytes) {
    std::vector<float> v(bytes.size());
    for (size_t i = 0; i < bytes.size(); ++i)
        v[i] = float(bytes[i]) / 255.0f;
    return v;
}

}  // namespace

Status renderClouds(const CloudInputs& in, std::vector<float>& out) {
    return renderClouds(in, out, nullptr);
}

Status renderClouds(const CloudInputs& in, std::vector<float>& out, std::vector<float>* standardError) {
    if (Status s = validate(in); !s) return s;
    std::vector<float> result;  // not `out` directly: `in.color` may view it
    std::vector<float> baseTexels, detailTexels;
    const CloudNoiseSettings& n = in.settings.noise;
    try {
        result.assign(in.color.begin(), in.color.end());
        if (standardError) standardError->assign(in.color.size(), 0.0f);
        if (n.enabled && in.baseNoise.empty())
            baseTexels = unorm(common::generateNoiseCpu(n.baseSize, n.seed));
        if (n.enabled && in.detailNoise.empty())
            detailTexels = unorm(common::generateWorleyNoiseCpu(n.detailSize, clouds::detailSeed(n.seed)));
    } catch (const std::bad_alloc&) {
        return {Result::OutOfMemory,
                "reference::renderClouds: cannot allocate the output image or the noise"};
    }
    if (!in.settings.enabled || in.settings.coverage <= 0.0f || in.settings.density <= 0.0f) {
        out.swap(result);
        return Status::success();
    }
    FrameInfo frame;
    frame.camera = in.camera;
    frame.sun = in.sun;
    frame.ambient = in.ambient;
    frame.timeSeconds = in.timeSeconds;
    frame.clouds = in.settings;
    frame.atmosphere = in.atmosphere;
    clouds::NoiseVolume base{baseTexels.empty() ? in.baseNoise : std::span<const float>(baseTexels),
                             baseTexels.empty() && in.baseNoiseSize ? in.baseNoiseSize : n.baseSize};
    clouds::NoiseVolume detail{
        detailTexels.empty() ? in.detailNoise : std::span<const float>(detailTexels),
        detailTexels.empty() && in.detailNoiseSize ? in.detailNoiseSize : n.detailSize};
    const clouds::CoverageMapTexels coverageMap{in.coverageMap, in.coverageMapWidth, in.coverageMapHeight};
    const clouds::Model model = clouds::modelFrom(frame, base, detail, coverageMap);

    // The air in front of the clouds (atmosphere on): reference (a)'s integration to their mean distance.
    std::shared_ptr<const common::Air> air;
    if (in.atmosphere.enabled) {
        try {
            air = common::makeViewAir(in.atmosphere, in.sun, dvec3(in.camera.position), 256);
        } catch (const std::bad_alloc&) {
            return {Result::OutOfMemory, "reference::renderClouds: cannot allocate the atmosphere's tables"};
        }
    }

    clouds::PathOptions paths;
    paths.samples = in.pathSamples;
    paths.maxScatteringOrders = in.maxScatteringOrders;
    paths.seed = in.pathSeed;
    const glm::dmat4 clipToView = detail::clipToView(in.camera);
    const double farDepth = in.depthConvention.reversedZ ? 0.0 : 1.0;
    common::parallelFor(in.height, in.threads, [&](uint32_t j) {
        for (uint32_t i = 0; i < in.width; ++i) {
            const size_t p = size_t(j) * in.width + i;
            const detail::PixelRay ray =
                detail::pixelRay(clipToView, farDepth, in.width, in.height, i, j, in.depth[p]);
            const double far = std::min(ray.distance, double(in.settings.maxDistance));
            clouds::MarchResult r;
            dvec3 error(0.0);
            if (in.pathTraced) {
                const clouds::PixelTruth truth =
                    clouds::tracePixel(model, ray.d, far, in.stepsPerPixel, paths, p);
                r.luminance = truth.light.radiance;
                r.transmittance = truth.transmittance;
                r.meanDistance = truth.meanDistance;
                error = truth.light.standardError;
            } else {
                r = clouds::march(model, ray.d, far, in.stepsPerPixel, 0.5, in.lightSteps);
            }
            if (!(r.transmittance < 1.0)) continue;
            dvec3 L = r.luminance;
            if (air) {
                const common::Air::Segment front = air->viewSegment(ray.d, r.meanDistance);
                L = front.transmittance * L + (1.0 - r.transmittance) * front.luminance;
                error *= front.transmittance;
            }
            detail::composite(L, r.transmittance, &in.color[p * 4], &result[p * 4]);
            if (standardError)
                for (int c = 0; c < 3; ++c)
                    (*standardError)[p * 4 + c] = float(error[c]);
        }
    });
    out.swap(result);
    return Status::success();
}

}  // namespace postfx::reference
