// The memory budget (ContextCreateInfo::memoryBudgetBytes): a frame's images and buffers, as the frame
// plan counts them, checked before anything is created, with an error naming the settings that size the
// largest of them (ImageDesc::sizedBy).
#pragma once

#include <postfx/result.h>

#include "core/frame_builder.h"

#include <cstdint>
#include <string>

namespace postfx::core {

// A held resource's bytes as the frame plan lists them: texels × bytes per texel, or a uniform ring.
uint64_t resourceBytes(const ResourceDecl& r, uint32_t framesInFlight);

// "5.4 GiB", "640 MiB", "12 KiB", "512 bytes": one decimal at most, none when it is 0.
std::string bytesText(uint64_t bytes);

// Success when the compiled frame's held resources take at most `budget` bytes (0: no budget); else
// InvalidArgument: the keys whose images the frame could drop to fit, largest first, each with its
// largest image's extent and its bytes, then the budget and where it is set.
Status checkMemoryBudget(const Frame& frame, uint32_t framesInFlight, uint64_t budget);

}  // namespace postfx::core
