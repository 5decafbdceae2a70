// The "orders" multiple-scattering model (atmosphere_orders.h) against the path tracer.
#include "atmosphere/atmosphere_orders.h"
#include "atmosphere/atmosphere_path_tracer.h"
#include "atmosphere/atmosphere_reference.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

namespace {

using namespace postfx::atmosphere;

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

uint32_t envOr(const char* name, uint32_t fallback) {
    const char* v = std::getenv(name);
    return v ? uint32_t(std::atoi(v)) : fallback;
}

TEST(AtmosphereOrders, DISABLED_Explore) {
    Model m;
    if (std::getenv("HAZY")) m.mieScattering *= 5.0, m.mieAbsorption *= 5.0;
    if (std::getenv("BLACK")) m.groundAlbedo = glm::dvec3(0.0);
    auto start = std::chrono::steady_clock::now();
    const std::shared_ptr<const TransmittanceTable> transmittance = sharedTransmittanceTable(m);
    const std::shared_ptr<const PsiTable> psi = sharedPsiTable(m);
    OrdersTableOptions oo;
    oo.radiusSize = envOr("NR", oo.radiusSize);
    oo.sunSize = envOr("NS", oo.sunSize);
    oo.viewSize = envOr("NV", oo.viewSize);
    oo.azimuthSize = envOr("NA", oo.azimuthSize);
    oo.directions = envOr("NK", oo.directions);
    oo.steps = envOr("STEPS", oo.steps);
    oo.orders = envOr("ORDERS", oo.orders);
    const OrdersTable orders(m, *transmittance, oo);
    std::printf("tables built in %.1f s\n", seconds(start));
    const uint64_t paths = envOr("PATHS", 100000);
    for (double altitude : {0.0, 1000.0, 10000.0, 100000.0, 400000.0})
        for (double sunElevation : {60.0, 10.0, 2.0, -2.0})
            for (double viewZenith : {0.0, 60.0, 85.0, 89.0, 95.0, 120.0})
                for (double azimuth : {0.0, 90.0, 180.0}) {
                    if (viewZenith == 0.0 && azimuth != 0.0) continue;
                    const ViewSunRay ray = viewSunRay(m, {viewZenith, sunElevation, azimuth, altitude});
                    Sun sun;
                    sun.toSun = ray.toSun;
                    PathTracerOptions po;
                    po.paths = paths;
                    const PathTracerResult mc =
                        pathTraceViewRay(m, *transmittance, ray.origin, ray.dir, sun, po);
                    ViewRayOptions vo;
                    vo.steps = 512;
                    vo.transmittanceTable = transmittance.get();
                    vo.psiTable = psi.get();
                    vo.ground = true;
                    const ViewRayResult hill = integrateViewRay(m, ray.origin, ray.dir, sun, vo);
                    vo.ordersTable = &orders;
                    const ViewRayResult ord = integrateViewRay(m, ray.origin, ray.dir, sun, vo);
                    double se = 0.0;
                    for (int c = 0; c < 3; ++c)
                        se = std::max(se, 100.0 * mc.standardError[c] / mc.luminance[c]);
                    const auto err = [&](const glm::dvec3& v, int c) {
                        return 100.0 * (v[c] / mc.luminance[c] - 1.0);
                    };
                    std::printf(
                        "alt %5.0f sun %4.0f view %3.0f az %3.0f  se %.2f%%  hillaire %+5.1f %+5.1f %+5.1f  "
                        "orders %+5.1f %+5.1f %+5.1f\n",
                        altitude, sunElevation, viewZenith, azimuth, se, err(hill.luminance, 0),
                        err(hill.luminance, 1), err(hill.luminance, 2), err(ord.luminance, 0),
                        err(ord.luminance, 1), err(ord.luminance, 2));
                    std::fflush(stdout);
                }
}

}  // namespace
