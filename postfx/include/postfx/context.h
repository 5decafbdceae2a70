// The postfx context: one per VkDevice, created from handles the host lends.
//
// Lifecycle (as AMD FidelityFX): Context::create once, Context::record once per frame into the host's
// command buffer, destroy (the unique_ptr) after the host has waited for the device to go idle.
// postfx loads every device-level function through the host's vkGetDeviceProcAddr and every
// instance-level function through the host's vkGetInstanceProcAddr; it links no Vulkan loader.
#pragma once

#include <postfx/atmosphere.h>
#include <postfx/clouds.h>
#include <postfx/export.h>
#include <postfx/fog.h>
#include <postfx/frame_plan.h>
#include <postfx/froxel_fog.h>
#include <postfx/inputs.h>
#include <postfx/result.h>
#include <postfx/types.h>
#include <postfx/volumetrics_lookup.h>
#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace postfx {

// A block of device memory the host hands postfx (DeviceMemoryCallbacks::allocate).
struct DeviceAllocation {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;  // where postfx binds its image or buffer; a multiple of the alignment asked
    // For a request with VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT: memory's bytes at `offset`, mapped by the
    // host and mapped while postfx holds the allocation (postfx never maps memory the host gave it).
    void* mapped = nullptr;
    void* handle = nullptr;  // the host's own (its allocator's allocation), handed back to free
};

// The host's device-memory allocator (ContextCreateInfo::deviceMemory; docs/integration.md, "Memory").
// Called on the thread of the postfx call that creates or frees a resource (create, record, prewarm,
// destroy).
struct DeviceMemoryCallbacks {
    // At least requirements.size bytes at an offset aligned to requirements.alignment, of a memory type
    // among requirements.memoryTypeBits with every `required` flag (DEVICE_LOCAL for images and storage;
    // HOST_VISIBLE | HOST_COHERENT, and DEVICE_LOCAL when the device has such a type, for the uniform
    // rings). VK_SUCCESS, or an error (VK_ERROR_OUT_OF_DEVICE_MEMORY): postfx then returns OutOfMemory
    // naming the resource, and calls nothing else for it.
    VkResult (*allocate)(void* userData, const VkMemoryRequirements& requirements,
                         VkMemoryPropertyFlags required, DeviceAllocation& out) = nullptr;
    // Gives back an allocation `allocate` returned, once postfx has destroyed what was bound to it.
    void (*free)(void* userData, const DeviceAllocation& allocation) = nullptr;
    void* userData = nullptr;
};

struct ContextCreateInfo {
    // Leave as is: the size of the struct as the host's compiler laid it out, which create() compares with
    // the library's (a host built with other packing or another postfx header gets an error, not garbage).
    uint32_t structSize = sizeof(ContextCreateInfo);

    // Borrowed handles; the host keeps ownership and must outlive the context.
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;  // for physical-device queries
    PFN_vkGetDeviceProcAddr getDeviceProcAddr = nullptr;      // every device call goes through this
    uint32_t queueFamilyIndex = 0;  // family of the queue that will execute recorded command buffers;
                                    // must support compute
    // Optional, used for every Vulkan object; when given, pfnAllocation, pfnReallocation and pfnFree are set
    // and pfnInternalAllocation / pfnInternalFree both or neither (as Vulkan requires).
    const VkAllocationCallbacks* allocator = nullptr;

    // Pipelines and device memory from the host (both optional; docs/integration.md, "Pipelines" and
    // "Memory").
    // Borrowed; when given, every pipeline postfx creates goes through it (a host that saves its data
    // between runs compiles nothing postfx needs twice). The host keeps it alive while the context lives
    // and synchronizes it as Vulkan requires (postfx creates pipelines in create(), record() and prewarm()).
    VkPipelineCache pipelineCache = VK_NULL_HANDLE;
    // The device memory of every image and buffer postfx creates: default (both null) its own
    // vkAllocateMemory per resource; given, the host's allocate and free, both or neither.
    DeviceMemoryCallbacks deviceMemory;

    // Largest color/depth extent that record() accepts [pixels]; each side in [1, the device's
    // maxImageDimension2D] (postfx creates images up to this size).
    VkExtent2D maxExtent = {3840, 2160};
    DepthConvention depth;
    uint32_t framesInFlight = 2;  // frames the host may record before waiting on the oldest, 1..8
    bool gpuTimings = true;       // write timestamp queries around each pass (see readPassTimings)
    // The host enabled VK_EXT_debug_utils on `instance`: postfx then wraps its work in each record() in a
    // "postfx" label and each pass in a label named after it ("fog.raymarch"), which RenderDoc, Nsight and
    // the validation layer show. Off: no label call is made (calling them without the extension is invalid).
    bool debugLabels = false;

    MessageCallback messageCallback = nullptr;  // optional
    void* messageUserData = nullptr;

    // The host's world frame: up axis, handedness and units (types.h, WorldFrame; docs/integration.md,
    // "World frame and units"). The default is postfx's own: y up, right-handed, metres. Every world-space
    // input of FrameInfo is in this frame (positions and sizes of what the host places in its world in its
    // units); media properties stay in metres. Checked by create(): up Y or Z, handedness Right or Left,
    // unitsPerMetre in [1e-3, 1e3].
    WorldFrame world;

    // The most device memory one frame's images and buffers may take [bytes] (the frame plan's
    // totalBytes, checked by record(), plan() and prewarm() before anything is created); default 2 GiB,
    // 0: no budget. A frame over it is refused with InvalidArgument naming the settings that size its
    // largest images ("froxel_fog.grid: 256x256x128 needs 320 MiB of images; ..."; docs/reliability.md,
    // "Memory and cost budget").
    uint64_t memoryBudgetBytes = uint64_t(2) << 30;
};

// Everything postfx needs for one frame.
struct FrameInfo {
    uint32_t structSize = sizeof(FrameInfo);  // leave as is (see ContextCreateInfo::structSize)

    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;  // recording, outside a render pass
    uint64_t frameIndex = 0;  // increases by one per frame; selects per-frame resources and noise seeds
    // The view does not continue the previous frame's (a cut, a teleport, a new level): every effect's
    // temporal history is dropped and this frame starts it anew (docs/temporal.md).
    bool cameraCut = false;

    // HDR scene color, linear radiance [W/(sr·m²) or cd/m², the host's choice, used consistently] times
    // preExposure. Formats: R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT, usage STORAGE. Effects composite
    // into it. Its alpha is carried through unchanged.
    ImageInput color;
    // The factor the host stores its color with (pre-exposure, as Unreal's: typically its camera exposure,
    // so that a 100,000 lux sun's radiance fits RGBA16F) [1]; default 1: physical units. postfx reads color
    // as radiance × preExposure and writes every radiance it adds the same way (the light it is given,
    // below, stays in physical units; docs/integration.md, "Pre-exposure"). In [1e-10, 1e10], and the
    // pre-exposed light within the ranges below (sun.illuminance and ambient × preExposure ≤ 1e7, each
    // light's intensity × preExposure ≤ 1e9). May change every frame: histories are rescaled, except
    // texels that clipped before a drop or underflowed before a rise, which are rejected
    // (docs/temporal.md). Choose it from what the camera sees, so that the visible radiance fits RGBA16F.
    float preExposure = 1.0f;
    // Scene depth, D32_SFLOAT / D16_UNORM / D24_UNORM_S8_UINT / X8_D24_UNORM_PACK32 / D32_SFLOAT_S8_UINT
    // (its view must select the depth aspect only), usage SAMPLED,
    // same extent as color, in the context's DepthConvention.
    ImageInput depth;
    // Optional: when present, the result goes here (not the color image; same extent and format, usage
    // STORAGE) and `color` is only read. When absent, effects composite into `color` in place.
    ImageInput output;
    // Every image: view not VK_NULL_HANDLE, extent >= 1x1, usage with the bit above, layout a VkImageLayout
    // of postfx's Vulkan headers other than UNDEFINED and PREINITIALIZED (docs/integration.md, "Images").

    double timeSeconds = 0.0;  // host time [s], moves the noise with the wind; in [-1e12, 1e12]

    // Inputs every effect shares (postfx/inputs.h), checked whichever effects run.
    CameraInput camera;
    SunInput sun;
    Vec3 ambient{0.0f};  // uniform incident radiance for ambient in-scattering; each in [0, 1e7]
    ShadowMapInput shadowMap;
    const LocalLight* lights = nullptr;  // lightCount local lights (may be null when 0); read during record()
    uint32_t lightCount = 0;             // [0, kMaxLocalLights]
    LocalShadowAtlasInput localShadows;  // the lights' shadow maps (LocalLight::shadow indexes them)

    // One GPU time budget for all of postfx's work in this frame [ms]; in [0, 1000], 0: off (each effect
    // whose quality is Auto keeps its own autoBudgetMs). When > 0, the effects whose quality is Auto share
    // it: from the budget less the measured time of the rest of postfx's work (the other effects, its own
    // passes; the last finished frame's), the context picks one preset per such effect, the combination
    // with the lowest summed error on the effects' committed accuracy–cost fronts, re-chosen every frame
    // from the measured times (docs/architecture.md, "One budget for the frame"; Context::budgetChoice).
    float budgetMs = 0.0f;

    // Effect settings. Each effect is off by default; the order they composite in is fixed
    // (docs/architecture.md, "Composite order").
    // Sky and atmosphere (docs/effects/atmosphere.md): with it on, sun.illuminance is the illuminance
    // outside the atmosphere, and every effect attenuates it by the atmosphere's transmittance.
    AtmosphereSettings atmosphere;
    // Volumetric clouds (docs/effects/clouds.md): in front of the sky, behind nearer geometry.
    CloudSettings clouds;
    FogSettings fog;              // ray-marched fog (docs/effects/fog.md)
    FroxelFogSettings froxelFog;  // froxel fog (docs/effects/froxel-fog.md); not together with `fog`

    // The volumetrics lookup for the host's transparent surfaces (postfx/volumetrics_lookup.h): off, nothing
    // is built; on, record() builds it and Context::volumetricsLookup / writeVolumetricsLookup hand it over.
    VolumetricsLookupSettings volumetricsLookup;
};

// GPU time of one postfx pass in one frame.
struct PassTiming {
    std::string name;  // "fog.raymarch" (effect.pass)
    double milliseconds = 0.0;
};

// Quality Auto's measurements of one effect for one key (color extent and the effect's cost-relevant
// features): the median GPU time of each of its presets' passes, work on slow inputs excluded.
struct AutoQualityTimings {
    std::string effect;              // "fog"
    uint32_t width = 0, height = 0;  // color image extent [px]; each >= 1
    uint32_t features = 0;           // bits the effect defines (fog: kFogAutoFeature*)
    std::vector<float> presetMs;     // one per preset, lowest preset first [ms]; each finite, >= 0
    TimingsOrigin origin;            // postfx version, device and driver they were measured with
};

// What one budget for the frame (FrameInfo::budgetMs) chose for the last recorded frame
// (Context::budgetChoice; docs/architecture.md, "One budget for the frame").
struct BudgetChoice {
    struct EffectChoice {
        std::string effect;   // "fog", "clouds": an active effect whose quality is Auto
        uint32_t preset = 0;  // 0 = the lowest (Low)
        float ms = 0.0f;      // the preset's measured GPU time on this device (median) [ms]
        double error = 0.0;   // its error on the effect's committed accuracy–cost front (relative RMSE)
    };
    float budgetMs = 0.0f;  // FrameInfo::budgetMs [ms]
    // The rest of postfx's work (effects not on Auto, the context's own passes), measured in the newest
    // finished frame before it [ms].
    float otherMs = 0.0f;
    float chosenMs = 0.0f;  // Σ effects[i].ms [ms]
    double error = 0.0;     // Σ effects[i].error
    // otherMs + chosenMs <= budgetMs. False: not even the lowest presets fit, and each effect runs its
    // fastest.
    bool fits = false;
    std::vector<EffectChoice> effects;  // in composite order
};

// Device memory postfx holds (Context::memoryUsage): what its images and buffers were bound to.
struct MemoryUsage {
    struct Owner {
        std::string name;      // "postfx" (the context's own), then each effect ("fog") in composite order
        uint64_t bytes = 0;    // Σ VkMemoryRequirements::size of its images and buffers [bytes]
        uint32_t images = 0;   // images held
        uint32_t buffers = 0;  // buffers held (uniform rings)
    };
    // Σ owners[i].bytes + retiringBytes: what postfx's own vkAllocateMemory calls (or the host's
    // DeviceMemoryCallbacks::allocate) were asked for and not yet freed [bytes].
    uint64_t totalBytes = 0;
    // Released images and buffers that frames in flight may still read, freed by a later record() [bytes].
    uint64_t retiringBytes = 0;
    // The context's own first ("postfx": the shared depth, the volumetrics lookup, postfx.copy's), then
    // every registered effect, in composite order, 0 for one that is off. An image two effects share (a
    // noise texture of one size and seed) counts once, for the effect that declared it first.
    std::vector<Owner> owners;
};

class POSTFX_API Context {
public:
    // Creates a context; on failure `out` stays empty and the status names the problem.
    static Status create(const ContextCreateInfo& info, std::unique_ptr<Context>& out);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    // Records this frame's passes into frame.commandBuffer. The host must have waited until the
    // frame recorded framesInFlight frames ago has completed on the GPU. Once per frameIndex, which only
    // grows (a resize does not reset it); every command buffer record() wrote into must be submitted
    // (postfx tracks its own images' layouts from what it recorded). record() binds its own compute
    // pipelines, descriptor sets and push constants and leaves them bound: the host rebinds its compute
    // state after it. docs/integration.md has the whole contract (layouts, synchronization, threads).
    Status record(const FrameInfo& frame);

    // What record(frame) would record now (docs/frame-plan.md): its passes in order, with what each reads
    // and writes, and every resource postfx would hold afterwards with its size. Checks `frame` like
    // record() (its command buffer may be null); records nothing, creates nothing. An effect that is off,
    // or whose medium is empty, has no pass and no resource; a separate output image that no effect
    // writes gets postfx.copy. Work on slow inputs (fog.noise) is listed only in the frame that redoes it.
    // With fog quality Auto: the preset record() would use now (still measuring: the one whose turn it is).
    Status plan(const FrameInfo& frame, FramePlan& out) const;

    // Timings of the passes recorded for `frameIndex`. Returns NotReady while the GPU has not finished
    // that frame, InvalidArgument if that frame's queries were overwritten by a newer frame (more than
    // framesInFlight ago) or were never written. Does not wait. Read a frame the host has waited for (its
    // fence): a frame recorded and submitted but not yet started on the GPU still holds the timings of the
    // frame that used its query slot framesInFlight frames before (the slot is reset by the frame's own
    // commands). Quality Auto reads only frames recorded framesInFlight frames ago or earlier.
    Status readPassTimings(uint64_t frameIndex, std::vector<PassTiming>& out) const;

    // Quality Auto (every effect with presets; the fog's typed view: fogAutoQuality in fog.h). The
    // context measures the effect's presets on the running device from real frames (the first frames of
    // every new key: the presets in turn, three frames each, median) and then uses the highest preset
    // whose passes take at most the effect's budget, or the lowest if none fits.
    //
    // The preset index (0 = lowest) Auto chose for `effect`'s last recorded frame: NotReady while that
    // key's presets are being measured or no Auto frame was recorded; InvalidArgument for an unknown
    // effect or one without presets.
    Status autoQuality(std::string_view effect, uint32_t& preset) const;
    // What FrameInfo::budgetMs chose for the last recorded frame. NotReady when that frame had no budget
    // or its effects' presets are still being measured (the first frames of a new color extent or
    // feature set; then the measured effects run their fallback preset, Medium).
    Status budgetChoice(BudgetChoice& out) const;
    // Every key measured so far (all presets) or given, for a host that keeps them between runs; each
    // carries its origin (postfx version, device, driver), since the presets' cost depends on all three.
    std::vector<AutoQualityTimings> autoQualityTimings() const;
    // Adds `timings` to Auto's cache (replacing keys it has), so frames with those keys choose from the
    // first frame. InvalidArgument naming the entry for an unknown effect, a preset count that is not
    // the effect's, a zero extent or a time that is negative or not finite; then nothing is added. An
    // entry of another origin (TimingsOrigin: postfx version, device or driver) is skipped with a warning:
    // those keys are measured again.
    Status setAutoQualityTimings(const std::vector<AutoQualityTimings>& timings);

    // An image postfx holds between frames (an effect's noise texture or LUT, named in its header, e.g.
    // kFogNoiseTexture), for hosts that sample it too: its view, and the layout it is in once the frames
    // recorded so far have executed. VK_NULL_HANDLE when it is not held or not built yet.
    VkImageView imageView(ResourceName name, VkImageLayout* layout = nullptr) const;
    // Records a copy of such an image into `buffer` at `offset` (usage TRANSFER_DST), texels tightly
    // packed (x fastest, then y, then z, then an array image's layers) with the barriers around it; the
    // copied bytes are visible to the host once the submission has completed. `extent` receives its size,
    // `bytes` the bytes copied. InvalidArgument when it is not held or not built yet.
    Status recordImageReadback(ResourceName name, VkCommandBuffer commandBuffer, VkBuffer buffer,
                               VkDeviceSize offset, VkExtent3D& extent, VkDeviceSize& bytes) const;

    // The volumetrics lookup the last record() built (FrameInfo::volumetricsLookup; docs/integration.md,
    // "Transparent surfaces"). InvalidArgument when that record() did not ask for it, or none was recorded.
    Status volumetricsLookup(VolumetricsLookup& out) const;
    // Writes it into the host's `set` (allocated from a layout with volumetricsLookupLayout's bindings) at
    // `bindings`. Call after each record() that asked for it, before the host's commands that read it.
    Status writeVolumetricsLookup(VkDescriptorSet set, const VolumetricsLookupBindings& bindings) const;

    // Pipelines and memory (docs/integration.md, "Pipelines" and "Memory").
    //
    // Creates every compute pipeline (every specialization) that frames with `frame`'s settings may
    // record, so that none of them compiles in record(): the builds of persistent images (noise, LUTs),
    // the first frame's and a camera cut's as well as the temporal frames', each preset of an effect on
    // quality Auto (and every combination under FrameInfo::budgetMs), the sun lit and dark, the froxel
    // fog's light variants (none, a loop over the lights, light lists, local shadows when an atlas is
    // given). Checks `frame` like plan() (its command buffer may be null); records nothing and creates no
    // image. The pipelines stay until the context is destroyed, whether or not frames use them (an effect
    // turned off and on again compiles nothing); calls add up, so a host prewarms each combination of
    // effects and settings it will switch to. On error the pipelines created before it stay.
    Status prewarm(const FrameInfo& frame);
    // The device memory postfx holds now, in total and per owner (the context, each effect). Does not fail.
    Status memoryUsage(MemoryUsage& out) const;

    const ContextCreateInfo& createInfo() const;

    struct POSTFX_INTERNAL Impl;  // internal; defined in postfx/src/core

private:
    friend struct ContextAccess;  // postfx's internals (tests add test-only effects through it)
    explicit Context(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace postfx
