#include "common/medium_noise.h"

#include "common/medium_shared.h"

namespace postfx::common {

bool noiseFormatSupported(const core::Gpu& gpu) {
    VkFormatProperties props{};
    gpu.fn.vkGetPhysicalDeviceFormatProperties(gpu.physicalDevice, kNoiseFormat, &props);
    const VkFormatFeatureFlags needed =
        VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
        VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT;
    return (props.optimalTilingFeatures & needed) == needed;
}

Status checkNoiseSupported(const FogNoiseSettings& noise, bool formatSupported, const std::string& prefix) {
    if (!noise.enabled || noise.hostTexture || formatSupported) return Status::success();
    return {Result::Unsupported,
            prefix +
                ".noise: the device cannot use VK_FORMAT_R8_UNORM as a storage image, linearly filtered "
                "sampled image and transfer source (give " +
                prefix + ".noise.hostTexture instead)"};
}

core::ImageRef declareGeneratedNoise(core::FrameBuilder& b, const core::ResourceId& id,
                                     const core::ComputePipelineDesc& pass, uint32_t size, uint32_t seed,
                                     uint32_t kind, const char* sizedBy) {
    core::ImageDesc desc;
    desc.sizedBy = sizedBy;
    desc.type = VK_IMAGE_TYPE_3D;
    desc.format = kNoiseFormat;
    desc.extent = {size, size, size};
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    // The key names the formula too: a texture of the same formula, size and seed another effect declared
    // this frame is the same texture, shared (the fogs' noise and the clouds' base noise).
    const uint64_t key = (uint64_t(kind) << 56) | (uint64_t(size) << 32) | seed;
    if (const core::ImageRef shared = b.findPersistent(id, desc, key); shared.valid()) return shared;
    const core::ImageRef image = b.persistentImage(id, desc, key);
    const uint32_t groups = size / gpu::kNoiseGroupSize;
    const gpu::NoisePush push{glm::uvec4(size, seed, kind, 0u)};
    b.pass(pass, groups, groups, groups)
        .bind(gpu::kNoiseBindingTexture, image, core::Use::StorageWrite)
        .push(&push, sizeof push);
    return image;
}

core::ImageRef declareNoise(core::FrameBuilder& b, const FogNoiseSettings& noise, const NoiseDeclaration& d) {
    if (noise.enabled && !noise.hostTexture)
        return declareGeneratedNoise(b, d.generated, d.generatePass, noise.textureSize, noise.seed,
                                     gpu::kNoisePerlinWorley, d.sizedBy);
    if (noise.enabled) return b.external("host.noise", noise.hostTexture, noise.hostTextureLayout);
    core::ImageDesc one;
    one.type = VK_IMAGE_TYPE_3D;
    one.format = kNoiseFormat;
    one.usage = VK_IMAGE_USAGE_SAMPLED_BIT;
    return b.transientImage(d.none, one);
}

}  // namespace postfx::common
