// The clouds' model in double (clouds_model.cpp) against closed forms: a homogeneous layer's transmittance,
// single scattering of the sun in a homogeneous slab, the phase function's normalisation, the shapes'
// intersections.
#include "clouds/clouds_model.h"
#include "clouds_frames.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace {

namespace cl = postfx::clouds;

// A flat homogeneous layer (noise off, coverage 1) between 1000 and 2000 m, camera at 10 m.
postfx::FrameInfo homogeneousFrame() {
    postfx::FrameInfo f;
    f.clouds = test::homogeneousLayer();
    f.clouds.albedo = 0.9f;
    // Single scattering only: one octave of Wrenninge's model.
    f.clouds.multipleScattering.model = postfx::CloudScatteringModel::Octaves;
    f.clouds.multipleScattering.octaves = 1;
    f.clouds.lightDistance = 1e5f;
    f.camera.position = {0.0, 10.0, 0.0};
    f.sun.toSun = {0.0f, 1.0f, 0.0f};
    f.sun.illuminance = postfx::Vec3(1.0f);
    return f;
}

TEST(CloudsModel, HomogeneousLayerTransmittanceIsBeerLambert) {
    const cl::Model m = cl::modelFrom(homogeneousFrame(), {}, {});
    for (double cosine : {1.0, 0.5, 0.1}) {
        const glm::dvec3 d(std::sqrt(1.0 - cosine * cosine), cosine, 0.0);
        const cl::MarchResult r = cl::march(m, d, 1e7, 64, 0.5, 8);
        EXPECT_NEAR(r.transmittance, std::exp(-double(0.002f) * 1000.0 / cosine), 1e-12) << cosine;
    }
}

// Looking straight up with the sun at the zenith, single scattering only, no ambient: every sample sees
// the sun through σ·(top - y), so L = α·σ·E·p(1)·H·e^{-σH} for a slab of thickness H.
TEST(CloudsModel, SingleScatteringInAHomogeneousSlabMatchesClosedForm) {
    const cl::Model m = cl::modelFrom(homogeneousFrame(), {}, {});
    const cl::MarchResult r = cl::march(m, {0.0, 1.0, 0.0}, 1e7, 4096, 0.5, 512);
    const double sigma = double(0.002f), H = 1000.0;
    const double expected = 0.9 * sigma * cl::phase(m, {0.0, 1.0, 0.0}, 1.0) * H * std::exp(-sigma * H);
    EXPECT_NEAR(r.luminance.x / expected, 1.0, 1e-4);
    // The dual lobe is brightest toward the sun: forward scattering peaks looking at it.
    EXPECT_GT(cl::phase(m, {0.0, 1.0, 0.0}, 1.0), cl::phase(m, {0.0, -1.0, 0.0}, 1.0));
    EXPECT_GT(cl::phase(m, {0.0, 1.0, 0.0}, 1.0), cl::phase(m, {1.0, 0.0, 0.0}, 1.0));
}

// ∫ p dω = 1 for the dual lobe and its octaves' scaled asymmetries (midpoint rule over cos θ).
TEST(CloudsModel, PhaseIsNormalised) {
    const cl::Model m = cl::modelFrom(homogeneousFrame(), {}, {});
    for (double scale : {1.0, 0.5, 0.25}) {
        const int n = 200000;
        double sum = 0.0;
        for (int i = 0; i < n; ++i) {
            const double c = -1.0 + (i + 0.5) * 2.0 / n;
            const glm::dvec3 d(std::sqrt(1.0 - c * c), c, 0.0);
            sum += cl::phase(m, d, scale) * 2.0 * glm::pi<double>() * (2.0 / n);
        }
        EXPECT_NEAR(sum, 1.0, 1e-4) << scale;
    }
}

TEST(CloudsModel, SegmentsOfEachShape) {
    postfx::FrameInfo f = homogeneousFrame();
    {  // flat: from below, straight up and at 60° from the zenith
        const cl::Model m = cl::modelFrom(f, {}, {});
        glm::dvec2 s = cl::segment(m, glm::dvec3(0.0), {0.0, 1.0, 0.0}, 1e7);
        EXPECT_NEAR(s.x, 990.0, 1e-9);
        EXPECT_NEAR(s.y, 1990.0, 1e-9);
        s = cl::segment(m, glm::dvec3(0.0), {0.0, -1.0, 0.0}, 1e7);
        EXPECT_LE(s.y, s.x);
    }
    {  // curved: straight up from the ground the same; horizontal from inside the layer: to the top sphere
        f.atmosphere.enabled = true;
        f.camera.position = {0.0, 1500.0, 0.0};
        const cl::Model m = cl::modelFrom(f, {}, {});
        const double R = f.atmosphere.groundRadius;
        const glm::dvec2 s = cl::segment(m, glm::dvec3(0.0), {1.0, 0.0, 0.0}, 1e9);
        EXPECT_NEAR(s.x, 0.0, 1e-9);
        EXPECT_NEAR(s.y, std::sqrt((R + 2000.0) * (R + 2000.0) - (R + 1500.0) * (R + 1500.0)), 1e-3);
    }
    {  // box: rotated 90° about y, looking along x through its z extent
        f.atmosphere.enabled = false;
        f.clouds.shape = postfx::CloudShape::Box;
        f.clouds.box.center = {100.0, 10.0, 0.0};
        f.clouds.box.halfSize = {5.0f, 5.0f, 20.0f};
        f.clouds.box.yawDeg = 90.0f;
        f.camera.position = {0.0, 10.0, 0.0};
        const cl::Model m = cl::modelFrom(f, {}, {});
        const glm::dvec2 s = cl::segment(m, glm::dvec3(0.0), {1.0, 0.0, 0.0}, 1e7);
        EXPECT_NEAR(s.x, 80.0, 1e-9);
        EXPECT_NEAR(s.y, 120.0, 1e-9);
        EXPECT_NEAR(cl::heightFraction(m, {100.0, 0.0, 0.0}), 0.5, 1e-12);
    }
}

}  // namespace
