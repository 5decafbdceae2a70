// The atmosphere's Monte Carlo path tracer (atmosphere_path_tracer.h): against single scattering where
// multiple scattering vanishes, and the model's Ψ approximation against it at a zenith view and high sun.
// AtmospherePathTracerTable.DISABLED_PrintTable prints docs/effects/atmosphere.md's table (a minute or two).
#include "atmosphere/atmosphere_path_tracer.h"
#include "atmosphere/atmosphere_reference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

namespace {

using namespace postfx::atmosphere;

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

Sun sunToward(const glm::dvec3& toSun) {
    Sun s;
    s.toSun = toSun;
    s.illuminance = glm::dvec3(1.0);
    return s;
}

// An optically thin (1e-5 of Earth's) pure-Rayleigh atmosphere over a black ground: every order beyond the
// first is O(τ) ≈ 3e-6 of it (measured with 1e-3 of Earth's: MC exceeds single scattering by ≈ τ, as it
// should), so the path tracer must agree with single scattering (integrateViewRay, exact sun
// transmittance) within 4 standard errors plus 1e-4 (the quadratures and the tables: the zenith view with
// the sun at the zenith has all paths' first event equal, a standard error of ~1e-7).
TEST(AtmospherePathTracer, ThinRayleighMatchesSingleScattering) {
    Model m;
    m.rayleighScattering *= 1e-5;
    m.mieScattering = m.mieAbsorption = 0.0;
    m.ozoneAbsorption = glm::dvec3(0.0);
    m.groundAlbedo = glm::dvec3(0.0);
    TransmittanceTableOptions to;
    to.size = {128, 64};
    to.steps = 100;
    const TransmittanceTable transmittance(m, to);
    for (const ViewSunAngles a :
         {ViewSunAngles{0.0, 90.0, 0.0, 0.0}, ViewSunAngles{80.0, 30.0, 180.0, 1000.0},
          ViewSunAngles{45.0, 10.0, 0.0, 0.0}}) {
        const ViewSunRay ray = viewSunRay(m, a);
        PathTracerOptions po;
        po.paths = 20000;
        const auto start = std::chrono::steady_clock::now();
        const PathTracerResult mc =
            pathTraceViewRay(m, transmittance, ray.origin, ray.dir, sunToward(ray.toSun), po);
        const double time = seconds(start);
        ViewRayOptions vo;
        vo.steps = 2000;
        vo.transmittanceSteps = 400;
        vo.multipleScattering = false;
        const ViewRayResult ss = integrateViewRay(m, ray.origin, ray.dir, sunToward(ray.toSun), vo);
        for (int c = 0; c < 3; ++c) {
            const double diff = std::abs(mc.luminance[c] - ss.luminance[c]);
            const double z = diff / mc.standardError[c];
            std::printf(
                "[ measured ] view %g sun %g az %g: MC %.6g ± %.2g, single %.6g (rel. diff %.2g, %.3g "
                "sigma) %.2f s\n",
                a.viewZenithDeg, a.sunElevationDeg, a.relativeAzimuthDeg, mc.luminance[c],
                mc.standardError[c], ss.luminance[c], diff / ss.luminance[c], z, time);
            EXPECT_LT(diff, 4.0 * mc.standardError[c] + 1e-4 * ss.luminance[c]);
            EXPECT_LT(mc.standardError[c], 0.02 * mc.luminance[c]);
        }
    }
}

// Earth's defaults, camera on the ground looking at the zenith, sun 60° high: the model (single scattering
// plus σs·Ψ, Ψ from a table of 64 directions and 20 steps per node) against every order.
TEST(AtmospherePathTracer, EarthZenithHighSunModelNearPathTracer) {
    const Model m;
    const std::shared_ptr<const TransmittanceTable> transmittance = sharedTransmittanceTable(m);
    PsiTableOptions pso;
    pso.muSSize = 32;
    pso.heightSize = 32;
    pso.psi = {64, 20, 0};
    const PsiTable psi(m, *transmittance, pso);
    const ViewSunRay ray = viewSunRay(m, {0.0, 60.0, 0.0, 0.0});
    PathTracerOptions po;
    po.paths = 20000;
    const PathTracerResult mc =
        pathTraceViewRay(m, *transmittance, ray.origin, ray.dir, sunToward(ray.toSun), po);
    ViewRayOptions vo;
    vo.steps = 256;
    vo.transmittanceTable = transmittance.get();
    vo.psiTable = &psi;
    vo.ground = true;
    const ViewRayResult model = integrateViewRay(m, ray.origin, ray.dir, sunToward(ray.toSun), vo);
    vo.multipleScattering = false;
    const ViewRayResult single = integrateViewRay(m, ray.origin, ray.dir, sunToward(ray.toSun), vo);
    for (int c = 0; c < 3; ++c) {
        const double err = model.luminance[c] / mc.luminance[c] - 1.0;
        std::printf(
            "[ measured ] zenith, sun 60 deg, channel %d: MC %.5g ± %.2g, model %.5g (%+.2f %%), single "
            "%.5g (%+.2f %%)\n",
            c, mc.luminance[c], mc.standardError[c], model.luminance[c], 100.0 * err, single.luminance[c],
            100.0 * (single.luminance[c] / mc.luminance[c] - 1.0));
        EXPECT_LT(std::abs(err), 0.05);
    }
}

// The table of docs/effects/atmosphere.md, "The multiple-scattering approximation against a path tracer":
//   build/tests/unit_tests --gtest_also_run_disabled_tests
//       --gtest_filter=AtmospherePathTracerTable.DISABLED_PrintTable
// Earth's defaults; MC with every order (400 000 paths per channel); the model: single scattering plus σs·Ψ,
// Ψ from the reference's default table (64×64 nodes, 256 directions, 100 steps), 1024 steps along the view;
// single: single scattering only. Both with the lit ground where the view meets it.
TEST(AtmospherePathTracerTable, DISABLED_PrintTable) {
    const Model m;
    const auto start = std::chrono::steady_clock::now();
    const std::shared_ptr<const TransmittanceTable> transmittance = sharedTransmittanceTable(m);
    const std::shared_ptr<const PsiTable> psi = sharedPsiTable(m);
    std::printf("tables built in %.1f s\n", seconds(start));
    std::printf(
        "| sun elev. | view zenith | azimuth | altitude | MC R, G, B [cd/m² per lx] | MC std. err. | "
        "model − MC | single − MC |\n");
    std::printf("|---:|---:|---:|---:|---|---:|---|---|\n");
    for (double altitude : {0.0, 10000.0})
        for (double sunElevation : {90.0, 30.0, 10.0, 2.0, -2.0})
            for (double viewZenith : {0.0, 45.0, 80.0, 89.0, 95.0})
                for (double azimuth : {0.0, 180.0}) {
                    if (viewZenith == 0.0 && azimuth != 0.0) continue;
                    const ViewSunRay ray = viewSunRay(m, {viewZenith, sunElevation, azimuth, altitude});
                    PathTracerOptions po;
                    po.paths = 400000;
                    const PathTracerResult mc =
                        pathTraceViewRay(m, *transmittance, ray.origin, ray.dir, sunToward(ray.toSun), po);
                    ViewRayOptions vo;
                    vo.steps = 1024;
                    vo.transmittanceTable = transmittance.get();
                    vo.psiTable = psi.get();
                    vo.ground = true;
                    const ViewRayResult model =
                        integrateViewRay(m, ray.origin, ray.dir, sunToward(ray.toSun), vo);
                    vo.multipleScattering = false;
                    const ViewRayResult single =
                        integrateViewRay(m, ray.origin, ray.dir, sunToward(ray.toSun), vo);
                    double stderrPercent = 0.0;
                    for (int c = 0; c < 3; ++c)
                        stderrPercent =
                            std::max(stderrPercent, 100.0 * mc.standardError[c] / mc.luminance[c]);
                    const auto err = [&](const glm::dvec3& v, int c) {
                        return 100.0 * (v[c] / mc.luminance[c] - 1.0);
                    };
                    std::printf(
                        "| %g | %g | %g | %g km | %.3g, %.3g, %.3g | %.2f %% | %+.1f, %+.1f, %+.1f %% | "
                        "%+.1f, %+.1f, %+.1f %% |\n",
                        sunElevation, viewZenith, azimuth, altitude / 1000.0, mc.luminance.x, mc.luminance.y,
                        mc.luminance.z, stderrPercent, err(model.luminance, 0), err(model.luminance, 1),
                        err(model.luminance, 2), err(single.luminance, 0), err(single.luminance, 1),
                        err(single.luminance, 2));
                    std::fflush(stdout);
                }
    std::printf("total %.1f s\n", seconds(start));
}

}  // namespace
