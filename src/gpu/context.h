// The Vulkan instance, device and compute queue, plus the validation-message counter that the
// tests read. With WAVEFRONT_VALIDATION=1 the Khronos validation layer is enabled and every
// message it emits is printed and counted.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/ray_tracing_functions.h"

namespace wf {

// Whether to enable the driver's ray tracing (VK_KHR_acceleration_structure,
// VK_KHR_ray_tracing_pipeline, buffer device addresses): only for a render that traces through
// it (--traversal rt, or auto where it picks rt), so a BVH render's device is as before.
//   Off:      never.
//   Auto:     where the device has it and is a GPU: on lavapipe (a CPU device) the project's own
//             BVH traced faster (docs/performance.md, "Traversal: bvh or rt").
//   Required: UsageError where the device lacks it.
enum class RayTracingRequest { Off, Auto, Required };

struct ContextOptions {
    std::optional<int> deviceIndex; // --device N; otherwise WAVEFRONT_DEVICE, else the best one
    bool validation = false;        // also switched on by WAVEFRONT_VALIDATION=1
    bool quiet = false;
    RayTracingRequest rayTracing = RayTracingRequest::Off; // --traversal
    // Presentation (the viewer; empty for headless use): the window system's instance
    // extensions, and a callback that creates the window's surface once the instance exists.
    // With it the context owns the surface, enables VK_KHR_swapchain and picks a queue family
    // that computes, draws (blits and the overlay need graphics) and presents to the surface.
    std::vector<const char*> instanceExtensions;
    std::function<VkSurfaceKHR(VkInstance)> createSurface;
};

class Context {
public:
    explicit Context(const ContextOptions& options = {});
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance instance() const { return instance_; }
    VkSurfaceKHR surface() const { return surface_; } // VK_NULL_HANDLE when headless
    VkDevice device() const { return device_; }
    VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
    VkQueue queue() const { return queue_; }
    uint32_t queueFamily() const { return queueFamily_; }
    VkCommandPool commandPool() const { return commandPool_; }
    const VkPhysicalDeviceProperties& properties() const { return properties_; }
    uint32_t subgroupSize() const { return subgroupSize_; }
    // 64-bit integers in shaders (enabled when the device has them; WF_PACKED_STORES).
    bool shaderInt64() const { return shaderInt64_; }
    // The device offers ray-tracing pipelines and acceleration structures (enabled or not).
    bool rayTracingSupported() const { return rayTracingSupported_; }
    // Enabled on this device: the functions below are loaded.
    bool rayTracingEnabled() const { return rayTracingEnabled_; }
    const RayTracingFunctions& rt() const { return rt_; }
    const VkPhysicalDeviceRayTracingPipelinePropertiesKHR& rayTracingProperties() const {
        return rayTracingProperties_;
    }
    uint32_t minScratchAlignment() const { return minScratchAlignment_; }
    const std::string& deviceName() const { return deviceName_; }
    const std::string& driverInfo() const { return driverInfo_; }
    bool validationEnabled() const { return messenger_ != VK_NULL_HANDLE; }
    uint32_t validationMessageCount() const { return validationMessages_.load(); }
    uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags wanted) const;

    // Records commands into a fresh command buffer, submits it and waits for it.
    void submitAndWait(const std::function<void(VkCommandBuffer)>& record) const;

private:
    void createInstance(bool validation, const std::vector<const char*>& extraExtensions);
    void pickPhysicalDevice(std::optional<int> index, bool quiet);
    void queryRayTracing();
    void loadRayTracingFunctions();
    void createDevice(RayTracingRequest rayTracing);
    bool canPresent(uint32_t family, const VkQueueFamilyProperties& properties) const;
    static VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(
        VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
        const VkDebugUtilsMessengerCallbackDataEXT* data, void* self);

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queueFamily_ = 0;
    VkCommandPool commandPool_ = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties_{};
    VkPhysicalDeviceMemoryProperties memoryProperties_{};
    uint32_t subgroupSize_ = 0;
    bool shaderInt64_ = false;
    bool rayTracingSupported_ = false;
    bool rayTracingEnabled_ = false;
    RayTracingFunctions rt_{};
    VkPhysicalDeviceRayTracingPipelinePropertiesKHR rayTracingProperties_{};
    uint32_t minScratchAlignment_ = 256;
    std::string deviceName_;
    std::string driverInfo_;
    std::atomic<uint32_t> validationMessages_{0};
};

} // namespace wf
