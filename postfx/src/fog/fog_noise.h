// The fog's generated noise texture: a tileable Perlin–Worley fBm in an R8_UNORM size³ 3D image,
// made on the GPU by shaders/fog/noise_generate.comp (formula in shaders/common/noise.glsl).
//
// A slow input: the texture is generated once and again only when its size or seed changes. Nothing is
// allocated until prepare() is first called; release() frees everything.
#pragma once

#include "core/compute_pipeline.h"
#include "core/gpu_resources.h"

#include <cstdint>

namespace postfx::fog {

class FogNoise {
public:
    FogNoise() = default;
    FogNoise(const FogNoise&) = delete;
    FogNoise& operator=(const FogNoise&) = delete;
    ~FogNoise() { release(); }

    // Makes sure an R8_UNORM size³ texture exists for (size, seed): creates the pipeline and the image
    // on first need, recreates the image when the size changes, and marks the texture for generation
    // when (size, seed) differs from what was last generated. `size`: a power of two in [16, 256].
    // Recreating the image destroys the old one at once: the caller must make sure no submitted
    // command still uses it (e.g. the device is idle, or the frames that sampled it have completed).
    Status prepare(const core::Gpu& gpu, uint32_t size, uint32_t seed);

    // If marked, records the generation (a dispatch between two barriers) and returns true: the image
    // is then in SHADER_READ_ONLY_OPTIMAL, its texels visible to compute-shader reads of later
    // commands. Otherwise records nothing and returns false. `status` is set (an error only when a
    // descriptor set could not be allocated; the texture then stays marked).
    bool recordGenerate(VkCommandBuffer cmd, core::DescriptorArena& arena, Status& status);

    // Copies the texture (which must be ready()) into `dst` at `offset`: size³ bytes, x fastest, then
    // y, then z (dst needs TRANSFER_DST usage and no pending use by earlier commands). Records the
    // barriers around the copy: the image returns to SHADER_READ_ONLY_OPTIMAL (visible to compute
    // reads) and the copied bytes are made visible to the host once the submission has completed.
    Status recordReadback(VkCommandBuffer cmd, VkBuffer dst, VkDeviceSize offset) const;

    VkImageView view() const { return image_.view(); }     // VK_NULL_HANDLE before prepare()
    uint32_t size() const { return size_; }                // edge [texels]; 0 before prepare()
    VkDeviceSize bytes() const { return image_.bytes(); }  // device memory held by the texture
    VkDeviceSize texelBytes() const { return VkDeviceSize(size_) * size_ * size_; }  // read-back size
    // The texture exists and its generation for the current (size, seed) has been recorded.
    bool ready() const { return image_.handle() != VK_NULL_HANDLE && generated_ && !pending_; }

    bool needsGeneration() const { return pending_; }  // recordGenerate() would record a dispatch
    // After prepare(size, seed), recordGenerate() would record a dispatch.
    bool wouldGenerate(uint32_t size, uint32_t seed) const {
        return !image_.handle() || size != size_ || seed != seed_ || pending_;
    }

    void release();  // frees the image and the pipeline (no-op when nothing is held)

private:
    const core::Gpu* gpu_ = nullptr;
    core::ComputePipeline pipeline_;
    core::GpuImage image_;
    uint32_t size_ = 0;
    uint32_t seed_ = 0;
    bool pending_ = false;    // (size, seed) changed since the last recorded generation
    bool generated_ = false;  // a generation into image_ has been recorded (it may be sampled or copied)
};

}  // namespace postfx::fog
