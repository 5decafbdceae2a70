// Scene description of the demo host renderer, loaded from JSON (docs/scene-format.md).
// Units: metres, lux (illuminance), cd/m² (radiance); directions in world space (right-handed, y up).
#pragma once

#include "scene/light.h"
#include "scene/particles.h"

#include <postfx/atmosphere.h>
#include <postfx/clouds.h>
#include <postfx/fog.h>
#include <postfx/froxel_fog.h>
#include <postfx/volumetrics_lookup.h>
#include <glm/glm.hpp>
// Declares nlohmann::json (sceneToJson's type) alone: a file that writes or reads JSON includes
// <nlohmann/json.hpp>, and the others (the renderer, most tests) skip its parse.
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace demo {

// Limits of scene files (docs/scene-format.md, "Limits"). Within them every derived quantity the renderer
// computes is finite (camera matrices and their inverse, the shadow map fit, the PNG exposure) and postfx
// accepts the frame, so a file that loads renders; tests/demo/fuzz checks it.
namespace limits {
constexpr double kMaxCoordinate = 1e7;  // [m] each coordinate of positions (camera, look_at, objects)
constexpr double kMaxObjectSize = 1e7;  // [m] box half sizes and sphere radii
constexpr double kMinUpLength = 1e-6;   // camera.up's length (its components within kMaxCoordinate)
constexpr double kMinFovYDeg = 0.01;    // camera.fov_y_deg [deg]
constexpr double kMaxFovYDeg = 179.0;
constexpr double kMinNear = 1e-6;  // camera.near [m]
constexpr double kMaxNear = 1e6;
constexpr double kMaxFar = 1e9;      // camera.far [m]
constexpr double kMinEv100 = -30.0;  // camera.ev100
constexpr double kMaxEv100 = 30.0;
constexpr double kMaxLight = 1e7;          // sun illuminance [lux], ambient and sky [cd/m²]: postfx's bound
constexpr std::size_t kMaxObjects = 4096;  // entries of `objects`
// Motion (docs/scene-format.md#motion; scene/motion.h). Positions that motion would carry beyond
// kMaxCoordinate stop there, so every frame's state is within the limits above.
constexpr double kMaxSpeed = 1e4;         // [m/s] each component of camera.velocity and lights[i].velocity
constexpr double kMaxYawRateDeg = 36000;  // [deg/s] camera.yaw_rate: 100 turns per second
constexpr double kMaxFrameTime = 1.0;     // [s] frame_time, in (0, 1]
}  // namespace limits

// The time between two frames when the file has no `frame_time` [s]: frame n is at n / 60 s.
constexpr double kDefaultFrameTime = 1.0 / 60.0;

// The exposure of tonemapped output (PNG, the window) for camera.ev100: radiance is multiplied by
// 1 / (1.2 · 2^ev100) (saturation-based, Lagarde & de Rousiers 2014).
float exposureFromEv100(float ev100);

struct Camera {
    glm::vec3 position{0.0f, 2.0f, 10.0f};  // [m]
    glm::vec3 lookAt{0.0f, 1.0f, 0.0f};     // [m], must differ from position
    glm::vec3 up{0.0f, 1.0f, 0.0f};         // not parallel to lookAt - position
    float fovYDeg = 60.0f;                  // vertical field of view [deg], [0.01, 179]
    float nearPlane = 0.1f;                 // [m], [1e-6, 1e6]
    float farPlane = 1000.0f;               // [m], (near, 1e9]
    float ev100 = 15.0f;                    // exposure for tonemapped output only [EV at ISO 100], [-30, 30]
    // Motion (scene/motion.h): the fields above are the camera at frame 0.
    glm::vec3 velocity{0.0f};  // [m/s] world, each in [-1e4, 1e4]
    // [deg/s] turning about world +y (view direction and up together), positive to the right: from -z
    // toward +x, clockwise seen from above (the window's fly camera's yaw); [-36000, 36000].
    float yawRateDeg = 0.0f;
};

struct Sun {
    glm::vec3 direction{0.0f, 1.0f, 0.0f};  // unit vector toward the sun (normalised on load)
    glm::vec3 illuminance{100000.0f};       // illuminance on a surface facing the sun [lux], [0, 1e7]
    bool shadows = true;                    // cast shadows through the shadow map
};

enum class ObjectType { Plane, Box, Sphere };

struct Object {
    ObjectType type = ObjectType::Plane;
    glm::vec3 position{0.0f};            // plane: a point on it; box, sphere: centre [m]
    glm::vec3 normal{0.0f, 1.0f, 0.0f};  // plane only, unit (normalised on load)
    glm::vec3 halfSize{0.5f};            // box only [m], (0, 1e7]
    float radius = 0.5f;                 // sphere only [m], (0, 1e7]
    glm::vec3 albedo{0.5f};              // diffuse reflectance, each in [0, 1]
    // Coverage [1], [0, 1]: 1 opaque (the G-buffer), below 1 transparent (the forward pass after postfx,
    // blended over the frame with this alpha, seen through postfx's volumetrics lookup).
    float opacity = 1.0f;
    // Drawn in the forward pass even at opacity 1 (tests compare it with the same object drawn opaque).
    bool forward = false;
};

// Whether `object` is drawn in the forward pass (transparent or forced there) rather than the G-buffer.
inline bool drawnForward(const Object& object) {
    return object.forward || object.opacity < 1.0f;
}
// Whether `object` casts shadows (the sun's map, the local lights' atlas): opaque ones only, so a glass
// pane does not cast a black shadow; an object forced forward at opacity 1 still does.
inline bool castsShadows(const Object& object) {
    return object.opacity >= 1.0f;
}

struct Scene {
    Camera camera;
    Sun sun;
    glm::vec3 ambient{0.0f};  // uniform incident radiance for the ambient term [cd/m²], [0, 1e7]
    glm::vec3 sky{0.0f};      // radiance of pixels with no geometry [cd/m²], [0, 1e7]
    std::vector<Object> objects;
    // Local lights (`lights`, at most postfx::kMaxLocalLights): the demo's surface lighting adds them and
    // passes them to postfx in FrameInfo::lights.
    std::vector<Light> lights;
    // effects.fog: postfx's ray-marched fog (docs/effects/fog.md); disabled unless the file has it.
    postfx::FogSettings fog;
    // effects.froxel_fog: postfx's froxel fog (docs/effects/froxel-fog.md); disabled unless the file has
    // it, and never enabled together with `fog` (the loader rejects that). Its `volumes` pointer stays
    // null and volumeCount 0: the volumes live in froxelVolumes, and froxelFogSettings(scene) points the
    // settings there for a frame.
    postfx::FroxelFogSettings froxelFog;
    // effects.froxel_fog.volumes: its local fog volumes, at most postfx::kMaxFogVolumes.
    std::vector<postfx::FogVolume> froxelVolumes;
    // effects.atmosphere: postfx's sky and atmosphere (docs/effects/atmosphere.md); disabled unless the file
    // has it. While enabled, sun.illuminance is the sun's outside the atmosphere: the renderer attenuates
    // the surfaces' sun by the atmosphere's transmittance, draws `sky` as black (space: postfx draws the
    // sky over it) and, with ambientFromSky, takes the ambient from the sky's irradiance instead of
    // `ambient` (host/atmosphere_lighting.h).
    postfx::AtmosphereSettings atmosphere;
    // effects.clouds: postfx's volumetric clouds (docs/effects/clouds.md); disabled unless the file has it.
    postfx::CloudSettings clouds;
    // `particles`: emitters of camera-facing quads drawn in the forward pass (scene/particles.h), at most
    // kMaxParticleEmitters.
    std::vector<ParticleEmitter> particles;
    // `volumetrics_lookup`: the resolution and depth range of postfx's lookup for the forward pass
    // (FrameInfo::volumetricsLookup). Its `enabled` is not read from the file: the renderer turns the lookup
    // on whenever the scene has forward draws (hasForwardDraws).
    postfx::VolumetricsLookupSettings volumetricsLookup;
    // `frame_time`: frame n is at time n · frameTime [s], for the motion of the camera and lights and for
    // postfx (FrameInfo::timeSeconds); (0, 1]. Kept in double, so that the default is exactly 1/60 s.
    double frameTime = kDefaultFrameTime;
    // `budget_ms`: one GPU time budget for all of postfx's work [ms] (FrameInfo::budgetMs: the effects
    // whose quality is "auto" share it); [0, 1000], 0 (the default): off.
    float budgetMs = 0.0f;
    // `camera_cut_frame`: the renderer sets FrameInfo::cameraCut on this frame (postfx drops its temporal
    // history); none when absent.
    std::optional<uint32_t> cameraCutFrame;
};

// Whether the scene draws anything in the forward pass: an object drawnForward or an enabled emitter with
// particles.
bool hasForwardDraws(const Scene& scene);

// scene.froxelFog with its volumes pointing into scene.froxelVolumes (volumeCount their number), as the
// renderer gives it to postfx (FrameInfo::froxelFog): valid while `scene` lives and its froxelVolumes is
// not changed.
postfx::FroxelFogSettings froxelFogSettings(const Scene& scene);

// Parses a scene from JSON text. On failure returns false and sets `error` to one line naming the
// key path, e.g. "objects[2].radius: expected a number in (0, 1e7], got -1".
bool parseScene(const std::string& jsonText, Scene& scene, std::string& error);
bool loadSceneFile(const std::string& path, Scene& scene, std::string& error);

// Serialises a scene to JSON with every key written (defaults included), in the format parseScene
// reads. For a valid scene (e.g. one parseScene produced), parseScene(sceneToJson(s).dump()) gives
// back s exactly: floats are written in their shortest form that reads back as the same float.
nlohmann::json sceneToJson(const Scene& scene);

// The scene-file name of a fog quality (`effects.fog.quality`): "custom", "low", ... "auto".
const char* fogQualityName(postfx::FogQuality quality);

// The built-in scene: ground plane, a few boxes and pillars, a low sun casting long shadows.
Scene defaultScene();
// The built-in scene as JSON text (the same scene; committed as scenes/default.json too).
std::string defaultSceneJson();

}  // namespace demo
