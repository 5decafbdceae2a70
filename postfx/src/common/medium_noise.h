// The shared medium's noise texture as a frame declares it (both fogs: docs/effects/fog.md#noise): the
// texture postfx generates (persistent: regenerated only when its size or seed changes), the host's, or
// a 1-texel stand-in bound when the noise is off (never sampled: a flag skips it). Each fog names its own
// resources and pass, so the frame plan says which effect holds the texture.
#pragma once

#include <postfx/fog.h>

#include "core/frame_graph.h"
#include "core/gpu.h"

#include <string>

namespace postfx::common {

inline constexpr VkFormat kNoiseFormat = VK_FORMAT_R8_UNORM;

// Whether the device can generate the noise texture: R8_UNORM as a storage image, a linearly filtered
// sampled image and a transfer source (read-back).
bool noiseFormatSupported(const core::Gpu& gpu);

// Unsupported naming `<prefix>.noise` when generated noise is asked for on a device that cannot make it.
Status checkNoiseSupported(const FogNoiseSettings& noise, bool formatSupported, const std::string& prefix);

struct NoiseDeclaration {
    const core::ResourceId& generated;              // the generated texture (persistent)
    const core::ResourceId& none;                   // the 1-texel stand-in
    const core::ComputePipelineDesc& generatePass;  // fog/noise_generate.comp under the effect's name
    const char* sizedBy;                            // its size's key: "fog.noise.texture_size"
};

// A generated noise texture of size³ R8 texels (persistent: `pass`, shaders/common/noise_generate.comp,
// runs only when no texture of that size and seed is held): the Perlin–Worley fBm (kNoisePerlinWorley)
// or the Worley fBm alone (kNoiseWorley). `size` is a power of two >= kNoiseGroupSize. When an effect
// declared the same texture (formula, size, seed) earlier this frame, that one is returned: one image and
// one build for all of them, named by the first and found by every sharer's name too
// (FrameBuilder::findPersistent). `sizedBy`: the key of `size` (ImageDesc::sizedBy).
core::ImageRef declareGeneratedNoise(core::FrameBuilder& builder, const core::ResourceId& id,
                                     const core::ComputePipelineDesc& pass, uint32_t size, uint32_t seed,
                                     uint32_t kind, const char* sizedBy);

// Declares the noise image (and its generation pass when it must be built) and returns it.
core::ImageRef declareNoise(core::FrameBuilder& builder, const FogNoiseSettings& noise,
                            const NoiseDeclaration& declaration);

}  // namespace postfx::common
