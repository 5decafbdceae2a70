// The double-precision fog reference (postfx::reference::renderFog) against closed forms of the model
// in docs/effects/fog.md. Host only. Homogeneous fog is integrated exactly by every step (the step
// integral is exact for constant σt), so those tests use few steps; height fog needs many.
#include "common/reference_model.h"

#include <postfx/reference.h>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

namespace {

using postfx::Result;
using postfx::reference::FogInputs;
using postfx::reference::henyeyGreenstein;
using postfx::reference::renderFog;

constexpr double kPi = std::numbers::pi;

// Vulkan perspective projection (clip y down), finite far plane, like the demo's.
glm::mat4 perspective(float fovY, float aspect, float n, float f, bool reversedZ) {
    const float s = 1.0f / std::tan(0.5f * fovY);
    glm::mat4 m(0.0f);
    m[0][0] = s / aspect;
    m[1][1] = -s;
    m[2][3] = -1.0f;
    m[2][2] = reversedZ ? n / (f - n) : f / (n - f);
    m[3][2] = reversedZ ? f * n / (f - n) : -f * n / (f - n);
    return m;
}

// One frame of inputs owning its arrays; inputs() points the spans at them.
struct Frame {
    uint32_t w, h;
    std::vector<float> color, depth, noise, shadow;
    FogInputs in;

    Frame(uint32_t width, uint32_t height, bool reversedZ = true) : w(width), h(height) {
        color.assign(size_t(w) * h * 4, 0.0f);
        for (size_t p = 0; p < size_t(w) * h; ++p)
            color[p * 4 + 3] = 0.25f;
        depth.assign(size_t(w) * h, reversedZ ? 0.0f : 1.0f);  // no geometry
        in.width = w;
        in.height = h;
        in.depthConvention.reversedZ = reversedZ;
        in.camera.projection = perspective(1.0f, float(w) / float(h), 0.1f, 1000.0f, reversedZ);
        in.sun.toSun = glm::normalize(glm::vec3(0.2f, 0.3f, -0.9f));
        in.sun.illuminance = {3.0f, 2.0f, 1.0f};
        in.ambient = glm::vec3(0.0f);
        in.settings.enabled = true;
        in.settings.density = 0.02f;
        in.settings.albedo = {0.9f, 0.5f, 0.2f};
        in.settings.anisotropy = 0.6f;
        in.settings.heightFalloff = 0.0f;
        in.settings.maxDistance = 200.0f;
        in.stepsPerPixel = 64;
        in.threads = 2;
    }
    const FogInputs& inputs() {
        in.color = color;
        in.depth = depth;
        in.noise = noise;
        in.shadowDepth = shadow;
        return in;
    }
    std::vector<float> render() {
        std::vector<float> out;
        const postfx::Status s = renderFog(inputs(), out);
        EXPECT_TRUE(s.ok()) << s.message;
        return out;
    }
    glm::dvec2 ndc(uint32_t i, uint32_t j) const {
        return {(i + 0.5) / w * 2.0 - 1.0, (j + 0.5) / h * 2.0 - 1.0};
    }
    // View-space point of pixel (i, j) at clip depth z.
    glm::dvec3 viewPoint(uint32_t i, uint32_t j, double z) const {
        const glm::dvec4 p = glm::inverse(glm::dmat4(in.camera.projection)) * glm::dvec4(ndc(i, j), z, 1.0);
        return glm::dvec3(p) / p.w;
    }
    // World-space unit direction of pixel (i, j).
    glm::dvec3 worldDir(uint32_t i, uint32_t j) const {
        return glm::normalize(glm::inverse(glm::dmat3(in.camera.view)) * viewPoint(i, j, 0.5));
    }
    // Puts a surface at distance distance(i, j) along every pixel's ray.
    void setWall(const std::function<double(uint32_t, uint32_t)>& distance) {
        const glm::dmat4 proj(in.camera.projection);
        for (uint32_t j = 0; j < h; ++j) {
            for (uint32_t i = 0; i < w; ++i) {
                const glm::dvec4 c =
                    proj * glm::dvec4(distance(i, j) * glm::normalize(viewPoint(i, j, 0.5)), 1.0);
                depth[j * w + i] = float(c.z / c.w);
            }
        }
    }
    // Distance to the surface that the stored (float) depth of pixel (i, j) reconstructs to.
    double surfaceDistance(uint32_t i, uint32_t j) const {
        return glm::length(viewPoint(i, j, depth[j * w + i]));
    }
    double phase(uint32_t i, uint32_t j) const {
        const glm::dvec3 toSun = glm::normalize(glm::dvec3(in.sun.toSun));
        return henyeyGreenstein(glm::dot(worldDir(i, j), toSun), in.settings.anisotropy);
    }
};

void expectRel(double actual, double expected, double rel, const char* what) {
    EXPECT_NEAR(actual, expected, rel * std::abs(expected) + 1e-12) << what;
}

// --- 1. Phase ---------------------------------------------------------------------------------------

TEST(FogReference, HenyeyGreensteinIsNormalisedAndPeaksTowardTheSun) {
    for (double g : {-0.99, -0.5, 0.0, 0.3, 0.9, 0.99}) {
        // ∫ p dω = 2π ∫ p(μ) dμ over [-1, 1], Simpson's rule fine enough for the g = ±0.99 peak.
        const int n = 2'000'000;
        const double step = 2.0 / n;
        double sum = henyeyGreenstein(-1.0, g) + henyeyGreenstein(1.0, g);
        for (int k = 1; k < n; ++k)
            sum += (k % 2 ? 4.0 : 2.0) * henyeyGreenstein(-1.0 + k * step, g);
        EXPECT_NEAR(2.0 * kPi * sum * step / 3.0, 1.0, 1e-4) << "g = " << g;

        for (int k = 0; k < 200; ++k) {
            const double mu = -1.0 + (k + 0.5) / 100.0;
            if (g > 0) {
                EXPECT_GT(henyeyGreenstein(1.0, g), henyeyGreenstein(mu, g)) << g;
            } else if (g < 0) {
                EXPECT_GT(henyeyGreenstein(-1.0, g), henyeyGreenstein(mu, g)) << g;
            } else {
                EXPECT_DOUBLE_EQ(henyeyGreenstein(mu, g), 1.0 / (4.0 * kPi));
            }
        }
    }
    // g is clamped to ±0.999 (stays finite at |g| = 1).
    EXPECT_DOUBLE_EQ(henyeyGreenstein(1.0, 1.0), henyeyGreenstein(1.0, double(0.999f)));
    EXPECT_TRUE(std::isfinite(henyeyGreenstein(-1.0, -1.0)));
}

// --- 2. Homogeneous fog, unshadowed: exact closed form -------------------------------------------------

void checkHomogeneousWall(bool reversedZ) {
    Frame f(8, 6, reversedZ);
    // A rotated camera far from the origin whose view matrix carries a (huge) translation that the march
    // must ignore: positions are camera-relative.
    f.in.camera.position = {1e6, 20.0, -3e5};
    glm::mat4 view = glm::mat4(glm::mat3(glm::rotate(glm::mat4(1.0f), 0.7f, glm::vec3(0.3f, 1.0f, 0.2f))));
    view[3] = glm::vec4(-4e5f, 1e4f, 7e5f, 1.0f);
    f.in.camera.view = view;
    f.setWall([](uint32_t i, uint32_t j) { return 10.0 + 7.0 * i + 3.0 * j; });
    const std::vector<float> black = f.render();

    for (size_t p = 0; p < f.color.size(); ++p)
        f.color[p] = 0.1f + 0.05f * float(p % 7);
    const std::vector<float> lit = f.render();

    const glm::dvec3 albedo(f.in.settings.albedo), e(f.in.sun.illuminance);
    for (uint32_t j = 0; j < f.h; ++j) {
        for (uint32_t i = 0; i < f.w; ++i) {
            const size_t p = j * f.w + i;
            const double t = std::exp(-double(f.in.settings.density) * f.surfaceDistance(i, j));
            for (int c = 0; c < 3; ++c) {
                const double l =
                    e[c] * f.phase(i, j) * albedo[c] * (1.0 - t);  // L = E·p·albedo·(1 - e^{-σt·D})
                expectRel(black[p * 4 + c], l, 1e-6, "black");
                expectRel(lit[p * 4 + c], f.color[p * 4 + c] * t + l, 1e-6, "color·T + L");
            }
            EXPECT_EQ(lit[p * 4 + 3], f.color[p * 4 + 3]);
        }
    }
}

TEST(FogReference, HomogeneousUnshadowedMatchesClosedFormReversedZ) {
    checkHomogeneousWall(true);
}
TEST(FogReference, HomogeneousUnshadowedMatchesClosedFormStandardZ) {
    checkHomogeneousWall(false);
}

// --- 3. Height fog along a vertical ray -------------------------------------------------------------------

struct Vertical {
    double t;         // transmittance (the output of a white pixel with no light)
    double distance;  // to the surface the stored depth reconstructs to
};

// A 1x1 image looking straight up (or down) at a surface at distance d.
Vertical verticalRay(bool up, double d, float maxDistance, bool reversedZ) {
    Frame f(1, 1, reversedZ);
    glm::mat4 view(1.0f);  // world ±y -> view -z
    view[1] = glm::vec4(0.0f, 0.0f, up ? -1.0f : 1.0f, 0.0f);
    view[2] = glm::vec4(0.0f, up ? 1.0f : -1.0f, 0.0f, 0.0f);
    f.in.camera.view = view;
    f.in.camera.position = {1e5, 30.0, -2e5};
    f.in.sun.illuminance = glm::vec3(0.0f);
    f.in.settings.density = 0.05f;
    f.in.settings.heightFalloff = 0.1f;
    f.in.settings.baseHeight = 2.0f;
    f.in.settings.maxDistance = maxDistance;
    f.in.stepsPerPixel = 4096;
    std::fill(f.color.begin(), f.color.end(), 1.0f);
    if (std::isfinite(d)) f.setWall([d](uint32_t, uint32_t) { return d; });
    return {f.render()[0], std::isfinite(d) ? f.surfaceDistance(0, 0) : d};
}

// T = exp(-density·h0·(1 - e^{-a·D})/a), a = height_falloff·d.y, h0 = h(camera height).
double heightFogTransmittance(double dy, double d) {
    const double k = double(0.1f), h0 = std::exp(-k * (30.0 - 2.0)), a = k * dy;
    return std::exp(-double(0.05f) * h0 * -std::expm1(-a * d) / a);
}

TEST(FogReference, HeightFogOpticalDepthAlongVerticalRays) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    for (bool reversedZ : {true, false}) {
        for (bool up : {true, false}) {
            const double d = up ? 20.0 : 25.0, dy = up ? 1.0 : -1.0;
            // Marched (4096 midpoint steps: relative error of τ ~ (a·Δ)²/24 ~ 1e-8).
            Vertical r = verticalRay(up, d, 200.0f, reversedZ);
            expectRel(r.t, heightFogTransmittance(dy, r.distance), 1e-6, "marched");
            // Mostly analytic tail (max_distance 3 m): exact.
            r = verticalRay(up, d, 3.0f, reversedZ);
            expectRel(r.t, heightFogTransmittance(dy, r.distance), 1e-6, "tail");
        }
    }
    // No geometry, looking up: the tail reaches infinity, τ = density·h0/height_falloff.
    const double k = double(0.1f), h0 = std::exp(-k * 28.0);
    expectRel(verticalRay(true, kInf, 3.0f, true).t, std::exp(-double(0.05f) * h0 / k), 1e-6,
              "infinite tail");
    // Looking down into ever denser fog with no geometry: opaque.
    EXPECT_EQ(verticalRay(false, kInf, 3.0f, true).t, 0.0);
}

// --- 4. Ambient only ------------------------------------------------------------------------------------

TEST(FogReference, AmbientOnlyInHomogeneousFog) {
    Frame f(6, 6);
    f.in.sun.illuminance = glm::vec3(0.0f);
    f.in.ambient = {0.5f, 1.0f, 2.0f};
    f.setWall([](uint32_t i, uint32_t j) { return 5.0 + 11.0 * i + 2.0 * j; });
    const std::vector<float> out = f.render();
    for (uint32_t j = 0; j < f.h; ++j)
        for (uint32_t i = 0; i < f.w; ++i)
            for (int c = 0; c < 3; ++c) {
                const double t = std::exp(-double(f.in.settings.density) * f.surfaceDistance(i, j));
                expectRel(out[(j * f.w + i) * 4 + c], f.in.settings.albedo[c] * f.in.ambient[c] * (1.0 - t),
                          1e-6, "albedo·A·(1 - T)");
            }
}

// --- 5. Analytic tail -----------------------------------------------------------------------------------

TEST(FogReference, AnalyticTailCompletesTheInfiniteHomogeneousMedium) {
    for (bool tail : {true, false}) {
        Frame f(5, 4);  // depth = far value everywhere: no geometry
        f.in.ambient = {0.3f, 0.2f, 0.1f};
        f.in.settings.maxDistance = 10.0f;
        f.in.settings.analyticTail = tail;
        const std::vector<float> out = f.render();
        const double opacity = tail ? 1.0 : 1.0 - std::exp(-double(f.in.settings.density) * 10.0);
        for (uint32_t j = 0; j < f.h; ++j)
            for (uint32_t i = 0; i < f.w; ++i)
                for (int c = 0; c < 3; ++c) {
                    const double light = f.in.sun.illuminance[c] * f.phase(i, j) + f.in.ambient[c];
                    expectRel(out[(j * f.w + i) * 4 + c], f.in.settings.albedo[c] * light * opacity, 1e-6,
                              tail ? "tail on" : "tail off");
                }
    }
}

// --- 6. Self-shadowing ----------------------------------------------------------------------------------

TEST(FogReference, SelfShadowDimsTheSunAndRemovesItBelowTheHorizon) {
    Frame f(6, 6);
    f.in.camera.position = {0.0, 5.0, 0.0};
    f.in.settings.heightFalloff = 0.05f;
    f.in.settings.density = 0.1f;
    f.in.settings.maxDistance = 40.0f;
    f.in.ambient = {0.1f, 0.1f, 0.1f};
    f.in.sun.toSun = glm::normalize(glm::vec3(0.2f, 0.6f, -0.7f));
    f.setWall([](uint32_t i, uint32_t) { return i < 3 ? 20.0 + i : 500.0; });  // some pixels with a tail
    f.in.settings.selfShadow = false;
    const std::vector<float> off = f.render();
    f.in.settings.selfShadow = true;
    const std::vector<float> on = f.render();
    for (size_t p = 0; p < off.size(); p += 4)
        for (int c = 0; c < 3; ++c)
            EXPECT_LT(on[p + c], off[p + c]) << p / 4;

    // Sun below the horizon: Tsun = 0, only the ambient light remains (and exactly the render without sun).
    f.in.sun.toSun = glm::normalize(glm::vec3(0.2f, -0.3f, -0.7f));
    const std::vector<float> below = f.render();
    f.in.sun.illuminance = glm::vec3(0.0f);
    const std::vector<float> ambientOnly = f.render();
    for (size_t p = 0; p < below.size(); ++p)
        EXPECT_EQ(below[p], ambientOnly[p]) << p;
    for (size_t p = 0; p < below.size(); p += 4)
        EXPECT_GT(below[p], 0.0f);
}

// --- 7. Shadow map --------------------------------------------------------------------------------------

TEST(FogReference, ShadowMapComparisonAndKernel) {
    // Sun straight up; the 4x4 map covers world x ∈ [-5, 5], z ∈ [-10, 10]; depth z = (20 - y)/40. Columns
    // 0-1 (x < 0) hold an occluder at y = 10 (stored 0.25), columns 2-3 nothing (stored 1).
    Frame f(8, 8);
    f.in.sun.toSun = {0.0f, 1.0f, 0.0f};
    f.in.sun.illuminance = glm::vec3(1.0f);
    f.in.settings.maxDistance = 10.0f;
    f.in.settings.analyticTail = false;
    f.shadow.resize(16);
    for (int t = 0; t < 16; ++t)
        f.shadow[t] = (t % 4) < 2 ? 0.25f : 1.0f;
    f.in.shadowWidth = f.in.shadowHeight = 4;
    glm::dmat4 m(0.0);
    m[0][0] = 0.2;  // clip x = x/5
    m[2][1] = 0.1;  // clip y = z/10
    m[1][2] = -1.0 / 40.0;
    m[3][2] = 0.5;  // clip z = (20 - y)/40
    m[3][3] = 1.0;
    // The camera away from the origin; the map follows it (the march looks up camera + x).
    f.in.camera.position = {100.0, 0.0, 50.0};
    f.in.shadowWorldToClip = m * glm::translate(glm::dmat4(1.0), -f.in.camera.position);

    f.in.settings.shadowKernel = 1;
    const std::vector<float> k1 = f.render();
    f.in.settings.shadowKernel = 3;
    const std::vector<float> k3 = f.render();
    const double opacity = 1.0 - std::exp(-double(f.in.settings.density) * 10.0);
    for (uint32_t j = 0; j < f.h; ++j) {
        for (uint32_t i = 0; i < f.w; ++i) {
            const size_t p = (j * f.w + i) * 4;
            if (i < 4) {
                EXPECT_EQ(k1[p], 0.0f) << i << "," << j;  // x < 0 all along the ray: fully shadowed
            } else {
                expectRel(k1[p], f.phase(i, j) * f.in.settings.albedo[0] * opacity, 1e-6, "lit half");
            }
        }
        const size_t row = j * f.w * 4;
        EXPECT_GT(k3[row + 3 * 4], k1[row + 3 * 4]);  // left of the boundary: the kernel reaches lit texels
        EXPECT_LT(k3[row + 4 * 4], k1[row + 4 * 4]);  // right of it: it reaches shadowed ones
        EXPECT_LT(k3[row + 0], k3[row + 3 * 4]);
    }
}

TEST(FogReference, ShadowVisibilityBoundaryOutsideAndRowOrder) {
    using postfx::reference::detail::ShadowMap;
    using postfx::reference::detail::shadowVisibility;
    const float below = std::nextafter(0.25f, 0.0f), above = std::nextafter(0.75f, 1.0f);
    float texel = 0.25f;
    ShadowMap map{std::span<const float>(&texel, 1), 1, 1, glm::dmat4(1.0), false, 0.25, 1};
    const glm::dvec3 x(0.0, 0.0, 0.5);         // uv (0.5, 0.5), z 0.5
    EXPECT_EQ(shadowVisibility(map, x), 1.0);  // z - bias == stored: lit
    texel = below;
    EXPECT_EQ(shadowVisibility(map, x), 0.0);
    map.reversedZ = true;
    texel = 0.75f;
    EXPECT_EQ(shadowVisibility(map, x), 1.0);  // z + bias == stored: lit
    texel = above;
    EXPECT_EQ(shadowVisibility(map, x), 0.0);
    EXPECT_EQ(shadowVisibility(map, {1.5, 0.0, 0.5}), 1.0);  // outside uv
    EXPECT_EQ(shadowVisibility(map, {0.0, 0.0, 1.5}), 1.0);  // before the near plane (reversed Z)
    map.depth = {};
    EXPECT_EQ(shadowVisibility(map, x), 1.0);  // no map

    // Row 0 is at v = 0 (clip y = -1).
    const float rows[2] = {0.0f, 1.0f};
    ShadowMap tall{rows, 1, 2, glm::dmat4(1.0), false, 0.0, 1};
    EXPECT_EQ(shadowVisibility(tall, {0.0, -0.5, 0.5}), 0.0);
    EXPECT_EQ(shadowVisibility(tall, {0.0, 0.5, 0.5}), 1.0);
    // Kernel 3 on the 1x2 map: texel indices clamped, 6 of 9 taps on row 0 at v < 0.5.
    tall.kernel = 3;
    EXPECT_DOUBLE_EQ(shadowVisibility(tall, {0.0, -0.5, 0.5}), 3.0 / 9.0);
}

// The map's depth range: beyond the far plane a tap is in shadow where its texel holds a caster (is not
// the cleared far value) and lit where it does not, whatever the bias; before the near plane every tap is
// lit, casters or not; inside [0, 1] the comparison decides (fog.md, "Shadow-map visibility").
TEST(FogReference, ShadowVisibilityOutsideTheDepthRange) {
    using postfx::reference::detail::ShadowMap;
    using postfx::reference::detail::shadowVisibility;
    float texel = 0.25f;  // a caster
    ShadowMap map{std::span<const float>(&texel, 1), 1, 1, glm::dmat4(1.0), false, 0.0, 1};
    const glm::dvec3 beyondFar(0.0, 0.0, 1.5), beforeNear(0.0, 0.0, -0.5), atFar(0.0, 0.0, 1.0);
    EXPECT_EQ(shadowVisibility(map, beyondFar), 0.0);   // under a caster: shadowed (was lit before)
    EXPECT_EQ(shadowVisibility(map, beforeNear), 1.0);  // between the sun and the map: lit
    EXPECT_EQ(shadowVisibility(map, atFar), 0.0);       // inside: 1 > 0.25
    map.bias = 1.0;                                     // a bias reaching past the caster ...
    EXPECT_EQ(shadowVisibility(map, atFar), 1.0);       // ... lights it inside the range,
    EXPECT_EQ(shadowVisibility(map, beyondFar), 0.0);   // not beyond the far plane
    map.bias = 0.0;
    texel = 1.0f;  // cleared: nothing along the texel's column
    EXPECT_EQ(shadowVisibility(map, beyondFar), 1.0);
    EXPECT_EQ(shadowVisibility(map, beforeNear), 1.0);
    EXPECT_EQ(shadowVisibility(map, atFar), 1.0);
    texel = std::nextafter(1.0f, 0.0f);  // the farthest caster the map can hold
    EXPECT_EQ(shadowVisibility(map, beyondFar), 0.0);

    // Reversed Z: far is 0, near is 1, cleared is 0.
    map.reversedZ = true;
    texel = 0.75f;
    EXPECT_EQ(shadowVisibility(map, {0.0, 0.0, -0.5}), 0.0);  // beyond the far plane, under a caster
    EXPECT_EQ(shadowVisibility(map, {0.0, 0.0, 1.5}), 1.0);   // before the near plane
    EXPECT_EQ(shadowVisibility(map, {0.0, 0.0, 0.0}), 0.0);   // inside: 0 < 0.75
    texel = 0.0f;
    EXPECT_EQ(shadowVisibility(map, {0.0, 0.0, -0.5}), 1.0);
    texel = std::nextafter(0.0f, 1.0f);
    EXPECT_EQ(shadowVisibility(map, {0.0, 0.0, -0.5}), 0.0);

    // Per tap: a 3×1 map of caster, cleared, caster under a 3×3 kernel at the middle texel, beyond the
    // far plane: the cleared column's 3 taps are lit, the casters' 6 shadowed.
    for (const bool reversed : {false, true}) {
        const float caster = reversed ? 0.75f : 0.25f, cleared = reversed ? 0.0f : 1.0f;
        const float row[3] = {caster, cleared, caster};
        const ShadowMap wide{row, 3, 1, glm::dmat4(1.0), reversed, 0.0, 3};
        EXPECT_DOUBLE_EQ(shadowVisibility(wide, {0.0, 0.0, reversed ? -0.5 : 1.5}), 3.0 / 9.0) << reversed;
        EXPECT_EQ(shadowVisibility(wide, {0.0, 0.0, reversed ? 1.5 : -0.5}), 1.0) << reversed;
    }
}

// --- 8. Noise -------------------------------------------------------------------------------------------

TEST(FogReference, NoiseThresholdAndMultiplier) {
    Frame f(4, 4);
    f.in.ambient = glm::vec3(1.0f);
    f.in.settings.noise.enabled = true;
    f.in.noiseSize = 4;
    f.noise.assign(64, 0.5f);
    for (size_t p = 0; p < f.color.size(); ++p)
        f.color[p] = 0.3f + 0.01f * float(p);
    // Surfaces within max_distance: the analytic tail (which has no noise) adds nothing.
    f.setWall([](uint32_t i, uint32_t j) { return 3.0 + 5.0 * i + j; });
    f.in.settings.noise.threshold = 0.6f;  // above every texel: no fog
    EXPECT_EQ(f.render(), f.color);
    f.in.settings.noise.threshold = 0.1f;
    f.in.settings.noise.multiplier = 0.0f;
    EXPECT_EQ(f.render(), f.color);

    // A constant texture scales σt by clamp(n - threshold, 0, 1)·multiplier = 0.5·3.
    std::fill(f.color.begin(), f.color.end(), 0.0f);
    f.noise.assign(64, 0.75f);
    f.in.settings.noise.threshold = 0.25f;
    f.in.settings.noise.multiplier = 3.0f;
    f.in.settings.noise.wind = {1.0f, 2.0f, 3.0f};
    f.in.timeSeconds = 12.5;
    const std::vector<float> out = f.render();
    for (uint32_t j = 0; j < f.h; ++j)
        for (uint32_t i = 0; i < f.w; ++i) {
            const double t = std::exp(-1.5 * double(f.in.settings.density) * f.surfaceDistance(i, j));
            for (int c = 0; c < 3; ++c) {
                const double light = f.in.sun.illuminance[c] * f.phase(i, j) + 1.0;
                expectRel(out[(j * f.w + i) * 4 + c], f.in.settings.albedo[c] * light * (1.0 - t), 1e-6,
                          "noise 1.5");
            }
        }
}

TEST(FogReference, NoiseTrilinearRepeat) {
    using postfx::reference::detail::sampleNoise;
    // Texel (x, y, z) at index x + 2·(y + 2·z).
    const std::vector<float> v = {0.05f, 0.15f, 0.3f, 0.45f, 0.5f, 0.65f, 0.8f, 0.95f};
    auto at = [&](int x, int y, int z) { return double(v[x + 2 * (y + 2 * z)]); };
    // Texel centres.
    EXPECT_DOUBLE_EQ(sampleNoise(v, 2, {0.25, 0.25, 0.25}), at(0, 0, 0));
    EXPECT_DOUBLE_EQ(sampleNoise(v, 2, {0.75, 0.25, 0.75}), at(1, 0, 1));
    // Halfway between texels 0 and 1 in x, inside and across the repeat boundary (u = 0 ≡ 1).
    EXPECT_NEAR(sampleNoise(v, 2, {0.5, 0.25, 0.25}), 0.5 * (at(0, 0, 0) + at(1, 0, 0)), 1e-15);
    EXPECT_NEAR(sampleNoise(v, 2, {0.0, 0.75, 0.25}), 0.5 * (at(1, 1, 0) + at(0, 1, 0)), 1e-15);
    // A generic point: s = u·2 - 0.5 = (1.3, -0.3, 0.7): x between texels 1 and 0 (wrapped) with weight 0.3
    // on texel 0; y between texels 1 (wrapped from -1) and 0, weight 0.7 on texel 0; z between 0 and 1,
    // weight 0.7 on texel 1.
    double expected = 0.0;
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
            for (int c = 0; c < 2; ++c) {
                const double wx = a ? 0.3 : 0.7, wy = b ? 0.7 : 0.3, wz = c ? 0.7 : 0.3;
                expected += wx * wy * wz * at(a ? 0 : 1, b ? 0 : 1, c ? 1 : 0);
            }
    EXPECT_NEAR(sampleNoise(v, 2, {0.9, 0.1, 0.6}), expected, 1e-14);
    // Repeat: any whole number of periods, negative too.
    EXPECT_NEAR(sampleNoise(v, 2, {-0.1, 3.1, -4.4}), expected, 1e-14);
}

TEST(FogReference, NoiseFollowsWorldPositionWindAndTiling) {
    // u = (camera + x - wind·time) · 0.01 · tiling: moving the camera against the wind is the same as
    // letting time pass, and moving it by whole texture periods (100/tiling m) changes nothing.
    Frame f(8, 8);
    f.in.ambient = glm::vec3(0.5f);
    f.in.settings.density = 0.1f;
    f.in.settings.maxDistance = 30.0f;
    f.in.settings.analyticTail = false;
    f.in.settings.noise.enabled = true;
    f.in.settings.noise.tiling = 4.0f;  // period 25 m
    f.in.settings.noise.threshold = 0.0f;
    f.in.settings.noise.wind = {2.0f, 0.5f, -1.0f};
    f.in.noiseSize = 8;
    f.noise.resize(8 * 8 * 8);
    for (size_t t = 0; t < f.noise.size(); ++t)
        f.noise[t] = float((t * 37) % 101) / 100.0f;
    f.in.camera.position = {3.0, 1.0, -2.0};
    f.in.timeSeconds = 1.5;
    const std::vector<float> windy = f.render();
    f.in.camera.position -= glm::dvec3(f.in.settings.noise.wind) * 1.5;
    f.in.timeSeconds = 0.0;
    const std::vector<float> moved = f.render();
    f.in.camera.position += glm::dvec3(25.0, -75.0, -50.0);
    const std::vector<float> periods = f.render();
    f.in.camera.position.x += 12.5;
    const std::vector<float> half = f.render();
    double change = 0.0;
    for (size_t p = 0; p < windy.size(); ++p) {
        expectRel(moved[p], windy[p], 1e-6, "wind·time");
        expectRel(periods[p], windy[p], 1e-6, "whole periods");
        change += std::abs(half[p] - windy[p]);
    }
    EXPECT_GT(change / windy.size(), 1e-3);  // half a period: a different field
}

// --- 9-11. Determinism, validation, convergence -------------------------------------------------------

// A 16x16 frame with everything on: noisy height fog, shadow map, self shadow, tail, walls and sky.
Frame busyFrame() {
    Frame f(16, 16);
    f.in.camera.position = {12.0, 4.0, -30.0};
    f.in.camera.view = glm::mat4(glm::mat3(glm::rotate(glm::mat4(1.0f), 0.4f, glm::vec3(0.2f, 1.0f, 0.0f))));
    f.in.ambient = {0.2f, 0.25f, 0.3f};
    f.in.timeSeconds = 7.0;
    f.in.settings.heightFalloff = 0.08f;
    f.in.settings.density = 0.05f;
    f.in.settings.maxDistance = 120.0f;
    f.in.settings.selfShadow = true;
    f.in.settings.noise.enabled = true;
    f.in.settings.noise.tiling = 2.0f;
    f.in.settings.noise.threshold = 0.2f;
    f.in.settings.noise.wind = {1.5f, 0.0f, -0.5f};
    f.in.noiseSize = 16;
    f.noise.resize(16 * 16 * 16);
    uint32_t state = 12345;
    for (float& n : f.noise) {
        state = state * 1664525u + 1013904223u;
        n = float(state >> 8) / float(1 << 24);
    }
    f.shadow.resize(32 * 32);
    for (size_t t = 0; t < f.shadow.size(); ++t)
        f.shadow[t] = ((t / 32) / 6 + (t % 32) / 5) % 2 ? 0.3f : 1.0f;
    f.in.shadowWidth = f.in.shadowHeight = 32;
    f.in.shadowWorldToClip =
        glm::dmat4(glm::orthoRH_ZO(-60.0f, 60.0f, -60.0f, 60.0f, -50.0f, 50.0f)) *
        glm::dmat4(glm::lookAt(glm::vec3(10, 10, -30), glm::vec3(0), glm::vec3(0, 1, 0)));
    f.setWall([](uint32_t i, uint32_t j) { return j < 8 ? 600.0 : 15.0 + 10.0 * i; });
    for (uint32_t i = 0; i < 16; ++i)
        f.depth[i] = 0.0f;  // top row: sky
    return f;
}

TEST(FogReference, OutputIndependentOfThreadCount) {
    Frame f = busyFrame();
    f.in.stepsPerPixel = 128;
    f.in.threads = 1;
    const std::vector<float> one = f.render();
    f.in.threads = 4;
    const std::vector<float> four = f.render();
    ASSERT_EQ(one.size(), four.size());
    EXPECT_EQ(std::memcmp(one.data(), four.data(), one.size() * sizeof(float)), 0);
}

TEST(FogReference, ValidationNamesTheField) {
    auto expectInvalid = [](Frame f, const char* field) {
        std::vector<float> out;
        const postfx::Status s = renderFog(f.inputs(), out);
        EXPECT_EQ(s.code, Result::InvalidArgument) << field;
        EXPECT_NE(s.message.find(field), std::string::npos) << s.message;
    };
    Frame ok(4, 4);
    Frame f = ok;
    f.in.settings.density = -1.0f;
    expectInvalid(f, "FrameInfo.fog.density");
    f = ok;
    f.in.settings.anisotropy = std::numeric_limits<float>::quiet_NaN();
    expectInvalid(f, "FrameInfo.fog.anisotropy");
    f = ok;
    f.depth.resize(12);
    expectInvalid(f, "FogInputs.depth: 12 values, expected 16");
    f = ok;
    f.color.resize(3);
    expectInvalid(f, "FogInputs.color");
    const float cloudTexels[3] = {1.0f, std::numeric_limits<float>::quiet_NaN(), 1.0f};
    f = ok;
    f.in.cloudShadow = std::span<const float>(cloudTexels, 3);
    f.in.cloudShadowWidth = f.in.cloudShadowHeight = 2;
    expectInvalid(f, "FogInputs.cloudShadow: 3 values, expected 4");
    f.in.cloudShadowWidth = 3;
    f.in.cloudShadowHeight = 1;
    expectInvalid(f, "FogInputs.cloudShadow: value 1 is not finite");
    f = ok;
    f.in.settings.noise.enabled = true;
    f.in.noiseSize = 4;
    f.noise.resize(63);
    expectInvalid(f, "FogInputs.noise");
    f = ok;
    f.shadow.resize(15);
    f.in.shadowWidth = f.in.shadowHeight = 4;
    expectInvalid(f, "FogInputs.shadowDepth");
    f = ok;
    f.in.camera.position.y = std::numeric_limits<double>::infinity();
    expectInvalid(f, "camera.position");
    f = ok;
    f.in.width = 0;
    expectInvalid(f, "FogInputs.width");

    // Disabled: the color comes back unchanged.
    f = ok;
    f.in.settings.enabled = false;
    for (size_t p = 0; p < f.color.size(); ++p)
        f.color[p] = float(p);
    EXPECT_EQ(f.render(), f.color);
}

// Relative RMSE of the fog (RGB) between renders with 1024 and 2048 steps per pixel.
double convergenceError(Frame& f) {
    f.in.threads = 0;
    f.in.stepsPerPixel = 1024;
    const std::vector<float> coarse = f.render();
    f.in.stepsPerPixel = 2048;
    const std::vector<float> fine = f.render();
    double err = 0.0, norm = 0.0, fog = 0.0;
    for (size_t p = 0; p < fine.size(); ++p) {
        if (p % 4 == 3) continue;
        err += (coarse[p] - fine[p]) * double(coarse[p] - fine[p]);
        norm += double(fine[p]) * fine[p];
        fog += std::abs(double(fine[p]) - f.color[p]);
    }
    EXPECT_GT(fog / (fine.size() * 0.75), 0.05);  // the frame really has fog in it
    return std::sqrt(err / norm);
}

TEST(FogReference, MarchConvergesWithStepCount) {
    // Noisy height fog with self shadow: the integrand is continuous along the ray, the midpoint march
    // converges at second order (~4e-6 here).
    Frame f = busyFrame();
    f.shadow.clear();
    EXPECT_LT(convergenceError(f), 1e-4);
    // With a shadow map V is piecewise constant along the ray (one depth comparison per texel), so the
    // march converges at first order only (~2e-4 here): shadowed references need many steps.
    Frame shadowed = busyFrame();
    EXPECT_LT(convergenceError(shadowed), 1e-3);
}

// The clouds' shadow map as the GPU samples it (shaders/common/cloud_shadow.glsl, a linear clamp-to-edge
// sampler): uv from the rows, 1 outside [0, 1]², bilinear between texel centres, edge texels clamped.
TEST(FogReference, CloudShadowVisibilityFiltersAndClampsLikeTheSampler) {
    using postfx::reference::detail::CloudShadowMap;
    using postfx::reference::detail::cloudShadowVisibility;
    // 2×2 texels over x, z ∈ [0, 100] m: uv = (x / 100, z / 100); row 0 at v = 0.
    const float texels[] = {0.2f, 0.4f, 0.6f, 0.8f};
    CloudShadowMap map{std::span<const float>(texels, 4), 2, 2, {0.01, 0.0, 0.0, 0.0}, {0.0, 0.0, 0.01, 0.0}};
    EXPECT_DOUBLE_EQ(cloudShadowVisibility(map, {25.0, 7.0, 25.0}), double(0.2f));  // texel (0, 0)'s centre
    EXPECT_DOUBLE_EQ(cloudShadowVisibility(map, {75.0, 0.0, 25.0}), double(0.4f));
    EXPECT_DOUBLE_EQ(cloudShadowVisibility(map, {25.0, 0.0, 75.0}), double(0.6f));  // row 1
    EXPECT_DOUBLE_EQ(cloudShadowVisibility(map, {50.0, 0.0, 50.0}),
                     0.25 * (double(0.2f) + double(0.4f) + double(0.6f) + double(0.8f)));
    EXPECT_DOUBLE_EQ(cloudShadowVisibility(map, {50.0, 0.0, 25.0}), 0.5 * (double(0.2f) + double(0.4f)));
    EXPECT_DOUBLE_EQ(cloudShadowVisibility(map, {0.0, 0.0, 0.0}), double(0.2f));  // the edge: clamped
    EXPECT_DOUBLE_EQ(cloudShadowVisibility(map, {100.0, 0.0, 100.0}), double(0.8f));
    EXPECT_EQ(cloudShadowVisibility(map, {-1.0, 0.0, 50.0}), 1.0);  // outside the map: no shadow
    EXPECT_EQ(cloudShadowVisibility(map, {50.0, 0.0, 101.0}), 1.0);
    map.texels = {};
    EXPECT_EQ(cloudShadowVisibility(map, {50.0, 0.0, 50.0}), 1.0);  // no map
}

// The clouds' shadow map dims the sun's in-scattering (the ambient's not): a map reading 0.25 wherever the
// rays go (constant rows: uv (0.5, 0.5) everywhere) gives a quarter of the marched sun-lit radiance.
TEST(FogReference, CloudShadowDimsTheSunOnly) {
    Frame f(8, 6);
    f.in.settings.analyticTail = false;  // the tail reads no cloud shadow (as on the GPU)
    const std::vector<float> lit = f.render();
    const float quarter[4] = {0.25f, 0.25f, 0.25f, 0.25f};
    f.in.cloudShadow = std::span<const float>(quarter, 4);
    f.in.cloudShadowWidth = f.in.cloudShadowHeight = 2;
    f.in.cloudShadowRows.u = {0.0, 0.0, 0.0, 0.5};
    f.in.cloudShadowRows.v = {0.0, 0.0, 0.0, 0.5};
    const std::vector<float> shadowed = f.render();
    ASSERT_EQ(lit.size(), shadowed.size());
    for (size_t i = 0; i < lit.size(); ++i) {
        if (i % 4 == 3) continue;
        ASSERT_GT(lit[i], 0.0f);
        EXPECT_NEAR(shadowed[i], 0.25 * lit[i], 1e-6 * lit[i]) << i;
    }
    f.in.ambient = glm::vec3(1.0f);  // the ambient's share is not dimmed
    f.in.sun.illuminance = glm::vec3(0.0f);
    const std::vector<float> ambient = f.render();
    f.in.cloudShadow = {};
    EXPECT_EQ(f.render(), ambient);
}

}  // namespace
