// The clouds' path tracer (clouds_path_tracer.h) against closed forms and a published path tracer: single
// scattering in a homogeneous slab, the composite's transmittance, every order in a published slab case,
// energy conservation at albedo 1, and an image that does not depend on the thread count. Every tolerance
// is a multiple of the estimate's own standard error.
#include "clouds/clouds_model.h"
#include "clouds/clouds_path_tracer.h"
#include "clouds_flux.h"
#include "clouds_frames.h"
#include "host/camera_math.h"

#include <postfx/reference.h>

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <vector>

namespace {

namespace cl = postfx::clouds;
using glm::dvec3;

// A flat homogeneous layer (atmosphere off, noise off, coverage 1) between `bottom` and `top` of extinction
// `sigma`, the camera at y = 0, sun illuminance 1, no ambient.
postfx::FrameInfo slabFrame(double bottom, double top, double sigma, double albedo) {
    postfx::FrameInfo f;
    f.clouds = test::homogeneousLayer();
    f.clouds.bottomHeight = float(bottom);
    f.clouds.topHeight = float(top);
    f.clouds.density = float(sigma);
    f.clouds.albedo = float(albedo);
    f.camera.position = {0.0, 0.0, 0.0};
    f.sun.toSun = {0.0f, 1.0f, 0.0f};
    f.sun.illuminance = postfx::Vec3(1.0f);
    f.ambient = postfx::Vec3(0.0f);
    return f;
}

// A unit direction `elevationDeg` above the horizon at azimuth `azimuthDeg` (0: +x, 90: +z).
dvec3 direction(double elevationDeg, double azimuthDeg) {
    const double e = glm::radians(elevationDeg), a = glm::radians(azimuthDeg);
    return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}

// Single scattering seen from below a homogeneous slab of thickness H (the camera under it), view and sun
// both upward (cosines μv, μ0 to the vertical): L = α·E·p·(σ/μv)·e^{-σH/μ0}·∫_0^H e^{-σs(1/μv - 1/μ0)} ds.
double slabSingleScattering(double albedo, double sigma, double H, double muV, double mu0, double phase) {
    const double a = sigma * (1.0 / muV - 1.0 / mu0);
    const double integral = std::abs(a * H) < 1e-12 ? H : -std::expm1(-a * H) / a;
    return albedo * phase * (sigma / muV) * std::exp(-sigma * H / mu0) * integral;
}

// The model's layer is float: its values as the model reads them.
double f32(double v) {
    return double(float(v));
}

cl::PathEstimate trace(const cl::Model& m, const dvec3& d, uint32_t samples, uint32_t orders) {
    cl::PathOptions o;
    o.samples = samples;
    o.maxScatteringOrders = orders;
    return cl::estimateRadiance(m, dvec3(0.0), d, cl::kMaxPathLength, o, 0);
}

// Looking straight up at the sun overhead: α·σ·E·p(1)·H·e^{-σH}.
TEST(CloudsPathTracer, SingleScatteringOverheadMatchesClosedForm) {
    postfx::FrameInfo f = slabFrame(1000.0, 2000.0, 0.002, 0.9);
    const cl::Model m = cl::modelFrom(f, {}, {});
    const dvec3 up(0.0, 1.0, 0.0);
    const cl::PathEstimate e = trace(m, up, 20000, 1);
    const double sigma = f32(0.002), H = 1000.0, albedo = f32(0.9);
    const double expected = albedo * sigma * cl::phase(m, up, 1.0) * H * std::exp(-sigma * H);
    EXPECT_NEAR(e.radiance.x, expected, 4.0 * e.standardError.x + 1e-12);
    EXPECT_EQ(e.radiance.x, e.radiance.y);  // a grey sun, a grey medium
    EXPECT_LT(e.standardError.x, 0.05 * expected);
    EXPECT_EQ(e.truncated, 0u);
}

// An oblique view and sun: the integral over the slab of α·σ·E·p(cosθ)·e^{-σs/μ0}·e^{-σs'/μv}.
TEST(CloudsPathTracer, SingleScatteringObliqueMatchesClosedForm) {
    postfx::FrameInfo f = slabFrame(1000.0, 2000.0, 0.002, 0.9);
    const dvec3 toSun = direction(30.0, 40.0), view = direction(50.0, 0.0);
    f.sun.toSun = postfx::Vec3(toSun);
    const cl::Model m = cl::modelFrom(f, {}, {});
    const cl::PathEstimate e = trace(m, view, 20000, 1);
    const double expected =
        slabSingleScattering(f32(0.9), f32(0.002), 1000.0, view.y, m.toSun.y, cl::phase(m, view, 1.0));
    EXPECT_NEAR(e.radiance.x, expected, 4.0 * e.standardError.x + 1e-12);
    EXPECT_LT(e.standardError.x, 0.05 * expected);
}

// The composite's transmittance (the fine march's, which tracePixel hands on) is e^{-σH/μ}.
TEST(CloudsPathTracer, CompositeTransmittanceIsBeerLambert) {
    const cl::Model m = cl::modelFrom(slabFrame(1000.0, 2000.0, 0.002, 0.9), {}, {});
    cl::PathOptions o;
    o.samples = 2;
    for (double mu : {1.0, 0.5, 0.1}) {
        const dvec3 d(std::sqrt(1.0 - mu * mu), mu, 0.0);
        const cl::PixelTruth p = cl::tracePixel(m, d, 1e7, 1024, o, 0);
        EXPECT_NEAR(p.transmittance, std::exp(-f32(0.002) * 1000.0 / mu), 1e-12) << mu;
        // D: the entry's distance plus the extinction-weighted mean depth inside, (1 - e^{-x}(1 + x)) /
        // (σ(1 - e^{-x})) with x = σ·L.
        const double sigma = f32(0.002), L = 1000.0 / mu, x = sigma * L;
        const double D = 1000.0 / mu + (1.0 - std::exp(-x) * (1.0 + x)) / (sigma * -std::expm1(-x));
        EXPECT_NEAR(p.meanDistance / D, 1.0, 1e-4) << mu;
        EXPECT_GT(p.light.radiance.x, 0.0) << mu;
    }
}

// The published slab case: a layer 1000–1500 m of extinction 0.01 /m (optical depth 5), albedo 1, HG g =
// 0.6, seen from the ground 60° up with the sun 45° up, 15° from the view direction: L/E = 0.1167 ± 0.13%
// (1σ), single scattering 5.692e-3 (the published depth-2 path tracer).
TEST(CloudsPathTracer, PublishedSlabCase) {
    postfx::FrameInfo f = slabFrame(1000.0, 1500.0, 0.01, 1.0);
    f.clouds.anisotropyForward = 0.6f;
    f.clouds.lobeMix = 0.0f;
    const dvec3 view = direction(60.0, 0.0), toSun = direction(45.0, 0.0);
    f.sun.toSun = postfx::Vec3(toSun);
    const cl::Model m = cl::modelFrom(f, {}, {});
    ASSERT_NEAR(glm::degrees(std::acos(glm::dot(view, m.toSun))), 15.0, 1e-4);

    // Single scattering: the closed form, and ours against it and against the published depth-2 value (its
    // error taken as the same 0.13%).
    const double publishedSingle = 5.692e-3, publishedSingleError = 0.0013 * publishedSingle;
    const double closed =
        slabSingleScattering(1.0, f32(0.01), 500.0, view.y, m.toSun.y, cl::phase(m, view, 1.0));
    EXPECT_NEAR(closed, publishedSingle, 4.0 * publishedSingleError);
    const cl::PathEstimate single = trace(m, view, 200000, 1);
    EXPECT_NEAR(single.radiance.x, closed, 4.0 * single.standardError.x + 1e-12);
    EXPECT_NEAR(single.radiance.x, publishedSingle,
                4.0 * std::hypot(single.standardError.x, publishedSingleError));

    const uint32_t kPaths = 1000000;  // 1.4 s: 1σ ≈ 0.2%
    const cl::PathEstimate all = trace(m, view, kPaths, 0);
    const double published = 0.1167, publishedError = 0.0013 * published;
    const double sigma = std::hypot(all.standardError.x, publishedError);
    EXPECT_NEAR(all.radiance.x, published, 4.0 * sigma);
    EXPECT_LT(all.standardError.x, 0.003 * published);
    EXPECT_EQ(all.truncated, 0u);
    std::printf("published slab: L/E = %.5f ± %.5f (1σ, %u paths), single %.6f ± %.6f (closed form %.6f)\n",
                all.radiance.x, all.standardError.x, kPaths, single.radiance.x, single.standardError.x,
                closed);
}

// Albedo 1, sun alone: the flux the layer sends up, the diffuse flux it lets down and the direct beam
// through it add up to the incident E·μ0.
TEST(CloudsPathTracer, ConservativeSlabConservesEnergy) {
    postfx::FrameInfo f = slabFrame(1000.0, 2000.0, 0.002, 1.0);  // the dual lobe's defaults
    f.sun.toSun = postfx::Vec3(direction(60.0, 30.0));
    const cl::Model m = cl::modelFrom(f, {}, {});
    cl::Rng rng(7);
    const test::RadianceFunction radiance = [&](const dvec3& origin, const dvec3& dir) {
        return cl::tracePath(m, origin, dir, cl::kMaxPathLength, 0, rng);
    };
    const uint32_t n = 200000;
    const test::FluxEstimate up =
        test::hemisphereFlux(radiance, {0.0, 2001.0, 0.0}, {0.0, -1.0, 0.0}, n, rng);
    const test::FluxEstimate down =
        test::hemisphereFlux(radiance, {0.0, 999.0, 0.0}, {0.0, 1.0, 0.0}, n, rng);
    const double mu0 = m.toSun.y, tau = f32(0.002) * 1000.0;
    const double direct = mu0 * std::exp(-tau / mu0);
    const double total = up.flux.x + down.flux.x + direct;
    const double sigma = std::hypot(up.standardError.x, down.standardError.x);
    EXPECT_NEAR(total, mu0, 4.0 * sigma + 1e-12);
    EXPECT_LT(sigma, 0.005 * mu0);
    std::printf("energy: up %.5f + diffuse down %.5f + direct %.5f = %.5f ± %.5f of %.5f\n", up.flux.x,
                down.flux.x, direct, total, sigma, mu0);
}

// renderClouds' path-traced mode on noisy clouds: the same seed gives the same image and standard error
// on 1 and 2 threads; another seed another image.
TEST(CloudsPathTracer, SameSeedSameImageOnAnyThreadCount) {
    const uint32_t w = 8, h = 6;
    std::vector<float> color(size_t(w) * h * 4, 0.5f), depth(size_t(w) * h, 0.0f);
    postfx::reference::CloudInputs in;
    in.width = w;
    in.height = h;
    in.color = color;
    in.depth = depth;
    in.depthConvention.reversedZ = true;
    in.camera.view = glm::lookAt(glm::vec3(0.0f), glm::vec3(0.3f, 1.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    in.camera.projection = demo::perspectiveProjection(1.0f, float(w) / float(h), 0.1f, 1000.0f, true, false);
    in.sun.toSun = {0.3f, 0.8f, -0.2f};
    in.sun.illuminance = {3.0f, 2.0f, 1.0f};
    in.ambient = {0.2f, 0.3f, 0.5f};
    in.settings = test::finelyMarchedNoisyClouds();
    in.settings.bottomHeight = 1000.0f;
    in.settings.topHeight = 1600.0f;
    in.stepsPerPixel = 64;
    in.pathTraced = true;
    in.pathSamples = 4;
    std::vector<float> one, two, other, errorOne, errorTwo, errorOther;
    in.threads = 1;
    ASSERT_TRUE(postfx::reference::renderClouds(in, one, &errorOne).ok());
    in.threads = 2;
    ASSERT_TRUE(postfx::reference::renderClouds(in, two, &errorTwo).ok());
    EXPECT_EQ(one, two);
    EXPECT_EQ(errorOne, errorTwo);
    in.pathSeed = 2;
    ASSERT_TRUE(postfx::reference::renderClouds(in, other, &errorOther).ok());
    EXPECT_NE(one, other);
    size_t traced = 0;
    for (size_t p = 0; p < size_t(w) * h; ++p) {
        traced += errorOne[p * 4] > 0.0f ? 1 : 0;
        EXPECT_EQ(errorOne[p * 4 + 3], 0.0f);
    }
    EXPECT_GT(traced, size_t(0));  // some pixels look through clouds

    in.pathSamples = 1;
    const postfx::Status s = postfx::reference::renderClouds(in, other, nullptr);
    EXPECT_EQ(s.code, postfx::Result::InvalidArgument);
    EXPECT_NE(s.message.find("CloudInputs.pathSamples"), std::string::npos) << s.message;
    in.pathSamples = 4;
    in.maxScatteringOrders = 2000000;
    EXPECT_NE(
        postfx::reference::renderClouds(in, other, nullptr).message.find("CloudInputs.maxScatteringOrders"),
        std::string::npos);
}

}  // namespace
