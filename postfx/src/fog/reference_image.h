// The image side of the CPU references, shared by the ray-marched fog's (fog_reference.cpp) and the
// froxel fog's (froxel_fog/froxel_reference.cpp): pixel rays, the composite, rows spread over threads.
#pragma once

#include <postfx/inputs.h>
#include <postfx/result.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <thread>
#include <vector>

namespace postfx::reference::detail {

// InvalidArgument "<field>: <count> values, expected <expected> (<what>)" unless count == expected.
Status checkCount(const char* field, size_t count, uint64_t expected, const char* what);

// Rotation-only view: the view matrix with its translation column zeroed (the march is camera-relative).
glm::dmat4 clipToView(const CameraInput& camera);

struct PixelRay {
    glm::dvec3 d;     // unit direction, camera-relative world space
    double distance;  // D_s: to the surface, ∞ for no geometry
};

// Ray: ndc of the pixel centre, p = clipToView · (ndc, z, 1), x_s = p.xyz / p.w, D_s = |x_s|, d = x_s / D_s.
// No geometry (z exactly `farDepth`): d from z = 0.5, D_s = ∞.
PixelRay pixelRay(const glm::dmat4& clipToView, double farDepth, uint32_t width, uint32_t height, uint32_t i,
                  uint32_t j, double z);

// Composite: out.rgb = color.rgb · T + L, out.a = color.a, as the GPU does it (shaders/fog/composite.glsl):
// ±Inf color counts as ±FLT_MAX, the result is clamped to ±FLT_MAX, a NaN channel stays NaN.
void composite(const glm::dvec3& L, double T, const float* color, float* out);

// Runs `rowTask(j)` for rows 0..rows-1 on `threads` threads (0: all hardware threads). Rows are
// independent, so the result does not depend on how they are shared out.
template <class RowTask>
void forEachRow(uint32_t rows, uint32_t threads, const RowTask& rowTask) {
    std::atomic<uint32_t> nextRow{0};
    auto work = [&] {
        for (uint32_t j; (j = nextRow.fetch_add(1)) < rows;)
            rowTask(j);
    };
    threads = std::min(threads ? threads : std::max(1u, std::thread::hardware_concurrency()), rows);
    std::vector<std::thread> pool;
    try {
        pool.reserve(threads - 1);
        for (uint32_t t = 1; t < threads; ++t)
            pool.emplace_back(work);
    } catch (const std::exception&) {
        // Fewer threads than asked for: the ones running (and this one) take all rows.
    }
    work();
    for (std::thread& t : pool)
        t.join();
}

}  // namespace postfx::reference::detail
