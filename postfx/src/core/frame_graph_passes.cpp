// The graph's two built-in passes: postfx.copy (a separate output no effect writes gets the color) and
// postfx.view_distance (the host's depth as surface distances, once for the effects that read it).
#include "core/frame_graph.h"

#include "common/shared.h"
#include "core/camera_math.h"
#include "core/frame_graph_internal.h"
#include "core/target.h"
#include "postfx_objects_spirv.h"

namespace postfx::core {
namespace {

// postfx.copy (shaders/core/copy.comp): output = color, for a frame with a separate output image that no
// effect writes.
constexpr Binding kCopyBindings[] = {{gpu::kCopyBindingIn, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                     {gpu::kCopyBindingOut, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};
const ComputePipelineDesc kCopy16{"postfx.copy", spirv::core_copy_comp, kCopyBindings, 8};
const ComputePipelineDesc kCopy32{"postfx.copy", spirv::core_copy_comp_COLOR_RGBA32F, kCopyBindings, 8};

// postfx.view_distance (shaders/core/view_distance.comp): the host's depth as surface distances, once for
// every effect that reads it.
constexpr Binding kViewDistanceBindings[] = {
    {gpu::kViewDistanceBindingDepth, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
    {gpu::kViewDistanceBindingOut, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};
const ComputePipelineDesc kViewDistance{"postfx.view_distance", spirv::core_view_distance_comp,
                                        kViewDistanceBindings, sizeof(gpu::ViewDistancePush)};
inline constexpr ResourceId kViewDistanceImage{"postfx.view_distance"};

// The same as a copy command, for a color target postfx does not composite in place (core/target.h):
// same format, bit for bit.
const ComputePipelineDesc kCopyTransfer{"postfx.copy", {}, {}, 0};

}  // namespace

void declareOutputCopy(const FrameGraph& graph, Frame& f) {
    const uint16_t output = f.host[size_t(HostImage::Output)];
    if (!compositesInPlace(f.info->color)) {
        FrameBuilder b(graph, f, -1);
        b.transfer(kCopyTransfer, TransferOp::Copy, {f.host[size_t(HostImage::Color)]}, {output});
        f.passes.back().live = true;
        return;
    }
    const VkExtent2D e = f.info->color.extent;
    const ComputePipelineDesc& copy =
        f.info->color.format == VK_FORMAT_R32G32B32A32_SFLOAT ? kCopy32 : kCopy16;
    FrameBuilder b(graph, f, -1);
    const uint32_t g = gpu::kCopyGroupSize;
    const uint32_t extent[2] = {e.width, e.height};
    b.pass(copy, (e.width + g - 1) / g, (e.height + g - 1) / g, 1)
        .bind(gpu::kCopyBindingIn, {f.host[size_t(HostImage::Color)]}, Use::StorageRead)
        .bind(gpu::kCopyBindingOut, {output}, Use::StorageWrite)
        .push(extent, sizeof extent);
    f.passes.back().live = true;
}

DepthInput FrameBuilder::depthInput() {
    const ImageRef depth = host(HostImage::Depth);
    if (!f_.shareDepth) return {depth, false};
    if (const ImageRef shared = find(kViewDistanceImage); shared.valid()) return {shared, true};
    // Declared by the context (effect -1), before the first reader's passes.
    FrameBuilder context(graph_, f_, -1);
    const VkExtent2D e = f_.info->color.extent;
    ImageDesc desc;
    desc.format = VK_FORMAT_R32_SFLOAT;
    desc.extent = {e.width, e.height, 1};
    const ImageRef distance = context.transientImage(kViewDistanceImage, desc);
    gpu::ViewDistancePush push{};
    const FrameInfo& info = *f_.info;
    push.clipToView =
        glm::mat4(glm::inverse(glm::dmat4(info.camera.projection) * rotationOnly(info.camera.view)));
    push.params = glm::vec4(depthConvention().reversedZ ? 0.0f : 1.0f, float(e.width), float(e.height), 0.0f);
    const uint32_t g = gpu::kViewDistanceGroupSize, rows = g * gpu::kViewDistanceRows;
    context.pass(kViewDistance, (e.width + g - 1) / g, (e.height + rows - 1) / rows, 1)
        .bind(gpu::kViewDistanceBindingDepth, depth, Use::Sampled)
        .bind(gpu::kViewDistanceBindingOut, distance, Use::StorageWrite)
        .push(&push, sizeof push);
    return {distance, true};
}

}  // namespace postfx::core
