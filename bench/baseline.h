// The two baselines the accuracy–cost benchmark puts beside postfx's fog, run on the same inputs:
//   SeedAsWritten:    the shader postfx started from (a Unity URP post-process fog shader from a Korean
//                     tutorial article; bench/shaders/seed_as_written.comp) as written: fixed step length
//                     (cost grows with distance), its phase formula (numerator 1 - cos²θ), in-scattering
//                     neither attenuated by the transmittance in front nor integrated, added to a
//                     constant fog colour and blended by 1 - T.
//   SeedFixedRiemann: the same with its formula errors fixed (real Henyey–Greenstein, T·σs·light·Δ,
//                     color·T + L) but still a plain Riemann sum with fixed step length.
// Both read the medium exactly as postfx does (shaders/common/medium/medium.glsl with postfx's FogUniforms).
#pragma once

#include "host/vulkan_host.h"

#include <postfx/context.h>

#include <memory>
#include <string>

namespace bench {

enum class Baseline { SeedAsWritten, SeedFixedRiemann };
const char* baselineName(Baseline b);  // "seed-as-written", "seed-fixed-riemann"

class BaselinePass {
public:
    static std::unique_ptr<BaselinePass> create(demo::VulkanHost& host, uint32_t framesInFlight,
                                                std::string& error);
    ~BaselinePass();

    // Records the baseline over frame.color (RGBA16F, in GENERAL, in place) with the same inputs postfx
    // would get in `frame` (camera, sun, ambient, shadow map, frame.fog's medium), marching with a fixed
    // `stepLength` [m] up to min(surface, fog.maxDistance). `noiseView`: the fog's noise texture (R8 3D,
    // SHADER_READ_ONLY_OPTIMAL) or VK_NULL_HANDLE when noise is off. Writes a timestamp before and after
    // the dispatch at queries `query`, `query + 1` of `queryPool` (already reset).
    bool record(VkCommandBuffer cmd, const postfx::FrameInfo& frame, const postfx::DepthConvention& depth,
                Baseline which, float stepLength, VkImageView noiseView, VkQueryPool queryPool,
                uint32_t query, std::string& error);

private:
    struct Impl;
    explicit BaselinePass(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace bench
