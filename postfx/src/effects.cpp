// The registry: one line per effect. The order is the composite order: each effect composites over what
// the effects before it left in color, attenuating it, so the farthest comes first (sky, then clouds,
// then the fogs, as they arrive; docs/architecture.md, "Composite order").
#include "effects.h"

#include "atmosphere/atmosphere_effect.h"
#include "clouds/clouds_effect.h"
#include "fog/fog_effect.h"
#include "froxel_fog/froxel_effect.h"

namespace postfx {

std::vector<std::unique_ptr<core::Effect>> makeEffects(const core::Gpu& gpu) {
    std::vector<std::unique_ptr<core::Effect>> effects;
    // sky and atmosphere (docs/effects/atmosphere.md): the farthest, first
    effects.push_back(std::make_unique<atmosphere::AtmosphereEffect>(gpu));
    // volumetric clouds (docs/effects/clouds.md): in front of the sky, behind the fogs
    effects.push_back(std::make_unique<clouds::CloudsEffect>(gpu));
    effects.push_back(std::make_unique<fog::FogEffect>(gpu));  // ray-marched fog (docs/effects/fog.md)
    // froxel fog (docs/effects/froxel-fog.md); never in one frame with the ray-marched fog
    effects.push_back(std::make_unique<froxel_fog::FroxelFogEffect>(gpu));
    return effects;
}

}  // namespace postfx
