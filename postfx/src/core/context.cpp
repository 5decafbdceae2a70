#include <postfx/context.h>

#include "core/barriers.h"
#include "core/context_impl.h"
#include "core/copy_pass.h"

#include <string>

namespace postfx {

namespace {

constexpr uint32_t kMaxFramesInFlight = 8;
constexpr uint32_t kDescriptorSetsPerFrame = 64;

Status invalid(std::string message) {
    return {Result::InvalidArgument, std::move(message)};
}

Status validateCreateInfo(const ContextCreateInfo& info) {
    if (!info.instance) return invalid("ContextCreateInfo.instance is VK_NULL_HANDLE");
    if (!info.physicalDevice) return invalid("ContextCreateInfo.physicalDevice is VK_NULL_HANDLE");
    if (!info.device) return invalid("ContextCreateInfo.device is VK_NULL_HANDLE");
    if (!info.getInstanceProcAddr) return invalid("ContextCreateInfo.getInstanceProcAddr is null");
    if (!info.getDeviceProcAddr) return invalid("ContextCreateInfo.getDeviceProcAddr is null");
    if (info.maxExtent.width == 0 || info.maxExtent.height == 0)
        return invalid("ContextCreateInfo.maxExtent is " + std::to_string(info.maxExtent.width) + "x" +
                       std::to_string(info.maxExtent.height) + ": both sides must be > 0");
    if (info.framesInFlight == 0 || info.framesInFlight > kMaxFramesInFlight)
        return invalid("ContextCreateInfo.framesInFlight is " + std::to_string(info.framesInFlight) +
                       ": must be in 1.." + std::to_string(kMaxFramesInFlight));
    return Status::success();
}

bool isColorFormat(VkFormat f) {
    return f == VK_FORMAT_R16G16B16A16_SFLOAT || f == VK_FORMAT_R32G32B32A32_SFLOAT;
}

bool isDepthFormat(VkFormat f) {
    return f == VK_FORMAT_D32_SFLOAT || f == VK_FORMAT_D16_UNORM || f == VK_FORMAT_D24_UNORM_S8_UINT ||
           f == VK_FORMAT_X8_D24_UNORM_PACK32 || f == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

std::string extentText(VkExtent2D e) {
    return std::to_string(e.width) + "x" + std::to_string(e.height);
}

Status validateImage(const ImageInput& image, const char* name, bool (*formatOk)(VkFormat),
                     const char* formats, VkExtent2D maxExtent) {
    const std::string n = std::string("FrameInfo.") + name;
    if (!image.present()) return invalid(n + ".image is VK_NULL_HANDLE");
    if (!image.view) return invalid(n + ".view is VK_NULL_HANDLE");
    if (!formatOk(image.format))
        return invalid(n + ".format " + std::to_string(image.format) + " is not supported (expected " +
                       formats + ")");
    if (image.extent.width == 0 || image.extent.height == 0)
        return invalid(n + ".extent is " + extentText(image.extent));
    if (image.extent.width > maxExtent.width || image.extent.height > maxExtent.height)
        return invalid(n + ".extent " + extentText(image.extent) + " exceeds ContextCreateInfo.maxExtent " +
                       extentText(maxExtent));
    if (image.layout == VK_IMAGE_LAYOUT_UNDEFINED || image.layout == VK_IMAGE_LAYOUT_PREINITIALIZED)
        return invalid(n + ".layout is UNDEFINED/PREINITIALIZED: postfx needs the image's contents");
    return Status::success();
}

// `frame` with the fog's steps, jitter, shadow kernel and resolution scale set by `preset`
// (Context::record and plan).
FrameInfo withFogPreset(const FrameInfo& frame, FogQuality preset) {
    FrameInfo resolved = frame;
    resolved.fog = applyFogQuality(frame.fog, preset);
    resolved.fog.quality = preset;
    return resolved;
}

// A separate output that no effect writes still gets the host's color (postfx.copy).
bool needsCopy(const FrameInfo& frame, bool fogRuns) {
    return frame.output.present() && !fogRuns;
}

}  // namespace

Status Context::Impl::report(Status status) const {
    if (!status.ok() && info.messageCallback)
        info.messageCallback(MessageSeverity::Error, status.message.c_str(), info.messageUserData);
    return status;
}

void Context::Impl::warn(const std::string& message) const {
    if (info.messageCallback)
        info.messageCallback(MessageSeverity::Warning, message.c_str(), info.messageUserData);
}

Status Context::create(const ContextCreateInfo& info, std::unique_ptr<Context>& out) {
    out.reset();
    auto fail = [&](Status s) {
        if (info.messageCallback)
            info.messageCallback(MessageSeverity::Error, s.message.c_str(), info.messageUserData);
        return s;
    };
    if (Status s = validateCreateInfo(info); !s) return fail(s);

    auto impl = std::make_unique<Impl>();
    impl->info = info;
    core::Gpu& gpu = impl->gpu;
    if (Status s = gpu.init(info); !s) return fail(s);

    uint32_t familyCount = 0;
    gpu.fn.vkGetPhysicalDeviceQueueFamilyProperties(info.physicalDevice, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    gpu.fn.vkGetPhysicalDeviceQueueFamilyProperties(info.physicalDevice, &familyCount, families.data());
    if (info.queueFamilyIndex >= familyCount)
        return fail(invalid("ContextCreateInfo.queueFamilyIndex " + std::to_string(info.queueFamilyIndex) +
                            " is out of range (the device has " + std::to_string(familyCount) +
                            " families)"));
    const VkQueueFamilyProperties& family = families[info.queueFamilyIndex];
    if (!(family.queueFlags & VK_QUEUE_COMPUTE_BIT))
        return fail(invalid("ContextCreateInfo.queueFamilyIndex " + std::to_string(info.queueFamilyIndex) +
                            " does not support compute"));

    if (Status s =
            impl->timer.create(gpu, info.framesInFlight, info.gpuTimings ? family.timestampValidBits : 0);
        !s)
        return fail(s);
    if (info.gpuTimings && family.timestampValidBits == 0)
        impl->warn("queue family " + std::to_string(info.queueFamilyIndex) +
                   " has no timestamps: no GPU timings");
    for (uint32_t i = 0; i < info.framesInFlight; ++i) {
        impl->arenas.push_back(std::make_unique<core::DescriptorArena>());
        if (Status s = impl->arenas.back()->create(gpu, kDescriptorSetsPerFrame); !s) return fail(s);
    }
    out.reset(new Context(std::move(impl)));
    return Status::success();
}

Context::Context(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Context::~Context() = default;

const ContextCreateInfo& Context::createInfo() const {
    return impl_->info;
}

Status Context::Impl::validateFrame(const FrameInfo& frame) const {
    if (Status s = validateImage(frame.color, "color", isColorFormat,
                                 "R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT", info.maxExtent);
        !s)
        return s;
    if (Status s = validateImage(frame.depth, "depth", isDepthFormat, "a depth format", info.maxExtent); !s)
        return s;
    if (frame.depth.extent.width != frame.color.extent.width ||
        frame.depth.extent.height != frame.color.extent.height)
        return invalid("FrameInfo.depth.extent " + extentText(frame.depth.extent) +
                       " differs from FrameInfo.color.extent " + extentText(frame.color.extent));
    if (frame.fog.enabled) return fog::FogPass::validate(frame);
    return Status::success();
}

void Context::Impl::buildPlan(const FrameInfo& frame, FramePlan& plan) const {
    plan = {};
    const bool fogRuns = fog::FogPass::runs(frame);
    if (fogRuns) fog::FogPass::plan(frame, fog.get(), info.framesInFlight, plan);
    if (needsCopy(frame, fogRuns)) plan.passes.push_back(core::CopyPass::plan(frame));
}

Status Context::plan(const FrameInfo& frame, FramePlan& out) const {
    out = {};
    const Impl& impl = *impl_;
    // A preset can change the passes and resources (its resolution scale): Auto is planned as the preset
    // record() would use now (a copy of its state selects; nothing is collected or measured).
    FogQuality preset = frame.fog.quality;
    if (preset == FogQuality::Auto) {
        fog::AutoQuality copy = impl.fogAutoQuality;
        preset = copy.select(fog::AutoQualityKey::of(frame), frame.fog.autoBudgetMs, impl.timer);
    }
    const FrameInfo resolved =
        fog::FogPass::runs(frame) && preset != FogQuality::Custom ? withFogPreset(frame, preset) : frame;
    if (Status s = impl.validateFrame(resolved); !s) return impl.report(s);
    impl.buildPlan(resolved, out);
    return Status::success();
}

Status Context::record(const FrameInfo& frame) {
    Impl& impl = *impl_;
    if (!frame.commandBuffer) return impl.report(invalid("FrameInfo.commandBuffer is VK_NULL_HANDLE"));
    if (Status s = validateImage(frame.color, "color", isColorFormat,
                                 "R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT", impl.info.maxExtent);
        !s)
        return impl.report(s);

    // Quality presets replace steps/jitter/shadowKernel/resolutionScale before the checks; Auto picks the
    // preset (reading finished frames' timings, so before the timer starts this frame).
    FrameInfo resolved;
    const FrameInfo* effective = &frame;
    const fog::AutoQualityKey autoKey = fog::AutoQualityKey::of(frame);
    const bool fogRuns = fog::FogPass::runs(frame);
    if (fogRuns && frame.fog.quality != FogQuality::Custom) {
        FogQuality preset = frame.fog.quality;
        if (preset == FogQuality::Auto) {
            if (!impl.timer.enabled() && !impl.warnedAutoWithoutTimings) {
                impl.warnedAutoWithoutTimings = true;
                impl.warn(
                    "fog quality Auto without GPU timings (gpuTimings off or unsupported): using Medium");
            }
            preset = impl.fogAutoQuality.select(autoKey, frame.fog.autoBudgetMs, impl.timer);
        }
        resolved = withFogPreset(frame, preset);
        effective = &resolved;
    }
    if (Status s = impl.validateFrame(*effective); !s) return impl.report(s);

    core::DescriptorArena& arena = impl.arena(frame.frameIndex);
    if (Status s = arena.beginFrame(); !s) return impl.report(s);
    impl.timer.beginFrame(frame.commandBuffer, frame.frameIndex);
    impl.retirement.collect(frame.frameIndex, impl.info.framesInFlight);
    if (fogRuns) {
        if (!impl.fog) impl.fog = std::make_unique<fog::FogPass>();
        if (Status s = impl.fog->record(impl.gpu, impl.info, arena, impl.timer, impl.retirement, *effective);
            !s)
            return impl.report(s);
        if (frame.fog.quality == FogQuality::Auto)
            impl.fogAutoQuality.recorded(frame.frameIndex, autoKey, effective->fog.quality);
    } else {
        // Off or empty: nothing recorded, and its GPU objects go once the frames in flight are done.
        impl.retirement.retire(frame.frameIndex, std::move(impl.fog));
    }
    if (needsCopy(frame, fogRuns)) {
        if (Status s = impl.copy.record(impl.gpu, arena, impl.timer, *effective); !s) return impl.report(s);
    }
    return Status::success();
}

Status Context::fogAutoQuality(FogQuality& chosen) const {
    return impl_->fogAutoQuality.chosen(chosen);
}

std::vector<FogAutoTimings> Context::fogAutoTimings() const {
    return impl_->fogAutoQuality.timings();
}

Status Context::setFogAutoTimings(const std::vector<FogAutoTimings>& timings) {
    return impl_->report(impl_->fogAutoQuality.give(timings));
}

Status Context::recordFogNoiseReadback(VkCommandBuffer commandBuffer, VkBuffer buffer, VkDeviceSize offset,
                                       uint32_t& size) const {
    const fog::FogNoise* noise = impl_->fog ? impl_->fog->noise() : nullptr;
    if (!commandBuffer)
        return impl_->report(invalid("recordFogNoiseReadback: commandBuffer is VK_NULL_HANDLE"));
    if (!buffer) return impl_->report(invalid("recordFogNoiseReadback: buffer is VK_NULL_HANDLE"));
    if (!noise || !noise->ready())
        return impl_->report(invalid("recordFogNoiseReadback: no fog noise texture has been generated yet"));
    size = noise->size();
    return impl_->report(noise->recordReadback(commandBuffer, buffer, offset));
}

VkImageView Context::fogNoiseView() const {
    const fog::FogNoise* noise = impl_->fog ? impl_->fog->noise() : nullptr;
    return noise && noise->ready() ? noise->view() : VK_NULL_HANDLE;
}

Status Context::readPassTimings(uint64_t frameIndex, std::vector<PassTiming>& out) const {
    Status s = impl_->timer.read(frameIndex, out);
    return s.code == Result::NotReady ? s : impl_->report(std::move(s));
}

}  // namespace postfx
