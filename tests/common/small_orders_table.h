// The atmosphere's scattering-orders table made small enough for lavapipe, for the tests and for
// postfx-bench --quick (header only: the benchmark links no test code).
#pragma once

#include <postfx/atmosphere.h>

namespace test {

// 16×16×8 nodes, 4 azimuths, 144 directions, 24 steps, 4 orders: the table the atmosphere's GPU tests
// check against the CPU one. The default table takes about 6 s of lavapipe's time to build, once per
// context and media change: tests whose subject is not the orders' accuracy, and the benchmark's CI-sized
// runs, use this one.
inline void smallScatteringOrders(postfx::AtmosphereSettings& atmosphere) {
    atmosphere.scatteringOrdersLutSize = {16, 16, 8};
    atmosphere.scatteringOrdersAzimuthSize = 4;
    atmosphere.scatteringOrdersDirections = 144;
    atmosphere.scatteringOrdersSteps = 24;
    atmosphere.scatteringOrders = 4;
}

}  // namespace test
