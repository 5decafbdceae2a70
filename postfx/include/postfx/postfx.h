// Umbrella header of postfx, volumetric post effects for Vulkan renderers.
#pragma once

#include <postfx/atmosphere.h>
#include <postfx/clouds.h>
#include <postfx/context.h>
#include <postfx/fog.h>
#include <postfx/frame_plan.h>
#include <postfx/froxel_fog.h>
#include <postfx/inputs.h>
#include <postfx/result.h>
#include <postfx/settings_table.h>
#include <postfx/types.h>
#include <postfx/version.h>
#include <postfx/volumetrics_lookup.h>
