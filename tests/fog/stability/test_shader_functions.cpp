// The fog's shader functions on their own (docs/stability.md, "Shader functions"): tables of hard inputs
// evaluated by postfx's own GLSL (shaders/common, shaders/common/medium/medium.glsl, composite.glsl) in one
// compute dispatch (tests/fog/stability/shaders/fog_functions.comp), each result against the double-precision
// model (postfx/src/common/reference_model.h) or the documented rule, to a stated tolerance, never NaN.
#include "common/reference_model.h"
#include "core/compute_pipeline.h"
#include "core/gpu_resources.h"
#include "fog_test_shaders_spirv.h"
#include "gpu_test.h"

#include <postfx/reference.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace test {
namespace {

// Must match fog_functions.comp.
enum Kind : uint32_t {
    kPhase,
    kOneMinusExp,
    kHeightTerm,
    kSunTransmittance,
    kTailDepth,
    kIgn,
    kComposite,
    kIntegrateStep,
};

struct FunctionCase {
    glm::vec4 a{0.0f};
    glm::vec4 b{0.0f};
    glm::vec4 c{0.0f};
    glm::uvec4 op{0u};
};
static_assert(sizeof(FunctionCase) == 64);

constexpr float kFloatMax = std::numeric_limits<float>::max();
constexpr double kUlp = 1.0 / (1 << 23);  // float's ulp at 1 (relative spacing is between this and half)

// Vulkan's precision for exp(x) (spec, "Precision of GLSL.std.450 instructions"): 3 + 2·|x| ULP.
double expTolerance(double x) {
    return (3.0 + 2.0 * std::abs(x)) * kUlp;
}

// The tolerance of 1 - e^{-x} computed as such (x >= 0.5) or by its series: the series' 8 rounded
// multiply-adds, or exp's own error grown by at most 1/(1 - e^{-0.5}).
double oneMinusExpTolerance(double x) {
    if (std::isinf(x)) return 8 * kUlp;
    return 8 * kUlp + expTolerance(x) * std::exp(-x) / std::max(-std::expm1(-x), 0.39);
}

class FogShaderFunctions : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        ASSERT_TRUE(host);
        ASSERT_TRUE(gpu.init(hostHandles()).ok());
    }

    // Evaluates every case on the GPU; one vec4 per case.
    std::vector<glm::vec4> evaluate(const std::vector<FunctionCase>& cases) {
        const VkDeviceSize inBytes = cases.size() * sizeof(FunctionCase), outBytes = cases.size() * 16;
        postfx::core::GpuBuffer input, output;
        EXPECT_TRUE(input.create(gpu, inBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true, "cases").ok());
        EXPECT_TRUE(output.create(gpu, outBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true, "results").ok());
        std::memcpy(input.mapped(), cases.data(), inBytes);

        const postfx::core::Binding bindings[] = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                                  {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
        postfx::core::ComputePipelineDesc pd;
        pd.name = "test.fog_functions";
        pd.spirv = fog_test_spirv::fog_functions_comp;
        pd.bindings = bindings;
        pd.pushConstantBytes = 4;
        postfx::core::ComputePipeline pipeline;
        const postfx::Status s = pipeline.create(gpu, pd);
        EXPECT_TRUE(s.ok()) << s.message;
        postfx::core::DescriptorArena arena;
        EXPECT_TRUE(arena.create(gpu, 1).ok());
        EXPECT_TRUE(arena.beginFrame().ok());
        VkDescriptorSet set = VK_NULL_HANDLE;
        EXPECT_TRUE(arena.allocate(pipeline.setLayout(), set).ok());
        postfx::core::DescriptorWrites(set)
            .storageBuffer(0, input.handle(), 0, VK_WHOLE_SIZE)
            .storageBuffer(1, output.handle(), 0, VK_WHOLE_SIZE)
            .apply(gpu);
        std::string error;
        EXPECT_TRUE(host->submitAndWait(
            [&](VkCommandBuffer cmd) {
                const uint32_t count = uint32_t(cases.size());
                pipeline.bind(cmd, set, &count);
                gpu.fn.vkCmdDispatch(cmd, (count + 63) / 64, 1, 1);
                VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
                toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
                toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
                vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                                     1, &toHost, 0, nullptr, 0, nullptr);
            },
            error))
            << error;
        std::vector<glm::vec4> results(cases.size());
        std::memcpy(results.data(), output.mapped(), outBytes);
        return results;
    }

    postfx::core::Gpu gpu;
};

// Tracks the worst relative error of a table and reports the first failure with its inputs.
struct Check {
    const char* what;
    double worst = 0.0;
    int failures = 0;
    std::string first;

    // |gpu - expected| <= tolerance · |expected| + absolute; NaN never passes; ±Inf only equals itself.
    void near(double gpu, double expected, double tolerance, double absolute, const std::string& inputs) {
        bool ok;
        if (std::isnan(gpu) || std::isnan(expected)) {
            ok = false;
        } else if (std::isinf(expected) || std::isinf(gpu)) {
            ok = gpu == expected;
        } else {
            const double diff = std::abs(gpu - expected);
            ok = diff <= tolerance * std::abs(expected) + absolute;
            if (std::abs(expected) > absolute) worst = std::max(worst, diff / std::abs(expected));
        }
        if (!ok && failures++ == 0) {
            std::ostringstream s;
            s.precision(9);
            s << what << "(" << inputs << ") = " << gpu << ", expected " << expected << " (tolerance "
              << tolerance << " relative + " << absolute << ")";
            first = s.str();
        }
    }
    void expectPassed() const {
        EXPECT_EQ(failures, 0) << failures << " failures, first: " << first;
        std::printf("[ stability ] %s: worst relative error %.3g\n", what, worst);
    }
};

std::string args(std::initializer_list<double> values) {
    std::ostringstream s;
    s.precision(9);
    bool first = true;
    for (double v : values) {
        s << (first ? "" : ", ") << v;
        first = false;
    }
    return s.str();
}

// x = 1e-30 … 1e3 (8 per decade), the series/exp boundary 0.5 on both sides, 0 and +Inf.
std::vector<float> opticalDepths() {
    std::vector<float> xs = {0.0f, 0.4999999f, 0.5f, 0.5000001f, std::numeric_limits<float>::infinity()};
    for (int i = -240; i <= 24; ++i)
        xs.push_back(float(std::pow(10.0, i / 8.0)));
    return xs;
}

// Henyey–Greenstein at |g| up to 0.999 along (cos θ = 1), against (-1) and near the light direction: the
// peak of 0.999 is 1.6e5 /sr, where 1 + g² - 2g·cosθ would cancel in float.
TEST_F(FogShaderFunctions, PhaseMatchesDoublePrecision) {
    const float gs[] = {-0.999f, -0.99f, -0.6f, 0.0f, 0.3f, 0.6f, 0.99f, 0.999f};
    const double angles[] = {0.0, 1e-4, 1e-3, 0.01, 0.1, 0.5, 1.0, 1.5707963, 2.5, 3.1, 3.14159265};
    std::vector<FunctionCase> cases;
    for (float g : gs) {
        for (double angle : angles) {
            FunctionCase c;
            c.op.x = kPhase;
            c.a = glm::vec4(float(std::sin(angle)), 0.0f, float(std::cos(angle)), 0.0f);  // view direction
            c.b = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f);                                      // toward the light
            c.c.x = g;
            cases.push_back(c);
        }
    }
    const std::vector<glm::vec4> r = evaluate(cases);
    Check check{"henyeyGreensteinDirections"};
    for (size_t i = 0; i < cases.size(); ++i) {
        // The model's phase of the two (float, so not exactly unit) directions, evaluated in double:
        // cos θ of the normalised directions, and 1 - |cos θ| as |d̂ ∓ l̂|²/2 so that double keeps it.
        const double g = cases[i].c.x;
        const glm::dvec3 d = glm::normalize(glm::dvec3(cases[i].a)),
                         l = glm::normalize(glm::dvec3(cases[i].b));
        const glm::dvec3 diff = d - (g < 0.0 ? -l : l);
        const double denom = (1.0 - std::abs(g)) * (1.0 - std::abs(g)) + std::abs(g) * glm::dot(diff, diff);
        const double expected = (1.0 - g * g) / (4.0 * std::numbers::pi * denom * std::sqrt(denom));
        // Float rounding of |d ∓ l|² (absolute ~2 ulp of 2, relative to denom) and of the unit lengths of
        // the inputs (1 ulp each), through the 3/2 power; plus a few roundings of the rest.
        const double conditioning = 1.5 * std::abs(g) * 6.0 * kUlp / denom;
        check.near(r[i].x, expected, conditioning + 8 * kUlp, 0.0, args({g, glm::dot(d, l)}));
        // Where the inputs are exactly unit (the peaks), the classic formula agrees.
        if (cases[i].a.x == 0.0f) {
            const double classic = postfx::reference::henyeyGreenstein(glm::dot(d, l), g);
            check.near(r[i].x, classic, 16 * kUlp, 0.0, args({g, glm::dot(d, l)}) + " (classic form)");
        }
    }
    check.expectPassed();
}

// 1 - e^{-x} and (1 - e^{-x})/x over 33 decades: no cancellation anywhere (at x = 1e-4 the direct
// formula keeps ~11 bits), the exact limits at 0 and +Inf.
TEST_F(FogShaderFunctions, OneMinusExpKeepsFloatPrecisionAtEveryScale) {
    std::vector<FunctionCase> cases;
    for (float x : opticalDepths()) {
        FunctionCase c;
        c.op.x = kOneMinusExp;
        c.a.x = x;
        cases.push_back(c);
    }
    const std::vector<glm::vec4> r = evaluate(cases);
    Check value{"oneMinusExp"}, ratio{"oneMinusExpOverX"};
    for (size_t i = 0; i < cases.size(); ++i) {
        const double x = cases[i].a.x;
        const double expected = -std::expm1(-x);
        const double expectedRatio = x == 0.0 ? 1.0 : (std::isinf(x) ? 0.0 : expected / x);
        const double tolerance = oneMinusExpTolerance(x);
        value.near(r[i].x, expected, tolerance, 0.0, args({x}));
        ratio.near(r[i].y, expectedRatio, tolerance, 1e-45, args({x}));
    }
    value.expectPassed();
    ratio.expectPassed();
}

// The medium's height term, its closed-form sun transmittance and the analytic tail's optical depth at
// heights from -1e6 to 1e6 m, falloffs 0 to 10 /m, sun from the zenith to below the horizon, rays climbing,
// level and descending, lengths 1 mm to infinity.
TEST_F(FogShaderFunctions, HeightFogTermsMatchDoublePrecision) {
    const float heights[] = {-1e6f, -1e3f, -8.0f, 0.0f, 0.5f, 10.0f, 300.0f, 1e3f, 1e5f, 1e6f};
    const float falloffs[] = {0.0f, 1e-3f, 0.1f, 10.0f};
    const float densities[] = {1e-12f, 0.02f, 1e6f};
    const float sunYs[] = {1.0f, 0.3f, 1e-6f, 0.0f, -0.5f};
    const float dirYs[] = {-1.0f, -0.5f, -1e-3f, -1e-7f, 0.0f, 1e-7f, 1e-3f, 0.5f, 1.0f};
    // 1e38: a finite length where density · len and a · len overflow float (fog.md, "Analytic tail").
    const float lengths[] = {1e-3f, 1.0f, 100.0f, 1e4f, 1e7f, 1e38f, std::numeric_limits<float>::infinity()};
    std::vector<FunctionCase> cases;
    for (float y : heights) {
        for (float k : falloffs) {
            FunctionCase h;
            h.op.x = kHeightTerm;
            h.a.x = y;
            h.c.y = k;
            cases.push_back(h);
            for (float density : densities) {
                for (float sunY : sunYs) {
                    FunctionCase s = h;
                    s.op.x = kSunTransmittance;
                    s.b.y = sunY;
                    s.c.x = density;
                    cases.push_back(s);
                }
                for (float dirY : dirYs) {
                    for (float len : lengths) {
                        FunctionCase t = h;
                        t.op.x = kTailDepth;
                        t.a.y = dirY;
                        t.a.z = len;
                        t.c.x = density;
                        cases.push_back(t);
                    }
                }
            }
        }
    }
    const std::vector<glm::vec4> r = evaluate(cases);
    namespace detail = postfx::reference::detail;
    Check height{"heightTerm"}, sun{"sunTransmittance"}, tail{"heightFogOpticalDepth"};
    for (size_t i = 0; i < cases.size(); ++i) {
        const FunctionCase& c = cases[i];
        const double y = c.a.x, k = c.c.y, density = c.c.x;
        const double exponent = detail::heightExponent(y, k, 0.0);
        // Results below float's smallest normal may be flushed to 0.
        constexpr double kDenormal = 1.2e-38;
        switch (c.op.x) {
            case kHeightTerm:
                height.near(r[i].x, std::exp(exponent), expTolerance(exponent), kDenormal, args({y, k}));
                break;
            case kSunTransmittance: {
                const double expected = detail::sunTransmittance(density, std::exp(exponent), k, c.b.y);
                // τsun = density·h/(k·toSun.y) carries h's error; exp(-τ) multiplies it by τ.
                const double tau = expected > 0.0 ? -std::log(expected) : 0.0;
                const double tolerance = expTolerance(tau) + tau * (expTolerance(exponent) + 4 * kUlp);
                sun.near(r[i].x, expected, tolerance, kDenormal, args({y, k, density, c.b.y}));
                break;
            }
            case kTailDepth: {
                const double dirY = c.a.y, len = c.a.z;
                double expected = detail::tailOpticalDepth(density, exponent, double(float(k * dirY)), len);
                if (expected > kFloatMax)
                    expected = std::numeric_limits<double>::infinity();  // overflows float
                // Two exps of half of exponent0 + max(-x, 0), the series or the exp of |x| (none for an
                // infinite length), a few roundings.
                const double x = std::isinf(len) ? 0.0 : k * dirY * len;
                const double tolerance =
                    expTolerance(exponent + std::max(-x, 0.0)) + expTolerance(std::abs(x)) + 16 * kUlp;
                tail.near(r[i].x, expected, tolerance, kDenormal, args({y, dirY, len, k, density}));
                break;
            }
        }
    }
    height.expectPassed();
    sun.expectPassed();
    tail.expectPassed();
}

// One step's in-scattering T · light · (1 - e^{-τ}) at transmittances, lights and optical depths from 0
// to the float range: finite, and the closed form.
TEST_F(FogShaderFunctions, IntegrateStepStaysFiniteAndExact) {
    const float transmittances[] = {0.0f, 1e-30f, 1e-3f, 1.0f};
    const float lights[] = {0.0f, 1.0f, 1e5f, 1e30f, kFloatMax};
    std::vector<FunctionCase> cases;
    for (float t : transmittances)
        for (float light : lights)
            for (float tau : opticalDepths()) {
                FunctionCase c;
                c.op.x = kIntegrateStep;
                c.a = glm::vec4(t, light, tau, 0.0f);
                cases.push_back(c);
            }
    const std::vector<glm::vec4> r = evaluate(cases);
    Check check{"integrateStep"};
    for (size_t i = 0; i < cases.size(); ++i) {
        const double t = cases[i].a.x, light = cases[i].a.y, tau = cases[i].a.z;
        const double expected = t * light * -std::expm1(-tau);
        const double tolerance = 4 * kUlp + oneMinusExpTolerance(tau);
        check.near(r[i].x, expected, tolerance, 1.2e-37, args({t, light, tau}));
    }
    check.expectPassed();
}

// Interleaved gradient noise: in [0, 1) and finite for pixels up to 16384 and every frame index up to
// 2^32 - 1 (the frame counter wraps).
TEST_F(FogShaderFunctions, InterleavedGradientNoiseStaysInTheUnitInterval) {
    std::vector<FunctionCase> cases;
    const uint32_t pixels[] = {0u, 1u, 7u, 1919u, 4095u, 16383u};
    const uint32_t frames[] = {0u, 1u, 63u, 64u, 1000003u, 0x7fffffffu, 0xffffffffu};
    for (uint32_t x : pixels)
        for (uint32_t y : pixels)
            for (uint32_t f : frames) {
                FunctionCase c;
                c.op = {kIgn, x, y, f};
                cases.push_back(c);
            }
    const std::vector<glm::vec4> r = evaluate(cases);
    for (size_t i = 0; i < cases.size(); ++i) {
        EXPECT_TRUE(r[i].x >= 0.0f && r[i].x < 1.0f) << "IGN(" << cases[i].op.y << ", " << cases[i].op.z
                                                     << ", frame " << cases[i].op.w << ") = " << r[i].x;
    }
}

// The composite over the host's color (docs/stability.md, "Host color"), RGBA16F variant: ±Inf counts as
// ±65504, the result is clamped to ±65504, NaN stays in its channel, negatives composite as given.
TEST_F(FogShaderFunctions, CompositeFollowsTheHostColorRule) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const float colors[] = {0.0f, 1.0f, -5.0f, 65504.0f, 1e9f, inf, -inf, nan};
    const float transmittances[] = {0.0f, 1e-6f, 0.5f, 1.0f};
    const float scattered[] = {0.0f, 3.0f, 65000.0f, 1e9f};
    std::vector<FunctionCase> cases;
    for (float color : colors)
        for (float t : transmittances)
            for (float l : scattered) {
                FunctionCase c;
                c.op.x = kComposite;
                c.a = glm::vec4(color, 2.0f, 0.0f, t);
                c.b = glm::vec4(l, l, 0.0f, 0.0f);
                cases.push_back(c);
            }
    const std::vector<glm::vec4> r = evaluate(cases);
    Check check{"compositeOver"};
    constexpr double kMax = 65504.0;
    for (size_t i = 0; i < cases.size(); ++i) {
        const double color = cases[i].a.x, t = cases[i].a.w, l = cases[i].b.x;
        const std::string in = args({color, t, l});
        if (std::isnan(color)) {
            EXPECT_TRUE(std::isnan(r[i].x)) << "NaN color must stay NaN: " << in;
        } else {
            const double expected = std::clamp(std::clamp(color, -kMax, kMax) * t + l, -kMax, kMax);
            check.near(r[i].x, expected, 2 * kUlp, 0.0, in);
        }
        // The other channels never see the first one's value.
        check.near(r[i].y, std::clamp(2.0 * t + l, -kMax, kMax), 2 * kUlp, 0.0, in + " (channel 1)");
        check.near(r[i].z, 0.0, 0.0, 0.0, in + " (channel 2)");
    }
    check.expectPassed();
}

}  // namespace
}  // namespace test
