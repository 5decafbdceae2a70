// The clouds' shadow map's geometry (docs/effects/clouds.md, "Shadows"): a square of the shape's bottom
// plane around the camera (its centre snapped to whole texels, so a moving camera does not make the
// shadows crawl), and the rows that map a position to the map's uv along the sun's direction.
#pragma once

#include <postfx/context.h>

#include <glm/glm.hpp>

namespace postfx::clouds {

struct ShadowMapGeometry {
    glm::dvec3 center{0.0};  // world position of the map's centre, on the shape's bottom plane [m]
    double extent = 1.0;     // edge [m]
    uint32_t size = 1;       // edge [texels]
};
ShadowMapGeometry shadowMapGeometry(const FrameInfo& frame);

}  // namespace postfx::clouds
