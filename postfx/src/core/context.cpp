#include <postfx/context.h>

#include "core/checks.h"
#include "core/context_impl.h"
#include "core/lookup_volume.h"
#include "core/memory_budget.h"
#include "core/target.h"
#include "core/world_frame.h"
#include "effects.h"

#include <algorithm>
#include <string>

namespace postfx {

namespace {

constexpr uint32_t kMaxFramesInFlight = 8;
constexpr uint32_t kDescriptorSetsPerFrame = 64;

Status validateCreateInfo(const ContextCreateInfo& info) {
    using core::invalid;
    if (info.structSize != sizeof(ContextCreateInfo))
        return invalid("ContextCreateInfo.structSize " + std::to_string(info.structSize) +
                       " differs from the library's " + std::to_string(sizeof(ContextCreateInfo)) +
                       ": the host was compiled with another postfx header or struct packing");
    if (!info.instance) return invalid("ContextCreateInfo.instance is VK_NULL_HANDLE");
    if (!info.physicalDevice) return invalid("ContextCreateInfo.physicalDevice is VK_NULL_HANDLE");
    if (!info.device) return invalid("ContextCreateInfo.device is VK_NULL_HANDLE");
    if (!info.getInstanceProcAddr) return invalid("ContextCreateInfo.getInstanceProcAddr is null");
    if (!info.getDeviceProcAddr) return invalid("ContextCreateInfo.getDeviceProcAddr is null");
    if (const VkAllocationCallbacks* a = info.allocator) {
        // What Vulkan requires of VkAllocationCallbacks (postfx passes them to every create and destroy).
        if (!a->pfnAllocation) return invalid("ContextCreateInfo.allocator->pfnAllocation is null");
        if (!a->pfnReallocation) return invalid("ContextCreateInfo.allocator->pfnReallocation is null");
        if (!a->pfnFree) return invalid("ContextCreateInfo.allocator->pfnFree is null");
        if (!a->pfnInternalAllocation != !a->pfnInternalFree)
            return invalid(
                "ContextCreateInfo.allocator->pfnInternalAllocation and pfnInternalFree: give both or "
                "neither");
    }
    if (!info.deviceMemory.allocate != !info.deviceMemory.free)
        return invalid(std::string("ContextCreateInfo.deviceMemory.") +
                       (info.deviceMemory.allocate ? "free" : "allocate") +
                       " is null: give both allocate and free, or neither");
    if (info.maxExtent.width == 0 || info.maxExtent.height == 0)
        return invalid("ContextCreateInfo.maxExtent is " + core::extentText(info.maxExtent) +
                       ": both sides must be > 0");
    if (info.framesInFlight == 0 || info.framesInFlight > kMaxFramesInFlight)
        return invalid("ContextCreateInfo.framesInFlight is " + std::to_string(info.framesInFlight) +
                       ": must be in 1.." + std::to_string(kMaxFramesInFlight));
    return core::checkWorldFrame(info.world, "ContextCreateInfo.world");
}

}  // namespace

void Context::Impl::warn(const std::string& message) const {
    if (info.messageCallback)
        info.messageCallback(MessageSeverity::Warning, message.c_str(), info.messageUserData);
}

std::vector<std::string> Context::Impl::adjustedInputs(const FrameInfo& resolved) const {
    std::vector<std::string> lines;
    for (const auto& effect : effects)
        if (effect->active(resolved)) effect->adjusted(resolved, lines);
    return lines;
}

TimingsOrigin Context::Impl::timingsOrigin() const {
    const VkPhysicalDeviceProperties& p = gpu.properties;
    return {POSTFX_VERSION, p.vendorID, p.deviceID, p.driverVersion};
}

std::string Context::Impl::otherOrigin(const TimingsOrigin& origin) const {
    const TimingsOrigin here = timingsOrigin();
    auto version = [](uint32_t v) {
        return std::to_string(v >> 22u) + "." + std::to_string((v >> 12u) & 0x3ffu) + "." +
               std::to_string(v & 0xfffu);
    };
    if (origin.postfxVersion != here.postfxVersion)
        return "postfx " + version(origin.postfxVersion) + " (this is " + version(here.postfxVersion) + ")";
    auto differs = [](uint32_t given, uint32_t actual) { return given != 0 && given != actual; };
    if (differs(origin.vendorId, here.vendorId) || differs(origin.deviceId, here.deviceId))
        return "another device (vendor " + std::to_string(origin.vendorId) + ", device " +
               std::to_string(origin.deviceId) + ")";
    if (differs(origin.driverVersion, here.driverVersion))
        return "another driver version (" + std::to_string(origin.driverVersion) + ", this is " +
               std::to_string(here.driverVersion) + ")";
    return {};
}

int Context::Impl::effectIndex(std::string_view name) const {
    for (size_t i = 0; i < effects.size(); ++i)
        if (name == effects[i]->name()) return int(i);
    return -1;
}

void Context::Impl::addEffect(std::unique_ptr<core::Effect> effect) {
    effects.push_back(std::move(effect));
    std::vector<const char*> names;
    std::vector<uint32_t> presets, fallback;
    for (const auto& e : effects) {
        names.push_back(e->name());
        presets.push_back(e->presetCount());
        fallback.push_back(e->fallbackPreset());
    }
    graph.setEffectNames(std::move(names));
    autoQuality.setEffects(std::move(presets), std::move(fallback), info.framesInFlight);
}

Status Context::create(const ContextCreateInfo& info, std::unique_ptr<Context>& out) {
    out.reset();
    if (Status s = validateCreateInfo(info); !s) return s;

    auto impl = std::make_unique<Impl>();
    impl->info = info;
    impl->world = core::WorldTransform(info.world);
    core::Gpu& gpu = impl->gpu;
    if (Status s = gpu.init(info); !s) return s;

    // postfx creates images as large as maxExtent (an effect's reduced-resolution targets, the copy).
    const uint32_t maxDimension = gpu.properties.limits.maxImageDimension2D;
    if (info.maxExtent.width > maxDimension || info.maxExtent.height > maxDimension)
        return core::invalid("ContextCreateInfo.maxExtent " + core::extentText(info.maxExtent) +
                             " exceeds the device's maxImageDimension2D " + std::to_string(maxDimension));

    uint32_t familyCount = 0;
    gpu.fn.vkGetPhysicalDeviceQueueFamilyProperties(info.physicalDevice, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    gpu.fn.vkGetPhysicalDeviceQueueFamilyProperties(info.physicalDevice, &familyCount, families.data());
    if (info.queueFamilyIndex >= familyCount)
        return core::invalid("ContextCreateInfo.queueFamilyIndex " + std::to_string(info.queueFamilyIndex) +
                             " is out of range (the device has " + std::to_string(familyCount) +
                             " families)");
    const VkQueueFamilyProperties& family = families[info.queueFamilyIndex];
    if (!(family.queueFlags & VK_QUEUE_COMPUTE_BIT))
        return core::invalid("ContextCreateInfo.queueFamilyIndex " + std::to_string(info.queueFamilyIndex) +
                             " does not support compute");

    if (Status s =
            impl->timer.create(gpu, info.framesInFlight, info.gpuTimings ? family.timestampValidBits : 0);
        !s)
        return s;
    if (info.gpuTimings && family.timestampValidBits == 0)
        impl->warn("queue family " + std::to_string(info.queueFamilyIndex) +
                   " has no timestamps: no GPU timings");
    for (uint32_t i = 0; i < info.framesInFlight; ++i) {
        impl->arenas.push_back(std::make_unique<core::DescriptorArena>());
        if (Status s = impl->arenas.back()->create(gpu, kDescriptorSetsPerFrame); !s) return s;
    }
    if (Status s = impl->graph.create(gpu, info.framesInFlight, info.depth); !s) return s;
    for (std::unique_ptr<core::Effect>& effect : makeEffects(gpu))
        impl->addEffect(std::move(effect));
    out.reset(new Context(std::move(impl)));
    return Status::success();
}

Context::Context(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Context::~Context() = default;

const ContextCreateInfo& Context::createInfo() const {
    return impl_->info;
}

Status Context::Impl::prepareFrame(const FrameInfo& frame, core::AutoQuality& autoQuality,
                                   FrameInfo& resolved, core::WorldScratch& scratch, core::Frame& out,
                                   std::vector<AutoUse>* measuring) const {
    if (Status s = core::checkSharedInputs(frame, info); !s) return s;
    core::TargetStore targetStore = core::TargetStore::Blit;
    if (Status s = core::checkTargetFeatures(gpu, frame, targetStore); !s) return s;
    // Each active effect's preset replaces its knobs before its settings are checked; Auto picks the
    // preset (reading finished frames' timings, so before the timer starts this frame).
    resolved = frame;
    if (measuring) measuring->assign(effects.size(), AutoUse{});
    // With one budget for the frame, the effects on Auto are chosen together (core/budget.h).
    const bool budget = frame.budgetMs > 0.0f;
    std::vector<core::AutoQuality::JointRequest> joint;
    std::vector<size_t> jointEffects;
    std::vector<int> others;  // the active effects not on Auto: the rest of the budget's work
    // Every effect reads the host's depth: with two or more active, postfx.view_distance unprojects it
    // once for all of them (a preset never turns an effect on or off).
    size_t activeCount = 0;
    for (size_t e = 0; e < effects.size(); ++e) {
        const core::Effect& effect = *effects[e];
        if (!effect.active(frame)) continue;
        ++activeCount;
        const bool onAuto =
            effect.presetCount() > 0 && effect.quality(frame).kind == core::QualityRequest::Kind::Auto;
        if (!budget || !onAuto) others.push_back(int(e));
        if (effect.presetCount() == 0) continue;
        const core::QualityRequest q = effect.quality(frame);
        if (q.kind == core::QualityRequest::Kind::Custom) continue;
        uint32_t preset = q.preset;
        if (q.kind == core::QualityRequest::Kind::Auto) {
            const core::AutoQualityKey key{int(e), frame.color.extent.width, frame.color.extent.height,
                                           effect.autoFeatures(frame)};
            if (budget) {
                joint.push_back({key, effect.presetErrors()});
                jointEffects.push_back(e);
                continue;
            }
            if (Status s = autoQuality.select(key, q.budgetMs, timer, preset); !s)
                return {s.code, std::string(effect.name()) + " quality Auto: " + s.message};
            if (measuring) (*measuring)[e] = {key, preset};
        }
        effect.applyPreset(resolved, preset);
    }
    if (budget) {
        if (activeCount >= 2) others.push_back(-1);  // the context's own pass, postfx.view_distance
        std::vector<uint32_t> presets;
        if (Status s = autoQuality.selectJoint(joint, others, double(frame.budgetMs), timer, presets); !s)
            return {s.code, "FrameInfo.budgetMs: " + s.message};
        for (size_t r = 0; r < joint.size(); ++r) {
            const size_t e = jointEffects[r];
            if (measuring) (*measuring)[e] = {joint[r].key, presets[r]};
            effects[e]->applyPreset(resolved, presets[r]);
        }
    } else {
        autoQuality.clearJoint();
    }
    for (const auto& effect : effects)
        if (Status s = effect->validate(resolved); !s) return s;
    // Checked in the host's frame, so that messages name its values; from here on, postfx's own.
    if (!world.identity()) {
        core::sharedInputsToPostfx(world, resolved, scratch);
        for (const auto& effect : effects)
            effect->toPostfxFrame(world, resolved, scratch);
    }

    graph.begin(out, resolved);
    out.world = world;
    out.shareDepth = activeCount >= 2;
    core::declareTargetLoad(graph, out);
    for (size_t e = 0; e < effects.size(); ++e) {
        if (!effects[e]->active(resolved)) continue;
        core::FrameBuilder builder(graph, out, int(e));
        if (Status s = effects[e]->declare(builder); !s) return s;
    }
    core::declareTargetStore(graph, out, targetStore);
    core::declareLookupClear(graph, out);
    graph.compile(out);
    // Before anything of the frame is created: its images and buffers within the budget.
    return core::checkMemoryBudget(out, info.framesInFlight, info.memoryBudgetBytes);
}

Status Context::plan(const FrameInfo& frame, FramePlan& out) const {
    out = {};
    const Impl& impl = *impl_;
    // Auto is planned as the preset record() would use now: a copy of its state selects (nothing is
    // collected or measured).
    core::AutoQuality autoQuality = impl.autoQuality;
    FrameInfo resolved;
    core::Frame declared;
    if (Status s = impl.prepareFrame(frame, autoQuality, resolved, impl.planScratch, declared, nullptr); !s)
        return s;
    impl.graph.plan(declared, out);
    out.adjusted = impl.adjustedInputs(resolved);
    return Status::success();
}

Status Context::record(const FrameInfo& frame) {
    Impl& impl = *impl_;
    if (!frame.commandBuffer) return core::invalid("FrameInfo.commandBuffer is VK_NULL_HANDLE");
    std::vector<Impl::AutoUse> measuring;
    if (Status s = impl.prepareFrame(frame, impl.autoQuality, impl.resolved, impl.recordScratch, impl.frame,
                                     &measuring);
        !s)
        return s;
    for (const Impl::AutoUse& m : measuring)
        if (m.preset != ~0u && !impl.timer.enabled() && !impl.warnedAutoWithoutTimings) {
            impl.warnedAutoWithoutTimings = true;
            impl.warn(std::string(impl.effects[size_t(m.key.effect)]->name()) +
                      " quality Auto without GPU timings (gpuTimings off or unsupported): using its fallback "
                      "preset");
        }

    core::DescriptorArena& arena = impl.arena(frame.frameIndex);
    if (Status s = arena.beginFrame(); !s) return s;
    impl.retirement.collect(frame.frameIndex, impl.info.framesInFlight);
    if (Status s = impl.graph.record(impl.frame, frame.commandBuffer, frame.frameIndex, arena, impl.timer,
                                     impl.retirement);
        !s)
        return s;
    for (const Impl::AutoUse& m : measuring)
        if (m.preset != ~0u) impl.autoQuality.recorded(frame.frameIndex, m.key, m.preset);
    impl.autoQuality.frameRecorded(frame.frameIndex);
    impl.lookupRecorded = impl.resolved.volumetricsLookup.enabled;
    impl.lookupFrame = frame.frameIndex;
    for (const auto& effect : impl.effects)
        effect->recorded(impl.resolved, effect->active(impl.resolved));
    // Each adjusted input said once, in the first frame that has it (not again while it stays).
    std::vector<std::string> adjusted = impl.adjustedInputs(impl.resolved);
    for (const std::string& line : adjusted)
        if (std::find(impl.adjusted.begin(), impl.adjusted.end(), line) == impl.adjusted.end())
            impl.warn(line);
    impl.adjusted = std::move(adjusted);
    return Status::success();
}

Status Context::budgetChoice(BudgetChoice& out) const {
    out = {};
    core::AutoQuality::JointChoice c;
    if (Status s = impl_->autoQuality.jointChoice(c); !s) return s;
    out.budgetMs = float(c.budgetMs);
    out.otherMs = float(c.otherMs);
    out.chosenMs = float(c.chosenMs);
    out.error = c.error;
    out.fits = c.fits && c.otherMs + c.chosenMs <= c.budgetMs;
    for (size_t i = 0; i < c.effects.size(); ++i)
        out.effects.push_back(
            {impl_->effects[size_t(c.effects[i])]->name(), c.presets[i], float(c.ms[i]), c.errors[i]});
    return Status::success();
}

Status Context::autoQuality(std::string_view effect, uint32_t& preset) const {
    const int e = impl_->effectIndex(effect);
    if (e < 0 || impl_->effects[size_t(e)]->presetCount() == 0)
        return core::invalid("autoQuality: '" + std::string(effect) + "' is not an effect with presets");
    return impl_->autoQuality.chosen(e, preset);
}

std::vector<AutoQualityTimings> Context::autoQualityTimings() const {
    std::vector<AutoQualityTimings> out;
    for (const auto& [key, ms] : impl_->autoQuality.timings())
        out.push_back({impl_->effects[size_t(key.effect)]->name(), key.width, key.height, key.features, ms,
                       impl_->timingsOrigin()});
    return out;
}

Status Context::setAutoQualityTimings(const std::vector<AutoQualityTimings>& timings) {
    std::vector<std::pair<core::AutoQualityKey, std::vector<float>>> given;
    for (size_t k = 0; k < timings.size(); ++k) {
        const AutoQualityTimings& t = timings[k];
        const std::string name = "auto quality timings[" + std::to_string(k) + "]";
        const int e = impl_->effectIndex(t.effect);
        if (e < 0 || impl_->effects[size_t(e)]->presetCount() == 0)
            return core::invalid(name + ".effect: '" + t.effect + "' is not an effect with presets");
        const uint32_t presets = impl_->effects[size_t(e)]->presetCount();
        if (t.presetMs.size() != presets)
            return core::invalid(name + ".presetMs: " + std::to_string(t.presetMs.size()) + " times, " +
                                 t.effect + " has " + std::to_string(presets) + " presets");
        if (t.width == 0 || t.height == 0) return core::invalid(name + ": extent must be at least 1x1");
        for (size_t i = 0; i < t.presetMs.size(); ++i)
            if (!std::isfinite(t.presetMs[i]) || t.presetMs[i] < 0.0f)
                return core::invalid(name + ".presetMs[" + std::to_string(i) +
                                     "]: " + core::numberText(t.presetMs[i]) + " must be finite and >= 0");
        if (const std::string other = impl_->otherOrigin(t.origin); !other.empty()) {
            impl_->warn(name + ": measured with " + other + "; skipped, measured again");
            continue;
        }
        given.emplace_back(core::AutoQualityKey{e, t.width, t.height, t.features}, t.presetMs);
    }
    impl_->autoQuality.give(given);
    return Status::success();
}

VkImageView Context::imageView(ResourceName name, VkImageLayout* layout) const {
    const core::FrameGraph::HeldImage held = impl_->graph.heldImage(name.value);
    if (layout) *layout = held.image ? held.layout : VK_IMAGE_LAYOUT_UNDEFINED;
    return held.image ? held.image->view() : VK_NULL_HANDLE;
}

Status Context::recordImageReadback(ResourceName name, VkCommandBuffer commandBuffer, VkBuffer buffer,
                                    VkDeviceSize offset, VkExtent3D& extent, VkDeviceSize& bytes) const {
    if (!commandBuffer) return core::invalid("recordImageReadback: commandBuffer is VK_NULL_HANDLE");
    if (!buffer) return core::invalid("recordImageReadback: buffer is VK_NULL_HANDLE");
    return impl_->graph.recordReadback(name.value, commandBuffer, buffer, offset, extent, bytes);
}

Status Context::memoryUsage(MemoryUsage& out) const {
    out = {};
    out.owners.resize(1 + impl_->effects.size());
    out.owners[0].name = "postfx";
    for (size_t e = 0; e < impl_->effects.size(); ++e)
        out.owners[1 + e].name = impl_->effects[e]->name();
    impl_->graph.memoryUsage(out.owners);
    out.retiringBytes = impl_->retirement.pendingBytes();
    out.totalBytes = out.retiringBytes;
    for (const MemoryUsage::Owner& o : out.owners)
        out.totalBytes += o.bytes;
    return Status::success();
}

Status Context::readPassTimings(uint64_t frameIndex, std::vector<PassTiming>& out) const {
    Status s = impl_->timer.read(frameIndex, out);
    return s.code == Result::NotReady ? s : std::move(s);
}

}  // namespace postfx
