// The entry points of VK_KHR_acceleration_structure and VK_KHR_ray_tracing_pipeline, which the
// Vulkan loader does not export: Context loads them with vkGetDeviceProcAddr when it enables
// ray tracing, and leaves them null otherwise.
#pragma once
#include <vulkan/vulkan.h>

namespace wf {

struct RayTracingFunctions {
    PFN_vkGetBufferDeviceAddress getBufferDeviceAddress = nullptr;
    PFN_vkCreateAccelerationStructureKHR createAccelerationStructure = nullptr;
    PFN_vkDestroyAccelerationStructureKHR destroyAccelerationStructure = nullptr;
    PFN_vkGetAccelerationStructureBuildSizesKHR getAccelerationStructureBuildSizes = nullptr;
    PFN_vkGetAccelerationStructureDeviceAddressKHR getAccelerationStructureDeviceAddress = nullptr;
    PFN_vkCmdBuildAccelerationStructuresKHR cmdBuildAccelerationStructures = nullptr;
    PFN_vkCreateRayTracingPipelinesKHR createRayTracingPipelines = nullptr;
    PFN_vkGetRayTracingShaderGroupHandlesKHR getRayTracingShaderGroupHandles = nullptr;
    PFN_vkCmdTraceRaysIndirectKHR cmdTraceRaysIndirect = nullptr;
};

} // namespace wf
