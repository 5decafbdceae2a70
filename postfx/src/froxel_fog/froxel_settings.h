// The froxel fog's grid limits (kMaxFroxelGridSize, kMaxFroxels) checked where the grid is known: as set
// (validateFroxelFogSettings) or from the tile size at the color extent (the effect's validate).
#pragma once

#include <postfx/froxel_fog.h>
#include <postfx/result.h>

#include <cstdint>
#include <string>

namespace postfx {

// InvalidArgument naming `field` when grid.x·grid.y·grid.z > kMaxFroxels; `from` precedes the grid in
// the message ("8 px at 1024x600 gives ").
Status checkFroxelCount(const UVec3& grid, const std::string& field, const std::string& from);

// With tileSizePx > 0: InvalidArgument naming FrameInfo.froxelFog.tileSizePx, the extent and the grid
// when the tiles give more than kMaxFroxelGridSize froxels across or down, or more than kMaxFroxels.
Status checkFroxelTiles(const FroxelFogSettings& settings, uint32_t width, uint32_t height);

}  // namespace postfx
