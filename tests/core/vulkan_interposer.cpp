#include "vulkan_interposer.h"

#include "core/device_functions.h"

#include <cstring>
#include <set>
#include <type_traits>

namespace test {
namespace {

// Every entry point postfx loads, by index.
enum class Fn : uint16_t {
#define POSTFX_ENUM(name) name,
    POSTFX_INSTANCE_FUNCTIONS(POSTFX_ENUM) POSTFX_DEVICE_FUNCTIONS(POSTFX_ENUM)
#undef POSTFX_ENUM
        Count
};
constexpr const char* kFnNames[] = {
#define POSTFX_NAME(name) #name,
    POSTFX_INSTANCE_FUNCTIONS(POSTFX_NAME) POSTFX_DEVICE_FUNCTIONS(POSTFX_NAME)
#undef POSTFX_NAME
};
constexpr size_t kFnCount = size_t(Fn::Count);

template <Fn F>
struct FnType;
#define POSTFX_TYPE(name)        \
    template <>                  \
    struct FnType<Fn::name> {    \
        using type = PFN_##name; \
    };
POSTFX_INSTANCE_FUNCTIONS(POSTFX_TYPE)
POSTFX_DEVICE_FUNCTIONS(POSTFX_TYPE)
#undef POSTFX_TYPE

// The error each fallible command fails with: one its specification lists (vk.xml's errorcodes);
// VK_SUCCESS: the command cannot fail (vkResetDescriptorPool) or returns nothing.
VkResult injectedError(Fn f) {
    switch (f) {
        case Fn::vkCreateBuffer:
        case Fn::vkCreateImage:
        case Fn::vkAllocateMemory:
        case Fn::vkBindBufferMemory:
        case Fn::vkBindImageMemory:
            return VK_ERROR_OUT_OF_DEVICE_MEMORY;
        case Fn::vkCreateImageView:
        case Fn::vkCreateSampler:
        case Fn::vkCreateShaderModule:
        case Fn::vkCreateDescriptorSetLayout:
        case Fn::vkCreatePipelineLayout:
        case Fn::vkCreateComputePipelines:
        case Fn::vkCreateDescriptorPool:
        case Fn::vkCreateQueryPool:
            return VK_ERROR_OUT_OF_HOST_MEMORY;
        case Fn::vkMapMemory:
            return VK_ERROR_MEMORY_MAP_FAILED;
        case Fn::vkAllocateDescriptorSets:
            return VK_ERROR_OUT_OF_POOL_MEMORY;
        case Fn::vkGetQueryPoolResults:
            return VK_ERROR_DEVICE_LOST;
        default:
            return VK_SUCCESS;
    }
}

struct State {
    PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;
    PFN_vkGetDeviceProcAddr getDeviceProcAddr = nullptr;
    PFN_vkVoidFunction real[kFnCount] = {};
    std::set<uint64_t> objects[size_t(VkObjectKind::Count)];
    uint64_t created[size_t(VkObjectKind::Count)] = {};
    uint64_t pipelinesWithCache = 0;  // created with a VkPipelineCache
    uint64_t peak = 0;
    uint64_t commands = 0;
    uint64_t calls = 0;       // fallible calls since arm()
    uint64_t failAt = ~0ull;  // index of the call to fail
    InjectedFault fault;
    std::vector<std::string> errors;

    // The error to return instead of calling the driver, or VK_SUCCESS.
    VkResult inject(Fn f) {
        const VkResult error = injectedError(f);
        if (error == VK_SUCCESS) return VK_SUCCESS;
        if (calls++ != failAt) return VK_SUCCESS;
        fault = {true, failAt, kFnNames[size_t(f)], error};
        return error;
    }
    uint64_t liveTotal() const {
        uint64_t n = 0;
        for (size_t k = 0; k < size_t(VkObjectKind::Count); ++k)
            if (VkObjectKind(k) != VkObjectKind::MemoryMapping) n += objects[k].size();
        return n;
    }
    void track(VkObjectKind kind, uint64_t handle, Fn f) {
        if (!objects[size_t(kind)].insert(handle).second)
            errors.push_back(std::string(kFnNames[size_t(f)]) + " returned a handle already live");
        ++created[size_t(kind)];
        peak = std::max(peak, liveTotal());
    }
    // False (and an error) when `handle` is not live: the caller must not pass it on.
    bool untrack(VkObjectKind kind, uint64_t handle, Fn f) {
        if (objects[size_t(kind)].erase(handle)) return true;
        errors.push_back(std::string(kFnNames[size_t(f)]) + " of a " + objectKindName(kind) +
                         " that is not live (never created, a failed call's output, or destroyed twice)");
        return false;
    }
};
State* g = nullptr;

template <class H>
uint64_t bits(H handle) {
    if constexpr (std::is_pointer_v<H>)
        return uint64_t(reinterpret_cast<uintptr_t>(handle));
    else
        return uint64_t(handle);
}
template <class H>
H poison() {
    if constexpr (std::is_pointer_v<H>)
        return reinterpret_cast<H>(uintptr_t{0xbad0bad0});
    else
        return H(0xbad0bad0);
}

template <Fn F>
typename FnType<F>::type real() {
    return reinterpret_cast<typename FnType<F>::type>(g->real[size_t(F)]);
}

bool isCommand(Fn f) {
    return std::strncmp(kFnNames[size_t(f)], "vkCmd", 5) == 0;
}

// Any entry point: injects its error, counts commands, forwards.
template <Fn F, class P = typename FnType<F>::type>
struct Generic;
template <Fn F, class R, class... A>
struct Generic<F, R(VKAPI_PTR*)(A...)> {
    static R VKAPI_CALL call(A... a) {
        if constexpr (std::is_same_v<R, VkResult>)
            if (const VkResult e = g->inject(F); e != VK_SUCCESS) return e;
        if (isCommand(F)) ++g->commands;
        return real<F>()(a...);
    }
};

// vkCreate* / vkAllocateMemory: one object, counted; a failure writes a poison handle.
template <Fn F, VkObjectKind K, class P = typename FnType<F>::type>
struct Create;
template <Fn F, VkObjectKind K, class Info, class H>
struct Create<F, K, VkResult(VKAPI_PTR*)(VkDevice, const Info*, const VkAllocationCallbacks*, H*)> {
    static VkResult VKAPI_CALL call(VkDevice device, const Info* info, const VkAllocationCallbacks* a,
                                    H* out) {
        if (const VkResult e = g->inject(F); e != VK_SUCCESS) {
            *out = poison<H>();
            return e;
        }
        const VkResult r = real<F>()(device, info, a, out);
        if (r == VK_SUCCESS) g->track(K, bits(*out), F);
        return r;
    }
};

// vkDestroy* / vkFreeMemory: only live objects are passed on (null is allowed by Vulkan and ignored).
template <Fn F, VkObjectKind K, class P = typename FnType<F>::type>
struct Destroy;
template <Fn F, VkObjectKind K, class H>
struct Destroy<F, K, void(VKAPI_PTR*)(VkDevice, H, const VkAllocationCallbacks*)> {
    static void VKAPI_CALL call(VkDevice device, H handle, const VkAllocationCallbacks* a) {
        if (bits(handle) == 0) return;
        if (!g->untrack(K, bits(handle), F)) return;
        if constexpr (F == Fn::vkFreeMemory)
            g->objects[size_t(VkObjectKind::MemoryMapping)].erase(bits(handle));
        real<F>()(device, handle, a);
    }
};

VkResult VKAPI_CALL createComputePipelines(VkDevice device, VkPipelineCache cache, uint32_t count,
                                           const VkComputePipelineCreateInfo* infos,
                                           const VkAllocationCallbacks* a, VkPipeline* out) {
    if (const VkResult e = g->inject(Fn::vkCreateComputePipelines); e != VK_SUCCESS) {
        for (uint32_t i = 0; i < count; ++i)
            out[i] = VK_NULL_HANDLE;  // the specification's rule for failed pipelines
        return e;
    }
    const VkResult r = real<Fn::vkCreateComputePipelines>()(device, cache, count, infos, a, out);
    for (uint32_t i = 0; i < count; ++i)
        if (out[i]) {
            g->track(VkObjectKind::Pipeline, bits(out[i]), Fn::vkCreateComputePipelines);
            if (cache) ++g->pipelinesWithCache;
        }
    return r;
}

VkResult VKAPI_CALL allocateDescriptorSets(VkDevice device, const VkDescriptorSetAllocateInfo* info,
                                           VkDescriptorSet* out) {
    if (const VkResult e = g->inject(Fn::vkAllocateDescriptorSets); e != VK_SUCCESS) {
        for (uint32_t i = 0; i < info->descriptorSetCount; ++i)
            out[i] = VK_NULL_HANDLE;  // the specification's rule
        return e;
    }
    return real<Fn::vkAllocateDescriptorSets>()(device, info, out);
}

VkResult VKAPI_CALL mapMemory(VkDevice device, VkDeviceMemory memory, VkDeviceSize offset, VkDeviceSize size,
                              VkMemoryMapFlags flags, void** data) {
    if (const VkResult e = g->inject(Fn::vkMapMemory); e != VK_SUCCESS) {
        *data = poison<void*>();
        return e;
    }
    if (!g->objects[size_t(VkObjectKind::DeviceMemory)].count(bits(memory)))
        g->errors.push_back("vkMapMemory of memory that is not live");
    const VkResult r = real<Fn::vkMapMemory>()(device, memory, offset, size, flags, data);
    if (r == VK_SUCCESS) g->track(VkObjectKind::MemoryMapping, bits(memory), Fn::vkMapMemory);
    return r;
}

void VKAPI_CALL unmapMemory(VkDevice device, VkDeviceMemory memory) {
    if (!g->untrack(VkObjectKind::MemoryMapping, bits(memory), Fn::vkUnmapMemory)) return;
    real<Fn::vkUnmapMemory>()(device, memory);
}

template <Fn F>
PFN_vkVoidFunction wrapper() {
    return reinterpret_cast<PFN_vkVoidFunction>(&Generic<F>::call);
}
#define POSTFX_TRACKED(X)                                                             \
    X(vkCreateBuffer, vkDestroyBuffer, Buffer)                                        \
    X(vkCreateImage, vkDestroyImage, Image)                                           \
    X(vkCreateImageView, vkDestroyImageView, ImageView)                               \
    X(vkCreateSampler, vkDestroySampler, Sampler)                                     \
    X(vkAllocateMemory, vkFreeMemory, DeviceMemory)                                   \
    X(vkCreateShaderModule, vkDestroyShaderModule, ShaderModule)                      \
    X(vkCreateDescriptorSetLayout, vkDestroyDescriptorSetLayout, DescriptorSetLayout) \
    X(vkCreatePipelineLayout, vkDestroyPipelineLayout, PipelineLayout)                \
    X(vkCreateDescriptorPool, vkDestroyDescriptorPool, DescriptorPool)                \
    X(vkCreateQueryPool, vkDestroyQueryPool, QueryPool)
#define POSTFX_WRAP_PAIR(create, destroy, kind)                                                       \
    template <>                                                                                       \
    PFN_vkVoidFunction wrapper<Fn::create>() {                                                        \
        return reinterpret_cast<PFN_vkVoidFunction>(&Create<Fn::create, VkObjectKind::kind>::call);   \
    }                                                                                                 \
    template <>                                                                                       \
    PFN_vkVoidFunction wrapper<Fn::destroy>() {                                                       \
        return reinterpret_cast<PFN_vkVoidFunction>(&Destroy<Fn::destroy, VkObjectKind::kind>::call); \
    }
POSTFX_TRACKED(POSTFX_WRAP_PAIR)
#undef POSTFX_WRAP_PAIR
template <>
PFN_vkVoidFunction wrapper<Fn::vkCreateComputePipelines>() {
    return reinterpret_cast<PFN_vkVoidFunction>(&createComputePipelines);
}
template <>
PFN_vkVoidFunction wrapper<Fn::vkDestroyPipeline>() {
    return reinterpret_cast<PFN_vkVoidFunction>(
        &Destroy<Fn::vkDestroyPipeline, VkObjectKind::Pipeline>::call);
}
template <>
PFN_vkVoidFunction wrapper<Fn::vkAllocateDescriptorSets>() {
    return reinterpret_cast<PFN_vkVoidFunction>(&allocateDescriptorSets);
}
template <>
PFN_vkVoidFunction wrapper<Fn::vkMapMemory>() {
    return reinterpret_cast<PFN_vkVoidFunction>(&mapMemory);
}
template <>
PFN_vkVoidFunction wrapper<Fn::vkUnmapMemory>() {
    return reinterpret_cast<PFN_vkVoidFunction>(&unmapMemory);
}

// Entry points whose wrapper is specialised above; any other that creates or destroys is an error.
bool specialised(Fn f) {
    switch (f) {
#define POSTFX_CASES(create, destroy, kind) \
    case Fn::create:                        \
    case Fn::destroy:
        POSTFX_TRACKED(POSTFX_CASES)
#undef POSTFX_CASES
        case Fn::vkCreateComputePipelines:
        case Fn::vkDestroyPipeline:
        case Fn::vkAllocateDescriptorSets:
        case Fn::vkMapMemory:
        case Fn::vkUnmapMemory:
            return true;
        default:
            return false;
    }
}

constexpr size_t kInstanceCount = 0
#define POSTFX_ONE(name) +1
    POSTFX_INSTANCE_FUNCTIONS(POSTFX_ONE)
#undef POSTFX_ONE
    ;

PFN_vkVoidFunction lookup(const char* name, size_t first, size_t last, size_t& index) {
    static const PFN_vkVoidFunction wrappers[] = {
#define POSTFX_WRAPPER(name) wrapper<Fn::name>(),
        POSTFX_INSTANCE_FUNCTIONS(POSTFX_WRAPPER) POSTFX_DEVICE_FUNCTIONS(POSTFX_WRAPPER)
#undef POSTFX_WRAPPER
    };
    for (size_t i = first; i < last; ++i)
        if (std::strcmp(kFnNames[i], name) == 0) {
            index = i;
            return wrappers[i];
        }
    return nullptr;
}

PFN_vkVoidFunction VKAPI_CALL getInstanceProcAddr(VkInstance instance, const char* name) {
    size_t i = 0;
    PFN_vkVoidFunction w = lookup(name, 0, kInstanceCount, i);
    if (!w) return g->getInstanceProcAddr(instance, name);
    g->real[i] = g->getInstanceProcAddr(instance, name);
    return g->real[i] ? w : nullptr;
}

PFN_vkVoidFunction VKAPI_CALL getDeviceProcAddr(VkDevice device, const char* name) {
    size_t i = 0;
    PFN_vkVoidFunction w = lookup(name, kInstanceCount, kFnCount, i);
    if (!w) return g->getDeviceProcAddr(device, name);
    g->real[i] = g->getDeviceProcAddr(device, name);
    return g->real[i] ? w : nullptr;
}

}  // namespace

const char* objectKindName(VkObjectKind kind) {
    static constexpr const char* names[] = {
        "Buffer",         "Image",         "ImageView",      "Sampler",
        "DeviceMemory",   "MemoryMapping", "ShaderModule",   "DescriptorSetLayout",
        "PipelineLayout", "Pipeline",      "DescriptorPool", "QueryPool"};
    return names[size_t(kind)];
}

VulkanInterposer::VulkanInterposer(PFN_vkGetInstanceProcAddr gipa, PFN_vkGetDeviceProcAddr gdpa) {
    g = new State;
    g->getInstanceProcAddr = gipa;
    g->getDeviceProcAddr = gdpa;
    for (size_t i = 0; i < kFnCount; ++i) {
        const std::string name = kFnNames[i];
        const bool makesOrFrees = name.starts_with("vkCreate") || name.starts_with("vkDestroy") ||
                                  name.starts_with("vkAllocate") || name.starts_with("vkFree");
        if (makesOrFrees && !specialised(Fn(i)))
            g->errors.push_back(name + " creates or destroys objects the interposer does not count: add it");
    }
}

VulkanInterposer::~VulkanInterposer() {
    delete g;
    g = nullptr;
}

postfx::ContextCreateInfo VulkanInterposer::wrap(postfx::ContextCreateInfo info) const {
    info.getInstanceProcAddr = &getInstanceProcAddr;
    info.getDeviceProcAddr = &getDeviceProcAddr;
    return info;
}

void VulkanInterposer::arm(uint64_t n) {
    g->calls = 0;
    g->failAt = n;
    g->fault = {};
}

void VulkanInterposer::disarm() {
    g->failAt = ~0ull;
}

const InjectedFault& VulkanInterposer::fault() const {
    return g->fault;
}

uint64_t VulkanInterposer::fallibleCalls() const {
    return g->calls;
}

uint64_t VulkanInterposer::live(VkObjectKind kind) const {
    return g->objects[size_t(kind)].size();
}

uint64_t VulkanInterposer::created(VkObjectKind kind) const {
    return g->created[size_t(kind)];
}

uint64_t VulkanInterposer::pipelinesWithCache() const {
    return g->pipelinesWithCache;
}

uint64_t VulkanInterposer::liveTotal() const {
    return g->liveTotal();
}

uint64_t VulkanInterposer::peakLiveTotal() const {
    return g->peak;
}

void VulkanInterposer::resetPeak() {
    g->peak = g->liveTotal();
}

std::string VulkanInterposer::liveSummary() const {
    std::string s;
    for (size_t k = 0; k < size_t(VkObjectKind::Count); ++k)
        if (!g->objects[k].empty())
            s += (s.empty() ? "" : ", ") + std::string(objectKindName(VkObjectKind(k))) + " " +
                 std::to_string(g->objects[k].size());
    return s.empty() ? "none" : s;
}

uint64_t VulkanInterposer::commands() const {
    return g->commands;
}

const std::vector<std::string>& VulkanInterposer::errors() const {
    return g->errors;
}

}  // namespace test
