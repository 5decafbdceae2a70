#include "core/world_frame.h"

#include "core/checks.h"

namespace postfx::core {
namespace {

// The slots of the shared inputs' arrays in WorldScratch.
constexpr char kLightsSlot = 'l', kShadowsSlot = 's';

}  // namespace

Status checkWorldFrame(const WorldFrame& world, const std::string& name) {
    if (world.up != UpAxis::Y && world.up != UpAxis::Z)
        return invalid(name + ".up: " + std::to_string(uint32_t(world.up)) + " is not UpAxis::Y or Z");
    if (world.handedness != Handedness::Right && world.handedness != Handedness::Left)
        return invalid(name + ".handedness: " + std::to_string(uint32_t(world.handedness)) +
                       " is not Handedness::Right or Left");
    return checkRange((name + ".unitsPerMetre").c_str(), world.unitsPerMetre, kMinUnitsPerMetre,
                      kMaxUnitsPerMetre);
}

WorldTransform::WorldTransform(const WorldFrame& world) : unitsPerMetre_(world.unitsPerMetre) {
    const bool left = world.handedness == Handedness::Left;
    if (world.up == UpAxis::Z) {  // postfx's (x, y, z) = (x, z, ∓y): the host's up is postfx's y
        axis_[1] = 2;
        axis_[2] = 1;
        sign_[2] = left ? 1.0 : -1.0;
    } else {
        sign_[2] = left ? -1.0 : 1.0;
    }
    identity_ = world.up == UpAxis::Y && !left && world.unitsPerMetre == 1.0;
}

glm::dvec3 WorldTransform::position(const glm::dvec3& host) const {
    glm::dvec3 p;
    for (int i = 0; i < 3; ++i)
        p[i] = sign_[i] * host[axis_[i]] / unitsPerMetre_;
    return p;
}

glm::dvec3 WorldTransform::direction(const glm::dvec3& host) const {
    glm::dvec3 d;
    for (int i = 0; i < 3; ++i)
        d[i] = sign_[i] * host[axis_[i]];
    return d;
}

glm::vec3 WorldTransform::direction(const glm::vec3& host) const {
    glm::vec3 d;
    for (int i = 0; i < 3; ++i)
        d[i] = float(sign_[i]) * host[axis_[i]];
    return d;
}

glm::vec3 WorldTransform::extent(const glm::vec3& host) const {
    glm::vec3 e;
    for (int i = 0; i < 3; ++i)
        e[i] = float(double(host[axis_[i]]) / unitsPerMetre_);
    return e;
}

glm::dvec3 WorldTransform::hostPosition(const glm::dvec3& position) const {
    glm::dvec3 p;
    for (int i = 0; i < 3; ++i)
        p[axis_[i]] = sign_[i] * position[i] * unitsPerMetre_;
    return p;
}

glm::dvec3 WorldTransform::hostRow(const glm::dvec3& row) const {
    glm::dvec3 r;
    for (int i = 0; i < 3; ++i)
        r[axis_[i]] = sign_[i] * row[i] / unitsPerMetre_;
    return r;
}

glm::dmat4 WorldTransform::toPostfx() const {
    glm::dmat4 m(0.0);
    for (int i = 0; i < 3; ++i)
        m[axis_[i]][i] = sign_[i] / unitsPerMetre_;
    m[3][3] = 1.0;
    return m;
}

glm::dmat4 WorldTransform::worldToClip(const glm::dmat4& host) const {
    // Column i of W·M⁻¹: M⁻¹ takes postfx's axis i to sign(i)·u along the host's axis(i).
    glm::dmat4 w = host;
    for (int i = 0; i < 3; ++i)
        w[i] = host[axis_[i]] * (sign_[i] * unitsPerMetre_);
    return w;
}

CameraInput WorldTransform::camera(const CameraInput& host) const {
    CameraInput c;
    c.position = position(host.position);
    for (int i = 0; i < 3; ++i) {
        c.view[i] = host.view[axis_[i]] * float(sign_[i]);  // A·R⁻¹: exact
        c.projection[i] = glm::vec4(glm::dvec4(host.projection[i]) * unitsPerMetre_);
    }
    c.view[3] = glm::vec4(glm::vec3(glm::dvec3(glm::vec3(host.view[3])) / unitsPerMetre_), host.view[3].w);
    c.projection[3] = host.projection[3];
    if (glm::determinant(glm::dmat3(c.view)) < 0.0) {
        // P'·F·F·V' with F = diag(1, 1, -1, 1): a left-handed view made right-handed (+z forward -> -z).
        for (int col = 0; col < 4; ++col)
            c.view[col][2] = -c.view[col][2];
        c.projection[2] = -c.projection[2];
    }
    return c;
}

std::vector<std::byte>& WorldScratch::storage(const void* slot) {
    for (auto& [key, bytes] : slots_)
        if (key == slot) return bytes;
    return slots_.emplace_back(slot, std::vector<std::byte>{}).second;
}

void sharedInputsToPostfx(const WorldTransform& world, FrameInfo& frame, WorldScratch& scratch) {
    frame.camera = world.camera(frame.camera);
    frame.sun.toSun = world.direction(glm::vec3(frame.sun.toSun));
    frame.shadowMap.worldToClip = world.worldToClip(frame.shadowMap.worldToClip);
    if (frame.lightCount > 0) {
        LocalLight* lights = scratch.copy(&kLightsSlot, frame.lights, frame.lightCount);
        for (uint32_t i = 0; i < frame.lightCount; ++i) {
            LocalLight& l = lights[i];
            l.position = world.position(l.position);
            l.direction = world.direction(glm::vec3(l.direction));
            l.range = float(world.length(l.range));
            l.sourceRadius = float(world.length(l.sourceRadius));
        }
        frame.lights = lights;
    }
    LocalShadowAtlasInput& atlas = frame.localShadows;
    if (atlas.shadowCount > 0) {
        LocalShadow* shadows = scratch.copy(&kShadowsSlot, atlas.shadows, atlas.shadowCount);
        for (uint32_t i = 0; i < atlas.shadowCount; ++i)
            for (uint32_t f = 0; f < shadows[i].faceCount; ++f)
                shadows[i].faces[f].worldToClip = world.worldToClip(shadows[i].faces[f].worldToClip);
        atlas.shadows = shadows;
    }
}

}  // namespace postfx::core
