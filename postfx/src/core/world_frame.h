// The host's world frame (ContextCreateInfo::world) and its conversion into postfx's own: y up,
// right-handed, metres (docs/integration.md, "World frame and units"). The context converts each frame
// once, at the top of record() and plan(), after its checks (which name the host's fields with the host's
// values): the core converts the shared inputs (camera, sun, shadow maps, lights), each effect its own
// settings (Effect::toPostfxFrame). Everything after that works in postfx's frame.
#pragma once

#include <postfx/context.h>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace postfx::core {

// InvalidArgument naming `name`'s field ("ContextCreateInfo.world.unitsPerMetre") when `world` is not
// one postfx takes.
Status checkWorldFrame(const WorldFrame& world, const std::string& name);

// The map from the host's coordinates to postfx's: postfx's axis i is sign(i) times the host's axis
// axis(i), divided by unitsPerMetre. A signed permutation (orthogonal, determinant ±1) times one scale:
// directions convert exactly, lengths by one division. The host's x is always postfx's +x and its up
// postfx's +y; its other horizontal axis is postfx's ±z, as the handedness requires:
//   y up, right: ( x,  y,  z)      z up, right: ( x, z, -y)
//   y up, left:  ( x,  y, -z)      z up, left:  ( x, z,  y)
class WorldTransform {
public:
    WorldTransform() = default;  // postfx's own frame: the identity
    explicit WorldTransform(const WorldFrame& world);

    bool identity() const { return identity_; }
    double unitsPerMetre() const { return unitsPerMetre_; }
    int axis(int i) const { return axis_[i]; }
    double sign(int i) const { return sign_[i]; }
    // +1: a rotation; -1: a mirror (the host is left-handed).
    double determinant() const { return sign_[0] * sign_[1] * sign_[2] * (axis_[1] == 1 ? 1.0 : -1.0); }

    glm::dvec3 position(const glm::dvec3& host) const;  // [host units] -> [m]
    glm::dvec3 direction(const glm::dvec3& host) const;
    glm::vec3 direction(const glm::vec3& host) const;  // exact in float
    glm::vec3 extent(const glm::vec3& host) const;     // sizes along the host's axes [host units] -> [m]
    double length(double host) const { return host / unitsPerMetre_; }  // [host units] -> [m]
    glm::dvec3 hostPosition(const glm::dvec3& position) const;          // [m] -> [host units]
    // A row r of a map of postfx's positions (value = dot(r, x)) as the row of the same map of the host's.
    glm::dvec3 hostRow(const glm::dvec3& row) const;
    // The linear part as a matrix: host [host units] -> postfx [m] (translation none).
    glm::dmat4 toPostfx() const;
    // A host's world -> clip matrix as postfx's: worldToClip · toPostfx⁻¹.
    glm::dmat4 worldToClip(const glm::dmat4& host) const;
    // The camera in postfx's frame: position converted; the view rigid in metres, V' = [A·R⁻¹ | t/u] for
    // the host's V = [A | t]; the projection's x, y, z columns times u, so that P'·V'·x' = P·V·x for every
    // point (x' = R·x/u). A mirror turns the view's handedness: its z row and the projection's z column are
    // negated (P'·V' unchanged), so postfx's view is a rotation (determinant +1) whenever the host's view
    // has the host's world's handedness.
    CameraInput camera(const CameraInput& host) const;

private:
    bool identity_ = true;
    int axis_[3] = {0, 1, 2};
    double sign_[3] = {1.0, 1.0, 1.0};
    double unitsPerMetre_ = 1.0;
};

// Copies of the arrays a converted frame points to, kept from frame to frame: a slot grows to the
// largest copy it held and never shrinks, so a warm context converts without allocating. Each array has
// its own slot, named by the address of a tag of its owner's.
class WorldScratch {
public:
    template <class T>
    T* copy(const void* slot, const T* data, size_t count) {
        static_assert(std::is_trivially_copyable_v<T>);
        std::vector<std::byte>& bytes = storage(slot);
        if (bytes.size() < count * sizeof(T)) bytes.resize(count * sizeof(T));
        if (count > 0) std::memcpy(bytes.data(), data, count * sizeof(T));
        return reinterpret_cast<T*>(bytes.data());  // new's alignment holds every input struct's
    }

private:
    std::vector<std::byte>& storage(const void* slot);
    std::vector<std::pair<const void*, std::vector<std::byte>>> slots_;
};

// FrameInfo's shared inputs (camera, sun, shadow map, local lights and their shadows) converted in place
// into postfx's frame; the lights and shadows are copied into `scratch` first.
void sharedInputsToPostfx(const WorldTransform& world, FrameInfo& frame, WorldScratch& scratch);

}  // namespace postfx::core
