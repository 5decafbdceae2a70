// Umbrella header of postfx, volumetric post effects for Vulkan renderers.
#pragma once

#include <postfx/context.h>
#include <postfx/result.h>
