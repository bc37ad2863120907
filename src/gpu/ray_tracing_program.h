// A ray-tracing pipeline (VK_KHR_ray_tracing_pipeline) over the passes' shared descriptor set:
// one ray-generation shader, one miss shader and up to two hit groups (triangles; procedural
// boxes with their intersection shader), with its shader binding table, traced by indirect
// arguments that an earlier pass wrote on the GPU. The twin of ComputeProgram.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/buffer.h"

namespace wf {

class Context;
class DescriptorTable;

using Spirv = std::vector<uint32_t>;

// Empty modules are absent. A hit group exists when any of its shaders does.
struct RayTracingShaders {
    Spirv rayGeneration;
    Spirv miss;
    Spirv triangleClosestHit; // hit group 0
    Spirv triangleAnyHit;
    Spirv boxIntersection;    // hit group 1 (procedural)
    Spirv boxClosestHit;
    Spirv boxAnyHit;
};

class RayTracingProgram {
public:
    RayTracingProgram(const Context& context, std::string name, const RayTracingShaders& shaders,
                      const DescriptorTable& table, uint32_t pushConstantBytes);
    ~RayTracingProgram();
    RayTracingProgram(const RayTracingProgram&) = delete;
    RayTracingProgram& operator=(const RayTracingProgram&) = delete;

    // Traces width x height x depth rays from the VkTraceRaysIndirectCommandKHR at `offset`.
    void traceIndirect(VkCommandBuffer cmd, const Buffer& args, VkDeviceSize offset,
                       const void* push = nullptr) const;

private:
    void create(const Context& context, const RayTracingShaders& shaders,
                const DescriptorTable& table);
    void release();

    const Context& context_;
    std::string name_;
    VkDescriptorSet set_;
    uint32_t pushBytes_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    Buffer table_; // the shader binding table
    VkStridedDeviceAddressRegionKHR rayGenRegion_{};
    VkStridedDeviceAddressRegionKHR missRegion_{};
    VkStridedDeviceAddressRegionKHR hitRegion_{};
    VkStridedDeviceAddressRegionKHR callableRegion_{};
};

// The stages the ray-tracing passes read and write in, for barriers around them.
constexpr VkShaderStageFlags kRayTracingStages =
    VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_MISS_BIT_KHR |
    VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR | VK_SHADER_STAGE_ANY_HIT_BIT_KHR |
    VK_SHADER_STAGE_INTERSECTION_BIT_KHR;

// A full barrier for waves with ray-tracing passes: compute, transfer and ray-tracing writes
// become visible to all three and to the indirect-argument fetch (computeBarrier leaves out
// the ray-tracing stage, which a device without the feature must not name).
void rayTracingBarrier(VkCommandBuffer cmd);

} // namespace wf
