// Scene description of the demo host renderer, loaded from JSON (docs/scene-format.md).
// Units: metres, lux (illuminance), cd/m² (radiance); directions in world space (right-handed, y up).
#pragma once

#include <postfx/fog.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace demo {

struct Camera {
    glm::vec3 position{0.0f, 2.0f, 10.0f};  // [m]
    glm::vec3 lookAt{0.0f, 1.0f, 0.0f};     // [m], must differ from position
    glm::vec3 up{0.0f, 1.0f, 0.0f};         // not parallel to lookAt - position
    float fovYDeg = 60.0f;                  // vertical field of view [deg], (0, 180)
    float nearPlane = 0.1f;                 // [m], > 0
    float farPlane = 1000.0f;               // [m], > near
    float ev100 = 15.0f;                    // exposure for tonemapped output only [EV at ISO 100]
};

struct Sun {
    glm::vec3 direction{0.0f, 1.0f, 0.0f};  // unit vector toward the sun (normalised on load)
    glm::vec3 illuminance{100000.0f};       // illuminance on a surface facing the sun [lux], >= 0
    bool shadows = true;                    // cast shadows through the shadow map
};

enum class ObjectType { Plane, Box, Sphere };

struct Object {
    ObjectType type = ObjectType::Plane;
    glm::vec3 position{0.0f};            // plane: a point on it; box, sphere: centre [m]
    glm::vec3 normal{0.0f, 1.0f, 0.0f};  // plane only, unit (normalised on load)
    glm::vec3 halfSize{0.5f};            // box only [m], > 0
    float radius = 0.5f;                 // sphere only [m], > 0
    glm::vec3 albedo{0.5f};              // diffuse reflectance, each in [0, 1]
};

struct Scene {
    Camera camera;
    Sun sun;
    glm::vec3 ambient{0.0f};  // uniform incident radiance for the ambient term [cd/m²], >= 0
    glm::vec3 sky{0.0f};      // radiance of pixels with no geometry [cd/m²], >= 0
    std::vector<Object> objects;
    // effects.fog: postfx's ray-marched fog (docs/effects/fog.md); disabled unless the file has it.
    postfx::FogSettings fog;
};

// Parses a scene from JSON text. On failure returns false and sets `error` to one line naming the
// key path, e.g. "objects[2].radius: expected a number > 0, got -1".
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
