// The local lights' shadow atlas layout (demo/host/local_shadows.h): the faces of each shadowed light, their
// regions packed without overlap inside the atlas, the resolutions halved to fit, the faces' matrices and
// the depth bias; a cube's faces hold every direction around a point light exactly once (postfx's rule:
// the first face whose clip square holds the point).
#include "host/local_shadows.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

demo::Light pointLight(uint32_t resolution) {
    demo::Light l;
    l.position = {1.0f, 2.0f, 3.0f};
    l.radius = 0.1f;
    l.range = 30.0f;
    l.shadows = true;
    l.shadowResolution = resolution;
    return l;
}

demo::Light spotLight(uint32_t resolution, float outerDeg) {
    demo::Light l = pointLight(resolution);
    l.kind = demo::LightKind::Spot;
    l.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    l.outerAngleDeg = outerDeg;
    return l;
}

// The clip position of world point p in `face`, and whether its clip square holds it.
bool holds(const postfx::LocalShadowFace& face, const glm::dvec3& p, glm::dvec4* clip = nullptr) {
    const glm::dvec4 c = glm::dmat4(face.worldToClip) * glm::dvec4(p, 1.0);
    if (clip) *clip = c;
    return c.w > 0.0 && std::abs(c.x) <= c.w && std::abs(c.y) <= c.w;
}

// Every region inside the atlas, none overlapping another.
void expectPacked(const demo::LocalShadowLayout& layout) {
    std::vector<const postfx::LocalShadowFace*> faces;
    for (const postfx::LocalShadow& s : layout.shadows)
        for (uint32_t f = 0; f < s.faceCount; ++f)
            faces.push_back(&s.faces[f]);
    EXPECT_EQ(faces.size(), layout.faceCount);
    for (size_t i = 0; i < faces.size(); ++i) {
        const postfx::LocalShadowFace& a = *faces[i];
        EXPECT_GE(a.extent.x, 16u);
        EXPECT_LE(a.offset.x + a.extent.x, layout.extent.x) << i;
        EXPECT_LE(a.offset.y + a.extent.y, layout.extent.y) << i;
        for (size_t j = 0; j < i; ++j) {
            const postfx::LocalShadowFace& b = *faces[j];
            const bool apart = a.offset.x + a.extent.x <= b.offset.x ||
                               b.offset.x + b.extent.x <= a.offset.x ||
                               a.offset.y + a.extent.y <= b.offset.y || b.offset.y + b.extent.y <= a.offset.y;
            EXPECT_TRUE(apart) << "faces " << j << " and " << i << " overlap";
        }
    }
}

TEST(DemoLocalShadows, NoShadowedLightNoAtlas) {
    std::vector<demo::Light> lights(3, pointLight(512));
    for (demo::Light& l : lights)
        l.shadows = false;
    const demo::LocalShadowLayout layout = demo::layoutLocalShadows(lights, demo::kMaxShadowAtlasEdge);
    EXPECT_TRUE(layout.shadows.empty());
    EXPECT_EQ(layout.extent, glm::uvec2(0u));
    ASSERT_EQ(layout.lightShadow.size(), 3u);
    for (uint32_t s : layout.lightShadow)
        EXPECT_EQ(s, postfx::kNoLocalShadow);
}

TEST(DemoLocalShadows, SpotOneFacePointSixPackedApart) {
    std::vector<demo::Light> lights = {pointLight(512), spotLight(1024, 24.0f), pointLight(100),
                                       spotLight(256, 80.0f)};
    lights[2].shadows = false;
    const demo::LocalShadowLayout layout = demo::layoutLocalShadows(lights, demo::kMaxShadowAtlasEdge);
    ASSERT_EQ(layout.shadows.size(), 3u);
    EXPECT_EQ(layout.lightShadow, (std::vector<uint32_t>{0, 1, postfx::kNoLocalShadow, 2}));
    EXPECT_EQ(layout.shadows[0].faceCount, 6u);
    EXPECT_EQ(layout.shadows[1].faceCount, 1u);
    EXPECT_EQ(layout.shadows[2].faceCount, 6u);  // wider than kMaxSpotFaceOuterDeg: a cube
    EXPECT_EQ(layout.faceCount, 13u);
    EXPECT_EQ(layout.resolutionShift, 0u);
    EXPECT_EQ(layout.shadows[0].faces[5].extent, postfx::UVec2(512u));
    EXPECT_EQ(layout.shadows[1].faces[0].extent, postfx::UVec2(1024u));
    expectPacked(layout);
    for (const postfx::LocalShadow& s : layout.shadows) {
        EXPECT_FALSE(s.reversedZ);
        EXPECT_GT(s.depthBias, 0.0f);
        EXPECT_LT(s.depthBias, 1e-3f);
    }
    // One texel at 45°, 4 m away, for a 512² 90° face with the near plane at 0.1 m: n·f/(f-n) · (2/512) / 4.
    EXPECT_NEAR(layout.shadows[0].depthBias, 0.1 * 30.0 / 29.9 * (2.0 / 512.0) / 4.0, 1e-9);
}

TEST(DemoLocalShadows, ResolutionsHalvedToFit) {
    const std::vector<demo::Light> lights(256, pointLight(4096));  // 1536 faces of 4096²
    const demo::LocalShadowLayout layout = demo::layoutLocalShadows(lights, demo::kMaxShadowAtlasEdge);
    EXPECT_GT(layout.resolutionShift, 0u);
    EXPECT_LE(layout.extent.x, demo::kMaxShadowAtlasEdge);
    EXPECT_LE(layout.extent.y, demo::kMaxShadowAtlasEdge);
    EXPECT_EQ(layout.shadows[0].faces[0].extent.x, 4096u >> layout.resolutionShift);
    expectPacked(layout);
}

// The cube's faces hold every direction, and the spot's face the cone around its axis; depth is 0 at the
// near plane and 1 at the far plane along each face's axis.
TEST(DemoLocalShadows, FacesCoverTheirLightsAndMapDepthZeroToOne) {
    const demo::Light point = pointLight(64);
    const demo::Light spot = spotLight(64, 40.0f);
    const demo::LocalShadowLayout layout = demo::layoutLocalShadows(std::vector{point, spot}, 8192);
    const postfx::LocalShadow& cube = layout.shadows[0];
    const glm::dvec3 centre(point.position);
    for (int i = 0; i < 2000; ++i) {
        // Directions spread over the sphere (a golden-angle spiral), corners and edges of the cube too.
        const double z = 1.0 - 2.0 * (i + 0.5) / 2000.0, r = std::sqrt(1.0 - z * z), phi = i * 2.399963;
        const glm::dvec3 d = i < 8 ? glm::dvec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)
                                   : glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
        int holding = 0;
        for (uint32_t f = 0; f < cube.faceCount; ++f)
            holding += holds(cube.faces[f], centre + 5.0 * d) ? 1 : 0;
        EXPECT_GE(holding, 1) << "direction " << i;
    }
    const postfx::LocalShadow& s = layout.shadows[1];
    const glm::dvec3 axis = glm::normalize(glm::dvec3(spot.direction));
    const glm::dvec3 side = glm::normalize(glm::cross(axis, glm::dvec3(0, 0, 1)));
    const double outer = glm::radians(40.0);
    glm::dvec4 c;
    EXPECT_TRUE(holds(
        s.faces[0], glm::dvec3(spot.position) + 3.0 * (std::cos(outer) * axis + std::sin(outer) * side), &c));
    EXPECT_FALSE(holds(s.faces[0], glm::dvec3(spot.position) - axis));
    const double n = 0.1, f = 30.0;
    EXPECT_TRUE(holds(s.faces[0], glm::dvec3(spot.position) + n * axis, &c));
    EXPECT_NEAR(c.z / c.w, 0.0, 1e-6);
    EXPECT_TRUE(holds(s.faces[0], glm::dvec3(spot.position) + f * axis, &c));
    EXPECT_NEAR(c.z / c.w, 1.0, 1e-6);
}

}  // namespace
