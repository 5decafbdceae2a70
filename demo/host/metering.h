// The demo's pre-exposure from what the camera sees (docs/integration.md, "Pre-exposure"): a frame is
// rendered, its RGBA16F image read back and measured, and the pre-exposure chosen so that the measured
// radiance fits half precision; the frame is rendered again when the choice changed (Renderer::render).
#pragma once

#include <cstddef>
#include <cstdint>

namespace demo {

// What one frame's HDR image (RGBA16F, radiance × the pre-exposure it was rendered with) holds, in its
// stored (pre-exposed) values: each pixel's largest of R, G and B.
struct Metering {
    double largest = 0.0;  // the largest pixel; 65504 (or Inf) when it clipped: then only a lower bound
    double median = 0.0;   // the median of the pixels above 0 (0 when none is)
    bool clipped() const { return !(largest < kClipped); }
    // The half format's largest finite value: a pixel there clipped.
    static constexpr double kClipped = 65504.0;
};

Metering meterHalfImage(const uint16_t* rgba, size_t pixels);

// The pre-exposure to render with after a frame rendered with `trial` measured `m`; `wanted`: the
// camera's (exposureFromEv100); [lowest, highest]: what postfx accepts for the scene (powers of two).
//   - clipped: trial · 2^-16 (measure again: what clipped is now at least 0.5, in range);
//   - nothing above 0 at trial ≤ 2^-10: trial · 2^16 (measure again: it may have underflowed);
//   - otherwise `wanted`, raised to put the median at kMedianTarget where it would fall below
//     kMedianFloor (half's precision), then lowered so the largest pixel stays ≤ kLargestTarget when it
//     would pass kLargestFit (the ends of the range: nothing seen clips, what most pixels see keeps its
//     digits), within [lowest, highest]; `wanted` itself when it fits.
// The result equals `trial` when the frame rendered with it stands.
double meteredPreExposure(const Metering& m, double trial, double wanted, double lowest, double highest);

inline constexpr double kLargestFit = 32768.0;      // 2^15: the largest pixel fits below it
inline constexpr double kLargestTarget = 16384.0;   // 2^14: where a pre-exposure lowered to fit puts it
inline constexpr double kMedianFloor = 1.0 / 1024;  // 2^-10: 16× half's smallest normal (2^-14)
inline constexpr double kMedianTarget = 0.125;      // 2^-3: middle grey, as an auto-exposure puts it

}  // namespace demo
