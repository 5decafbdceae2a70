// The settings registry: one line per effect (its FrameInfo member and table), in the effects' composite
// order (effects.cpp).
#include <postfx/context.h>
#include <postfx/settings_table.h>

namespace postfx {
namespace {

#define POSTFX_FRAME_MEMBER(m) [](void* f) -> void* { return &static_cast<FrameInfo*>(f)->m; }

constexpr EffectSettingsTable kEffectTables[] = {
    {"atmosphere", "atmosphere", atmosphereSettingsTable, POSTFX_FRAME_MEMBER(atmosphere)},
    {"clouds", "clouds", cloudSettingsTable, POSTFX_FRAME_MEMBER(clouds)},
    {"fog", "fog", fogSettingsTable, POSTFX_FRAME_MEMBER(fog)},
    {"froxel_fog", "froxelFog", froxelFogSettingsTable, POSTFX_FRAME_MEMBER(froxelFog)},
};

#undef POSTFX_FRAME_MEMBER

}  // namespace

std::span<const EffectSettingsTable> effectSettingsTables() {
    return kEffectTables;
}

}  // namespace postfx
