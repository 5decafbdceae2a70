// The effects a context holds, in composite order (docs/architecture.md, "Composite order").
#pragma once

#include "core/effect.h"
#include "core/gpu.h"

#include <memory>
#include <vector>

namespace postfx {

std::vector<std::unique_ptr<core::Effect>> makeEffects(const core::Gpu& gpu);

}  // namespace postfx
