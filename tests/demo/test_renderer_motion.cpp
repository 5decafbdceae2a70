// The demo renderer with a moving scene (docs/scene-format.md#motion): render() draws frame n in the
// scene's state at frame n (sceneAtFrame), so that its last frame equals a still scene placed where the
// motion has taken everything, G-buffer, lights, shadow map and fog included; renderReference() is of that
// same state; FrameInfo carries the frame's time (n · frame_time) and camera cuts (the scene's cut frame,
// requestCameraCut). Small images (32x18): lavapipe under the validation layer.
#include "gpu_test.h"
#include "host/renderer.h"
#include "scene/motion.h"
#include "scene/scene.h"

#include <cstring>
#include <string>

namespace test {
namespace {

constexpr uint32_t kWidth = 32, kHeight = 18;
constexpr uint32_t kFrames = 3;

// A ground, a box and a sphere under a shadowing sun, a point light, the ray-marched fog (noise with wind,
// temporal off: each frame stands alone); the camera walks and turns, the light moves and dims at the
// last frame.
demo::Scene movingScene() {
    demo::Scene s;
    s.camera.position = {0.0f, 2.0f, 8.0f};
    s.camera.lookAt = {0.0f, 1.0f, 0.0f};
    s.camera.farPlane = 100.0f;
    s.camera.velocity = {3.0f, 0.0f, -6.0f};
    s.camera.yawRateDeg = 200.0f;
    s.sun.direction = glm::normalize(glm::vec3(0.5f, 0.4f, -0.3f));
    s.sun.illuminance = glm::vec3(20000.0f);
    s.ambient = glm::vec3(500.0f);
    s.sky = glm::vec3(3000.0f);
    demo::Object ground;
    s.objects.push_back(ground);
    demo::Object box;
    box.type = demo::ObjectType::Box;
    box.position = {1.0f, 1.0f, -2.0f};
    box.halfSize = glm::vec3(1.0f);
    s.objects.push_back(box);
    demo::Object sphere;
    sphere.type = demo::ObjectType::Sphere;
    sphere.position = {-2.0f, 1.0f, 1.0f};
    sphere.radius = 1.0f;
    s.objects.push_back(sphere);
    demo::Light light;
    light.position = {-1.0f, 2.0f, 3.0f};
    light.intensity = {3000.0f, 2000.0f, 1000.0f};
    light.range = 20.0f;
    light.velocity = {2.0f, 0.0f, -3.0f};
    light.intensityChange = demo::IntensityChange{kFrames - 1, {500.0f, 1000.0f, 4000.0f}};
    s.lights.push_back(light);
    s.fog.enabled = true;
    s.fog.density = 0.05f;
    s.fog.steps = 16;
    s.fog.noise.enabled = true;
    s.fog.noise.textureSize = 16;
    s.fog.noise.wind = {2.0f, 0.0f, 1.0f};
    s.fog.temporal.enabled = false;
    s.frameTime = 0.05;
    return s;
}

// `scene` without its motion: everything stays as it is at frame 0.
demo::Scene still(demo::Scene scene) {
    scene.camera.velocity = glm::vec3(0.0f);
    scene.camera.yawRateDeg = 0.0f;
    for (demo::Light& l : scene.lights) {
        l.velocity = glm::vec3(0.0f);
        l.intensityChange.reset();
    }
    return scene;
}

bool identical(const demo::ImageF& a, const demo::ImageF& b) {
    return a.width == b.width && a.height == b.height && a.rgba.size() == b.rgba.size() &&
           std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)) == 0;
}

class DemoRendererMotion : public GpuTest {
protected:
    std::unique_ptr<demo::Renderer> renderer() {
        demo::RenderOptions o;
        o.width = kWidth;
        o.height = kHeight;
        o.frames = kFrames;
        o.shadowMapSize = 256;
        std::string error;
        auto r = demo::Renderer::create(*host, o, error);
        EXPECT_TRUE(r) << error;
        return r;
    }
    demo::ImageF render(const demo::Scene& scene) {
        demo::ImageF image;
        std::string error;
        if (auto r = renderer()) {
            EXPECT_TRUE(r->render(scene, image, error)) << error;
        }
        return image;
    }
    demo::ImageF reference(const demo::Scene& scene) {
        demo::ImageF image;
        std::string error;
        if (auto r = renderer()) {
            EXPECT_TRUE(r->renderReference(scene, image, error, 16)) << error;
        }
        return image;
    }
};

// The last frame of the moving scene is, to the bit, the still scene moved to that frame: the camera's
// place and turn, the plane quads centred under it, the shadow map's fit, the light's place and new
// intensity, and the fog's time are all frame n's.
TEST_F(DemoRendererMotion, LastFrameIsTheStateOfItsFrame) {
    const demo::Scene scene = movingScene();
    const demo::Scene last = still(demo::sceneAtFrame(scene, kFrames - 1));
    ASSERT_NE(last.camera.position, scene.camera.position);
    ASSERT_NE(last.lights[0].intensity, scene.lights[0].intensity);
    const demo::ImageF moving = render(scene);
    ASSERT_EQ(moving.rgba.size(), size_t(kWidth) * kHeight * 4);
    EXPECT_TRUE(identical(moving, render(last)));
    EXPECT_FALSE(identical(moving, render(still(scene))));  // the motion shows
}

// --reference is of the last frame's state too (a single frame: the reference has no history).
TEST_F(DemoRendererMotion, ReferenceIsOfTheLastFramesState) {
    const demo::Scene scene = movingScene();
    const demo::ImageF moving = reference(scene);
    ASSERT_EQ(moving.rgba.size(), size_t(kWidth) * kHeight * 4);
    EXPECT_TRUE(identical(moving, reference(still(demo::sceneAtFrame(scene, kFrames - 1)))));
    EXPECT_FALSE(identical(moving, reference(still(scene))));
}

// FrameInfo: time n · frame_time; cameraCut on the scene's cut frame and on the frame after
// requestCameraCut() (until one is recorded: render() records one, and starts with a cut itself).
TEST_F(DemoRendererMotion, FrameInfoHasTheFramesTimeAndCuts) {
    demo::Scene scene = movingScene();
    scene.cameraCutFrame = 7;
    auto r = renderer();
    ASSERT_TRUE(r);
    EXPECT_DOUBLE_EQ(r->frameInputs(VK_NULL_HANDLE, scene, 30).timeSeconds, 1.5);
    EXPECT_FALSE(r->frameInputs(VK_NULL_HANDLE, scene, 6).cameraCut);
    EXPECT_TRUE(r->frameInputs(VK_NULL_HANDLE, scene, 7).cameraCut);
    EXPECT_FALSE(r->frameInputs(VK_NULL_HANDLE, scene, 8).cameraCut);
    r->requestCameraCut();
    EXPECT_TRUE(r->frameInputs(VK_NULL_HANDLE, scene, 8).cameraCut);
    EXPECT_TRUE(r->frameInputs(VK_NULL_HANDLE, scene, 9).cameraCut);  // nothing recorded yet
    demo::ImageF image;
    std::string error;
    ASSERT_TRUE(r->render(scene, image, error)) << error;
    EXPECT_FALSE(r->frameInputs(VK_NULL_HANDLE, scene, 8).cameraCut);
    // A scene without frame_time: frame n at n / 60 s, as before motion.
    EXPECT_EQ(r->frameInputs(VK_NULL_HANDLE, demo::Scene{}, 42).timeSeconds, 42 * (1.0 / 60.0));
}

}  // namespace
}  // namespace test
