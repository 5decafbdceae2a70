// Local-light shadow maps for tests, drawn on the CPU: spheres ray-cast into regions of an R32F atlas
// (standard Z, cleared to 1) with the faces' matrices, and the exact visibility of a point from a light
// past those spheres (the closed forms' occluded interval).
#pragma once

#include <postfx/inputs.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace test {

struct ShadowSphere {
    glm::dvec3 centre{0.0};
    double radius = 1.0;
};

class ShadowAtlas {
public:
    ShadowAtlas(uint32_t width, uint32_t height)
        : width(width), height(height), texels(size_t(width) * height, 1.0f) {}

    // A spot light's face: perspective along `direction` with a full field of view `fovRad`, size × size
    // texels at `offset`.
    postfx::LocalShadow spot(const glm::dvec3& position, const glm::dvec3& direction, double fovRad,
                             glm::uvec2 offset, uint32_t size, double nearPlane, double farPlane,
                             const std::vector<ShadowSphere>& spheres);
    // A point light's six 90° faces (+X, -X, +Y, -Y, +Z, -Z), side by side from `offset` in a 3 × 2 block of
    // size × size regions; `rotation` turns the cube's axes (identity: world axes).
    postfx::LocalShadow point(const glm::dvec3& position, glm::uvec2 offset, uint32_t size, double nearPlane,
                              double farPlane, const std::vector<ShadowSphere>& spheres,
                              const glm::dmat3& rotation = glm::dmat3(1.0));

    uint32_t width, height;
    std::vector<float> texels;  // row-major, row 0 at v = 0

private:
    void drawFace(const glm::dmat4& worldToClip, const glm::dvec3& eye, glm::uvec2 offset, uint32_t size,
                  const std::vector<ShadowSphere>& spheres);
};

// Whether the segment from `x` to `light` passes through one of the spheres (exact).
bool occluded(const glm::dvec3& x, const glm::dvec3& light, const std::vector<ShadowSphere>& spheres);

}  // namespace test
