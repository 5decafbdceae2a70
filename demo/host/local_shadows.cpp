#include "host/local_shadows.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <bit>
#include <cmath>

namespace demo {
namespace {

constexpr uint32_t kMinFaceResolution = 16;

// Right-handed view space (looking down -z) -> clip with depth z/w = f/(f-n) · (1 - n/d) in [0, 1] at view
// depth d in [n, f]; x, y in [-1, 1] across a square of half angle atan(tanHalf).
glm::dmat4 perspectiveZeroToOne(double tanHalf, double n, double f) {
    glm::dmat4 p(0.0);
    p[0][0] = 1.0 / tanHalf;
    p[1][1] = 1.0 / tanHalf;
    p[2][2] = f / (n - f);
    p[2][3] = -1.0;
    p[3][2] = n * f / (n - f);
    return p;
}

// The axis and up vector of cube face i: +X, -X, +Y, -Y, +Z, -Z.
struct CubeFace {
    glm::dvec3 axis, up;
};
constexpr CubeFace kCubeFaces[6] = {
    {{1, 0, 0}, {0, -1, 0}},  {{-1, 0, 0}, {0, -1, 0}}, {{0, 1, 0}, {0, 0, 1}},
    {{0, -1, 0}, {0, 0, -1}}, {{0, 0, 1}, {0, -1, 0}},  {{0, 0, -1}, {0, -1, 0}},
};

// One light's faces (matrices and resolution; the regions are placed later).
struct LightFaces {
    postfx::LocalShadow shadow;
    uint32_t resolution = 0;
    double depthPerInverseDistance = 0.0;  // n·f/(f-n): z changes by this / d² per metre at distance d
};

LightFaces lightFaces(const Light& light) {
    LightFaces out;
    const bool singleFace = light.kind == LightKind::Spot && light.outerAngleDeg <= kMaxSpotFaceOuterDeg;
    const double n = std::max(double(kMinShadowNear), double(light.radius));
    const double f = std::max(double(light.range), 2.0 * n);
    const double tanHalf =
        singleFace ? std::tan(glm::radians(double(light.outerAngleDeg) + double(kSpotMarginDeg))) : 1.0;
    const glm::dmat4 projection = perspectiveZeroToOne(tanHalf, n, f);
    const glm::dvec3 position(light.position);
    postfx::LocalShadow& s = out.shadow;
    s.reversedZ = false;
    if (singleFace) {
        const glm::dvec3 axis = glm::normalize(glm::dvec3(light.direction));
        const glm::dvec3 up = std::abs(axis.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
        s.faceCount = 1;
        s.faces[0].worldToClip = projection * glm::lookAtRH(position, position + axis, up);
    } else {
        s.faceCount = 6;
        for (uint32_t i = 0; i < 6; ++i) {
            const CubeFace& c = kCubeFaces[i];
            s.faces[i].worldToClip = projection * glm::lookAtRH(position, position + c.axis, c.up);
        }
    }
    out.resolution = light.shadowResolution;
    out.depthPerInverseDistance = n * f / (f - n);
    return out;
}

struct Item {
    uint32_t shadow, face, resolution;
};

// Shelf packing of `items` (sorted, largest first) into rows of `width` texels: the height used.
uint32_t pack(std::vector<Item>& items, uint32_t width, std::vector<LightFaces>& faces) {
    uint32_t x = 0, y = 0, shelf = 0;
    for (const Item& it : items) {
        if (x + it.resolution > width) {
            y += shelf;
            x = 0;
            shelf = 0;
        }
        postfx::LocalShadowFace& face = faces[it.shadow].shadow.faces[it.face];
        face.offset = postfx::UVec2(x, y);
        face.extent = postfx::UVec2(it.resolution);
        x += it.resolution;
        shelf = std::max(shelf, it.resolution);
    }
    return y + shelf;
}

}  // namespace

double shadowTexelAngle(const postfx::LocalShadowFace& face) {
    const glm::dmat4& m = face.worldToClip;
    const double xScale = glm::length(glm::dvec3(m[0][0], m[1][0], m[2][0]));
    return 2.0 / (xScale * double(face.extent.x));
}

LocalShadowLayout layoutLocalShadows(std::span<const Light> lights, uint32_t maxEdge) {
    LocalShadowLayout out;
    out.lightShadow.assign(lights.size(), postfx::kNoLocalShadow);
    std::vector<LightFaces> faces;
    for (size_t i = 0; i < lights.size(); ++i) {
        if (!lights[i].shadows) continue;
        out.lightShadow[i] = uint32_t(faces.size());
        faces.push_back(lightFaces(lights[i]));
        out.faceCount += faces.back().shadow.faceCount;
    }
    if (faces.empty()) return out;

    maxEdge = std::max(maxEdge, kMinFaceResolution);
    for (uint32_t shift = 0;; ++shift) {
        std::vector<Item> items;
        uint64_t area = 0;
        uint32_t largest = 0;
        for (uint32_t s = 0; s < faces.size(); ++s) {
            const uint32_t r = std::min(std::max(faces[s].resolution >> shift, kMinFaceResolution), maxEdge);
            for (uint32_t f = 0; f < faces[s].shadow.faceCount; ++f)
                items.push_back({s, f, r});
            area += uint64_t(r) * r * faces[s].shadow.faceCount;
            largest = std::max(largest, r);
        }
        std::stable_sort(items.begin(), items.end(),
                         [](const Item& a, const Item& b) { return a.resolution > b.resolution; });
        // About square: the power of two at least the side of the faces' total area.
        const auto side = uint32_t(std::ceil(std::sqrt(double(area))));
        const uint32_t width = std::min(std::max(std::bit_ceil(side), largest), maxEdge);
        const uint32_t height = pack(items, width, faces);
        const bool smallest = largest == kMinFaceResolution;
        if (height <= maxEdge || smallest) {  // 1536 faces of 16² fit far below any device's limit
            out.extent = glm::uvec2(width, height);
            out.resolutionShift = shift;
            break;
        }
    }
    for (LightFaces& lf : faces) {
        postfx::LocalShadow& s = lf.shadow;
        // One texel at 45° at kShadowBiasDistance (local_shadows.h); every face of a light has the same.
        s.depthBias = float(lf.depthPerInverseDistance * shadowTexelAngle(s.faces[0]) / kShadowBiasDistance);
        out.shadows.push_back(s);
    }
    return out;
}

}  // namespace demo
