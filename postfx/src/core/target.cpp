#include "core/target.h"

#include "common/shared.h"
#include "core/checks.h"
#include "postfx_objects_spirv.h"

namespace postfx::core {
namespace {

// Transfer passes are named by a description without SPIR-V (FrameBuilder::transfer).
const ComputePipelineDesc kTargetLoad{"postfx.target_load", {}, {}, 0};
const ComputePipelineDesc kTargetStore{"postfx.target_store", {}, {}, 0};

// The compute store (shaders/core/copy.comp), per host format it has a storage format qualifier for.
constexpr Binding kStoreBindings[] = {{gpu::kCopyBindingIn, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                      {gpu::kCopyBindingOut, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};
const ComputePipelineDesc kStoreR11G11B10{"postfx.target_store", spirv::core_copy_comp_OUT_R11G11B10,
                                          kStoreBindings, 8};
const ComputePipelineDesc kStoreRGB10A2{"postfx.target_store", spirv::core_copy_comp_OUT_RGB10A2,
                                        kStoreBindings, 8};
const ComputePipelineDesc kStoreRGBA8{"postfx.target_store", spirv::core_copy_comp_OUT_RGBA8, kStoreBindings,
                                      8};
const ComputePipelineDesc kStoreRGBA16{"postfx.target_store", spirv::core_copy_comp_OUT_RGBA16,
                                       kStoreBindings, 8};

const ComputePipelineDesc* computeStore(VkFormat format) {
    switch (format) {
        case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
            return &kStoreR11G11B10;
        case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
            return &kStoreRGB10A2;
        case VK_FORMAT_R8G8B8A8_UNORM:
            return &kStoreRGBA8;
        case VK_FORMAT_R16G16B16A16_UNORM:
            return &kStoreRGBA16;
        default:
            return nullptr;
    }
}

bool hasFeature(const Gpu& gpu, VkFormat format, VkFormatFeatureFlags feature) {
    VkFormatProperties properties{};
    gpu.fn.vkGetPhysicalDeviceFormatProperties(gpu.physicalDevice, format, &properties);
    return (properties.optimalTilingFeatures & feature) == feature;
}

}  // namespace

Status checkTargetFeatures(const Gpu& gpu, const FrameInfo& frame, TargetStore& store) {
    store = TargetStore::Blit;
    if (compositesInPlace(frame.color)) return Status::success();
    if (!hasFeature(gpu, frame.color.format, VK_FORMAT_FEATURE_BLIT_SRC_BIT))
        return invalid("FrameInfo.color.format " + formatName(frame.color.format) +
                       ": the device cannot blit from it (VK_FORMAT_FEATURE_BLIT_SRC_BIT, optimal tiling), "
                       "which postfx needs to composite into it");
    const bool separate = frame.output.present();
    const ImageInput& written = separate ? frame.output : frame.color;
    if (hasFeature(gpu, written.format, VK_FORMAT_FEATURE_BLIT_DST_BIT)) return Status::success();
    const std::string field = separate ? "FrameInfo.output" : "FrameInfo.color";
    if (!computeStore(written.format) ||
        !hasFeature(gpu, written.format, VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT))
        return invalid(field + ".format " + formatName(written.format) +
                       ": the device can neither blit into it (VK_FORMAT_FEATURE_BLIT_DST_BIT, optimal "
                       "tiling) nor store to it from a shader, which postfx needs to composite into it");
    if (!(written.usage & VK_IMAGE_USAGE_STORAGE_BIT))
        return invalid(field + ".usage lacks VK_IMAGE_USAGE_STORAGE_BIT (the device cannot blit into " +
                       formatName(written.format) + ", so postfx stores its result from a shader)");
    store = TargetStore::Compute;
    return Status::success();
}

void declareTargetLoad(const FrameGraph& graph, Frame& f) {
    f.target = kNoResource;
    if (compositesInPlace(f.info->color)) return;
    FrameBuilder b(graph, f, -1);
    ImageDesc desc;
    desc.format = f.info->color.format == VK_FORMAT_R32G32B32A32_SFLOAT ? VK_FORMAT_R32G32B32A32_SFLOAT
                                                                        : VK_FORMAT_R16G16B16A16_SFLOAT;
    desc.extent = {f.info->color.extent.width, f.info->color.extent.height, 1};
    desc.usage =
        VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    const ImageRef target = b.transientImage(kTargetImage, desc);
    b.transfer(kTargetLoad, TransferOp::Blit, b.host(HostImage::Color), target);
    f.target = target.index;
}

void declareTargetStore(const FrameGraph& graph, Frame& f, TargetStore store) {
    if (f.target == kNoResource || !f.composited) return;
    FrameBuilder b(graph, f, -1);
    const bool separate = f.info->output.present();
    const ImageRef written = b.host(separate ? HostImage::Output : HostImage::Color);
    if (store == TargetStore::Blit) {
        b.transfer(kTargetStore, TransferOp::Blit, {f.target}, written);
        return;
    }
    const VkExtent2D e = f.info->color.extent;
    const uint32_t g = gpu::kCopyGroupSize;
    const uint32_t extent[2] = {e.width, e.height};
    b.pass(*computeStore((separate ? f.info->output : f.info->color).format), (e.width + g - 1) / g,
           (e.height + g - 1) / g, 1)
        .bind(gpu::kCopyBindingIn, {f.target}, Use::StorageRead)
        .bind(gpu::kCopyBindingOut, written, Use::StorageWrite)
        .push(extent, sizeof extent);
}

}  // namespace postfx::core
