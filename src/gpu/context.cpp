#include "gpu/context.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include "errors.h"
#include "gpu/vk_check.h"

namespace wf {
namespace {

const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool envFlag(const char* name) {
    const char* value = std::getenv(name);
    return value && *value && std::strcmp(value, "0") != 0;
}

bool hasLayer(const char* name) {
    uint32_t count = 0;
    VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
    std::vector<VkLayerProperties> layers(count);
    VK_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
    for (const auto& layer : layers)
        if (std::strcmp(layer.layerName, name) == 0)
            return true;
    return false;
}

int deviceTypeRank(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
    default: return 0;
    }
}

} // namespace

Context::Context(const ContextOptions& options) {
    std::optional<int> index = options.deviceIndex;
    if (!index) {
        if (const char* env = std::getenv("WAVEFRONT_DEVICE"); env && *env) {
            char* end = nullptr;
            long value = std::strtol(env, &end, 10);
            if (*end != '\0' || value < 0)
                throw UsageError("WAVEFRONT_DEVICE must be a device index (0, 1, ...), got '" +
                                 std::string(env) + "'");
            index = static_cast<int>(value);
        }
    }
    createInstance(options.validation || envFlag("WAVEFRONT_VALIDATION"),
                   options.instanceExtensions);
    if (options.createSurface)
        surface_ = options.createSurface(instance_);
    pickPhysicalDevice(index, options.quiet);
    queryRayTracing();
    if (options.rayTracing == RayTracingRequest::Required && !rayTracingSupported_)
        throw UsageError("--traversal rt: device '" + deviceName_ + "' (" + driverInfo_ +
                         ") has no ray-tracing pipelines (VK_KHR_ray_tracing_pipeline, "
                         "VK_KHR_acceleration_structure); use --traversal bvh or auto");
    createDevice(options.rayTracing);
}

Context::~Context() {
    if (device_) {
        vkDeviceWaitIdle(device_);
        vkDestroyCommandPool(device_, commandPool_, nullptr);
        vkDestroyDevice(device_, nullptr);
    }
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance_, messenger_, nullptr);
    }
    if (surface_)
        vkDestroySurfaceKHR(instance_, surface_, nullptr);
    if (instance_)
        vkDestroyInstance(instance_, nullptr);
}

namespace {

// lavapipe splits every dispatch into one contiguous share of workgroups per thread and waits
// for the slowest; on a shared machine a core that stalls holds up the whole pass. With twice
// as many threads as cores the kernel can move a stalled share's thread to the other core:
// +7-12% paths/s on the Cornell box while the 2-core CI machine was busy, no change while it
// was quiet. Only llvmpipe reads LP_NUM_THREADS; a value the user set is kept.
void defaultLavapipeThreads() {
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    setenv("LP_NUM_THREADS", std::to_string(2 * cores).c_str(), /*overwrite=*/0);
}

// Mesa 25's llvmpipe compiles the image loads of lavapipe's shaders as functions of their
// own (one per format, shared by all shaders) and keeps them in its on-disk shader cache under
// a key without the vector width, in a cache named without LP_NATIVE_VECTOR_WIDTH too. A run at
// LP_NATIVE_VECTOR_WIDTH=512 (16 lanes) then calls the 8-lane function a run at the default
// width stored, and lanes 8-15 of every subgroup read zeros: half the paths are lost (issue
// 33; tests/lavapipe_cache_repro/). So a width the user sets gets a cache folder of its own,
// under MESA_SHADER_CACHE_DIR where the user set one. Only Mesa reads these variables.
void separateLavapipeShaderCache() {
    static bool done = false; // a second Context must not nest the folder again
    const char* width = std::getenv("LP_NATIVE_VECTOR_WIDTH");
    if (done || !width || !*width || std::strspn(width, "0123456789") != std::strlen(width))
        return;
    done = true;
    std::string dir;
    if (const char* base = std::getenv("MESA_SHADER_CACHE_DIR"); base && *base)
        dir = std::string(base) + "/lp_native_vector_width_" + width;
    else if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        dir = std::string(xdg) + "/mesa_shader_cache_lp_width_" + width;
    else if (const char* home = std::getenv("HOME"); home && *home)
        dir = std::string(home) + "/.cache/mesa_shader_cache_lp_width_" + width;
    std::error_code error;
    if (!dir.empty())
        std::filesystem::create_directories(dir, error);
    if (dir.empty() || error)
        setenv("MESA_SHADER_CACHE_DISABLE", "true", /*overwrite=*/1); // no folder: no cache
    else
        setenv("MESA_SHADER_CACHE_DIR", dir.c_str(), /*overwrite=*/1);
}

} // namespace

void Context::createInstance(bool validation, const std::vector<const char*>& extraExtensions) {
    defaultLavapipeThreads(); // before the driver reads them, at instance creation
    separateLavapipeShaderCache();
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "wavefront";
    app.apiVersion = VK_API_VERSION_1_2;

    std::vector<const char*> layers;
    std::vector<const char*> extensions = extraExtensions;
    if (validation) {
        if (!hasLayer(kValidationLayer))
            throw InternalError("validation requested but VK_LAYER_KHRONOS_validation is not "
                                "installed. On Debian install vulkan-validationlayers.");
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                    VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = &Context::onDebugMessage;
    messengerInfo.pUserData = this;

    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    if (validation)
        info.pNext = &messengerInfo; // also catches messages from instance creation itself
    VkResult result = vkCreateInstance(&info, nullptr, &instance_);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw InternalError("No Vulkan 1.2 driver found. On Debian install mesa-vulkan-drivers.");
    VK_CHECK(result);

    if (validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        VK_CHECK(create(instance_, &messengerInfo, nullptr, &messenger_));
    }
}

VkBool32 Context::onDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                 VkDebugUtilsMessageTypeFlagsEXT,
                                 const VkDebugUtilsMessengerCallbackDataEXT* data, void* self) {
    auto* context = static_cast<Context*>(self);
    context->validationMessages_.fetch_add(1);
    const char* level =
        severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning";
    std::fprintf(stderr, "wavefront: validation %s: %s\n", level, data->pMessage);
    return VK_FALSE;
}

void Context::pickPhysicalDevice(std::optional<int> index, bool quiet) {
    uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(instance_, &count, nullptr));
    if (count == 0)
        throw InternalError("No Vulkan device found. On Debian install mesa-vulkan-drivers.");
    std::vector<VkPhysicalDevice> devices(count);
    VK_CHECK(vkEnumeratePhysicalDevices(instance_, &count, devices.data()));

    if (index) {
        if (*index < 0 || *index >= static_cast<int>(count))
            throw UsageError("device index " + std::to_string(*index) + " out of range: " +
                             std::to_string(count) + " Vulkan device(s) present");
        physicalDevice_ = devices[*index];
    } else {
        int bestRank = -1;
        for (VkPhysicalDevice candidate : devices) {
            VkPhysicalDeviceProperties props;
            vkGetPhysicalDeviceProperties(candidate, &props);
            if (props.apiVersion < VK_API_VERSION_1_2)
                continue;
            if (deviceTypeRank(props.deviceType) > bestRank) {
                bestRank = deviceTypeRank(props.deviceType);
                physicalDevice_ = candidate;
            }
        }
        if (!physicalDevice_)
            throw InternalError("No Vulkan 1.2 device found. On Debian install "
                                "mesa-vulkan-drivers.");
    }
    VkPhysicalDeviceSubgroupProperties subgroup{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    subgroup.pNext = &driver;
    VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props2.pNext = &subgroup;
    vkGetPhysicalDeviceProperties2(physicalDevice_, &props2);
    properties_ = props2.properties;
    if (properties_.apiVersion < VK_API_VERSION_1_2)
        throw InternalError(std::string("device '") + properties_.deviceName +
                            "' supports only Vulkan " +
                            std::to_string(VK_API_VERSION_MINOR(properties_.apiVersion)) +
                            ".x; Wavefront needs 1.2");
    const VkSubgroupFeatureFlags needed =
        VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_BALLOT_BIT;
    if ((subgroup.supportedOperations & needed) != needed ||
        !(subgroup.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT))
        throw InternalError(std::string("device '") + properties_.deviceName +
                            "' lacks subgroup ballot in compute shaders");
    subgroupSize_ = subgroup.subgroupSize;
    deviceName_ = properties_.deviceName;
    driverInfo_ = std::string(driver.driverName) + " " + driver.driverInfo;
    vkGetPhysicalDeviceMemoryProperties(physicalDevice_, &memoryProperties_);
    if (!quiet && std::getenv("WAVEFRONT_VERBOSE"))
        std::fprintf(stderr, "wavefront: device %s (%s)\n", deviceName_.c_str(),
                     driverInfo_.c_str());
}

namespace {

const char* const kRayTracingExtensions[] = {
    VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME, VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
    VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME};

} // namespace

void Context::queryRayTracing() {
    uint32_t count = 0;
    VK_CHECK(vkEnumerateDeviceExtensionProperties(physicalDevice_, nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> extensions(count);
    VK_CHECK(vkEnumerateDeviceExtensionProperties(physicalDevice_, nullptr, &count,
                                                  extensions.data()));
    for (const char* wanted : kRayTracingExtensions) {
        const bool present =
            std::any_of(extensions.begin(), extensions.end(), [&](const auto& e) {
                return std::strcmp(e.extensionName, wanted) == 0;
            });
        if (!present)
            return;
    }
    VkPhysicalDeviceBufferDeviceAddressFeatures address{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_BUFFER_DEVICE_ADDRESS_FEATURES};
    VkPhysicalDeviceAccelerationStructureFeaturesKHR acceleration{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
    VkPhysicalDeviceRayTracingPipelineFeaturesKHR pipeline{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
    acceleration.pNext = &address;
    pipeline.pNext = &acceleration;
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    features.pNext = &pipeline;
    vkGetPhysicalDeviceFeatures2(physicalDevice_, &features);
    rayTracingSupported_ = address.bufferDeviceAddress && acceleration.accelerationStructure &&
                           pipeline.rayTracingPipeline &&
                           pipeline.rayTracingPipelineTraceRaysIndirect;
    if (!rayTracingSupported_)
        return;
    VkPhysicalDeviceAccelerationStructurePropertiesKHR asProperties{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
    rayTracingProperties_ = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
    rayTracingProperties_.pNext = &asProperties;
    VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props.pNext = &rayTracingProperties_;
    vkGetPhysicalDeviceProperties2(physicalDevice_, &props);
    rayTracingProperties_.pNext = nullptr;
    minScratchAlignment_ = std::max(1u, asProperties.minAccelerationStructureScratchOffsetAlignment);
}

void Context::createDevice(RayTracingRequest rayTracing) {
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, families.data());
    bool found = false;
    for (uint32_t i = 0; i < familyCount && !found; ++i) {
        if ((families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) && families[i].timestampValidBits &&
            (!surface_ || canPresent(i, families[i]))) {
            queueFamily_ = i;
            found = true;
        }
    }
    if (!found)
        throw InternalError(deviceName_ + (surface_ ? " has no queue family that computes, draws "
                                                      "and presents to the window, with timestamps"
                                                    : " has no compute queue with timestamps"));

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = queueFamily_;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;

    const char* swapchainExtension = VK_KHR_SWAPCHAIN_EXTENSION_NAME;
    VkPhysicalDeviceFeatures supported{};
    vkGetPhysicalDeviceFeatures(physicalDevice_, &supported);
    VkPhysicalDeviceFeatures enabled{};
    enabled.shaderInt64 = supported.shaderInt64;
    shaderInt64_ = supported.shaderInt64 == VK_TRUE;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pEnabledFeatures = &enabled;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    std::vector<const char*> extensions;
    if (surface_)
        extensions.push_back(swapchainExtension);
    rayTracingEnabled_ =
        rayTracingSupported_ &&
        (rayTracing == RayTracingRequest::Required ||
         (rayTracing == RayTracingRequest::Auto &&
          properties_.deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU));
    // Only what the ray-tracing passes use: addresses for the structures' inputs and the
    // shader binding table, acceleration structures, pipelines traced by indirect arguments.
    VkPhysicalDeviceBufferDeviceAddressFeatures address{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_BUFFER_DEVICE_ADDRESS_FEATURES};
    address.bufferDeviceAddress = VK_TRUE;
    VkPhysicalDeviceAccelerationStructureFeaturesKHR acceleration{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
    acceleration.accelerationStructure = VK_TRUE;
    acceleration.pNext = &address;
    VkPhysicalDeviceRayTracingPipelineFeaturesKHR pipeline{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
    pipeline.rayTracingPipeline = VK_TRUE;
    pipeline.rayTracingPipelineTraceRaysIndirect = VK_TRUE;
    pipeline.pNext = &acceleration;
    if (rayTracingEnabled_) {
        for (const char* name : kRayTracingExtensions)
            extensions.push_back(name);
        info.pNext = &pipeline;
    }
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VK_CHECK(vkCreateDevice(physicalDevice_, &info, nullptr, &device_));
    if (rayTracingEnabled_)
        loadRayTracingFunctions();
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = queueFamily_;
    VK_CHECK(vkCreateCommandPool(device_, &poolInfo, nullptr, &commandPool_));
}

void Context::loadRayTracingFunctions() {
    const auto load = [&](auto& function, const char* name) {
        function = reinterpret_cast<std::remove_reference_t<decltype(function)>>(
            vkGetDeviceProcAddr(device_, name));
        if (!function)
            throw InternalError(std::string("vkGetDeviceProcAddr found no ") + name + " on " +
                                deviceName_ + ", which offers ray tracing");
    };
    load(rt_.getBufferDeviceAddress, "vkGetBufferDeviceAddress");
    load(rt_.createAccelerationStructure, "vkCreateAccelerationStructureKHR");
    load(rt_.destroyAccelerationStructure, "vkDestroyAccelerationStructureKHR");
    load(rt_.getAccelerationStructureBuildSizes, "vkGetAccelerationStructureBuildSizesKHR");
    load(rt_.getAccelerationStructureDeviceAddress, "vkGetAccelerationStructureDeviceAddressKHR");
    load(rt_.cmdBuildAccelerationStructures, "vkCmdBuildAccelerationStructuresKHR");
    load(rt_.createRayTracingPipelines, "vkCreateRayTracingPipelinesKHR");
    load(rt_.getRayTracingShaderGroupHandles, "vkGetRayTracingShaderGroupHandlesKHR");
    load(rt_.cmdTraceRaysIndirect, "vkCmdTraceRaysIndirectKHR");
}

bool Context::canPresent(uint32_t family, const VkQueueFamilyProperties& properties) const {
    VkBool32 supported = VK_FALSE;
    VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(physicalDevice_, family, surface_, &supported));
    return supported && (properties.queueFlags & VK_QUEUE_GRAPHICS_BIT);
}

uint32_t Context::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags wanted) const {
    for (uint32_t i = 0; i < memoryProperties_.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) &&
            (memoryProperties_.memoryTypes[i].propertyFlags & wanted) == wanted)
            return i;
    throw InternalError("no Vulkan memory type with the needed properties on " + deviceName_);
}

void Context::submitAndWait(const std::function<void(VkCommandBuffer)>& record) const {
    VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocInfo.commandPool = commandPool_;
    allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocInfo.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateCommandBuffers(device_, &allocInfo, &cmd));
    VkFence fence = VK_NULL_HANDLE;
    try {
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
        record(cmd);
        VK_CHECK(vkEndCommandBuffer(cmd));
        VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VK_CHECK(vkCreateFence(device_, &fenceInfo, nullptr, &fence));
        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &cmd;
        VK_CHECK(vkQueueSubmit(queue_, 1, &submit, fence));
        VK_CHECK(vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX));
    } catch (...) {
        if (fence)
            vkDestroyFence(device_, fence, nullptr);
        vkFreeCommandBuffers(device_, commandPool_, 1, &cmd);
        throw;
    }
    vkDestroyFence(device_, fence, nullptr);
    vkFreeCommandBuffers(device_, commandPool_, 1, &cmd);
}

} // namespace wf
