// Checks of AtmosphereSettings (postfx/atmosphere.h), shared by the effect and the CPU reference.
#pragma once

#include <postfx/atmosphere.h>
#include <postfx/result.h>

#include "atmosphere/atmosphere_shared.h"

namespace postfx::atmosphere {

// Bounds of the documented ranges (postfx/atmosphere.h, docs/effects/atmosphere.md).
constexpr double kMinGroundRadius = 1.0;  // [m]
constexpr double kMaxRadius = 1e8;        // ground and top [m]
constexpr double kMaxCoefficient = 1.0;   // scattering and absorption [1/m]
constexpr double kMaxHeight = 1e7;        // scale heights, ozone centre and half width, AP distance [m]
constexpr double kMaxSunAngularRadiusDeg = 45.0;
constexpr uint32_t kMinLutSide = 4;
// The LUTs' maxima: a few times beyond the sizes and counts where the benchmark's error stops falling
// (docs/effects/atmosphere.md, "Benchmark"), so that the largest frame finishes on a CPU device
// (docs/reliability.md, "Memory and cost budget").
constexpr uint32_t kMaxLut2dSide = 512;  // transmittance and sky-view
constexpr uint32_t kMaxMultipleScatteringSide = 64;
constexpr uint32_t kMaxAerialPerspectiveSide = 64;
constexpr uint32_t kMaxSteps = 128;                           // any LUT's march
constexpr uint32_t kMinDirections = 4, kMaxDirections = 256;  // multiple scattering, a perfect square
constexpr uint32_t kMaxStepsPerSlice = 8;                     // aerial perspective
// The scattering-orders LUT: a 3D image of (view·azimuth, sun, 2·height + 1) texels.
constexpr uint32_t kMaxOrdersViewSide = 64, kMaxOrdersSunSide = 128, kMaxOrdersHeightSide = 64;
constexpr uint32_t kMinOrdersAzimuths = 2, kMaxOrdersAzimuths = 16;
constexpr uint32_t kMaxScatteringOrders = 16;
constexpr uint32_t kMaxOrdersDirections = gpu::kAtmosphereOrdersMaxDirections;  // the pass's shared memory
// The orders' work together: orders · μ_s nodes · (2·height + 1) nodes · directions · (steps + μ nodes ·
// azimuths), the march and the gather per node and order (atmosphere.md, "Passes"). The defaults do
// 6.1e8; each key alone at its maximum (the table's three sides together) at most 15×; all at their
// maxima 290× (more than 8 minutes on lavapipe). 2^34, 28× the defaults', admits every key alone.
constexpr double kMaxOrdersWork = 17179869184.0;
double scatteringOrdersWork(const AtmosphereSettings& settings);

// InvalidArgument naming the field by its key under effects.atmosphere ("atmosphere.mie_anisotropy: 1 is
// outside (-1, 1)") for any value out of range, NaN or Inf; success otherwise.
Status validateSettings(const AtmosphereSettings& settings);

}  // namespace postfx::atmosphere
