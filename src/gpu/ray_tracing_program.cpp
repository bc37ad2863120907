#include "gpu/ray_tracing_program.h"

#include <cstring>

#include "errors.h"
#include "gpu/compute_program.h"
#include "gpu/context.h"
#include "gpu/vk_check.h"

namespace wf {
namespace {

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
    return (value + alignment - 1) / alignment * alignment;
}

} // namespace

RayTracingProgram::RayTracingProgram(const Context& context, std::string name,
                                     const RayTracingShaders& shaders,
                                     const DescriptorTable& table, uint32_t pushConstantBytes)
    : context_(context), name_(std::move(name)), set_(table.set()),
      pushBytes_(pushConstantBytes) {
    if (!context.rayTracingEnabled())
        throw InternalError("pass \"" + name_ + "\" needs a context with ray tracing enabled");
    try {
        create(context, shaders, table);
    } catch (const InternalError& error) {
        release();
        throw InternalError(std::string(error.what()) + " (pass \"" + name_ + "\")");
    } catch (...) {
        release();
        throw;
    }
}

void RayTracingProgram::create(const Context& context, const RayTracingShaders& shaders,
                               const DescriptorTable& table) {
    VkDevice device = context.device();
    const RayTracingFunctions& rt = context.rt();
    layout_ = createPipelineLayout(device, table, VK_SHADER_STAGE_RAYGEN_BIT_KHR, pushBytes_);

    std::vector<VkShaderModule> modules;
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    const auto stage = [&](const Spirv& spirv, VkShaderStageFlagBits bit) -> uint32_t {
        if (spirv.empty())
            return VK_SHADER_UNUSED_KHR;
        VkShaderModule module = createShaderModule(device, spirv);
        modules.push_back(module);
        VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        info.stage = bit;
        info.module = module;
        info.pName = "main";
        stages.push_back(info);
        return static_cast<uint32_t>(stages.size() - 1);
    };
    const auto group = [](VkRayTracingShaderGroupTypeKHR type, uint32_t general,
                          uint32_t closest, uint32_t any, uint32_t intersection) {
        VkRayTracingShaderGroupCreateInfoKHR info{
            VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR};
        info.type = type;
        info.generalShader = general;
        info.closestHitShader = closest;
        info.anyHitShader = any;
        info.intersectionShader = intersection;
        return info;
    };
    VkResult result = VK_SUCCESS;
    try {
        std::vector<VkRayTracingShaderGroupCreateInfoKHR> groups;
        groups.push_back(group(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR,
                               stage(shaders.rayGeneration, VK_SHADER_STAGE_RAYGEN_BIT_KHR),
                               VK_SHADER_UNUSED_KHR, VK_SHADER_UNUSED_KHR,
                               VK_SHADER_UNUSED_KHR));
        groups.push_back(group(VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR,
                               stage(shaders.miss, VK_SHADER_STAGE_MISS_BIT_KHR),
                               VK_SHADER_UNUSED_KHR, VK_SHADER_UNUSED_KHR,
                               VK_SHADER_UNUSED_KHR));
        // Hit group 0 always exists (possibly empty: an opaque triangle then just hits), so
        // that hit group 1 keeps its index.
        groups.push_back(group(
            VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR, VK_SHADER_UNUSED_KHR,
            stage(shaders.triangleClosestHit, VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR),
            stage(shaders.triangleAnyHit, VK_SHADER_STAGE_ANY_HIT_BIT_KHR), VK_SHADER_UNUSED_KHR));
        if (!shaders.boxIntersection.empty())
            groups.push_back(group(
                VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR, VK_SHADER_UNUSED_KHR,
                stage(shaders.boxClosestHit, VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR),
                stage(shaders.boxAnyHit, VK_SHADER_STAGE_ANY_HIT_BIT_KHR),
                stage(shaders.boxIntersection, VK_SHADER_STAGE_INTERSECTION_BIT_KHR)));
        VkRayTracingPipelineCreateInfoKHR info{
            VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR};
        info.stageCount = static_cast<uint32_t>(stages.size());
        info.pStages = stages.data();
        info.groupCount = static_cast<uint32_t>(groups.size());
        info.pGroups = groups.data();
        info.maxPipelineRayRecursionDepth = 1; // rays are traced from ray generation only
        info.layout = layout_;
        result = rt.createRayTracingPipelines(device, VK_NULL_HANDLE, VK_NULL_HANDLE, 1, &info,
                                              nullptr, &pipeline_);
        for (VkShaderModule module : modules)
            vkDestroyShaderModule(device, module, nullptr);
        modules.clear();
        VK_CHECK(result);

        // The binding table: ray generation, miss, hit groups, each region on the base
        // alignment, records on the handle alignment.
        const auto& properties = context.rayTracingProperties();
        const uint32_t handleSize = properties.shaderGroupHandleSize;
        const VkDeviceSize stride =
            alignUp(handleSize, properties.shaderGroupHandleAlignment);
        const VkDeviceSize base = properties.shaderGroupBaseAlignment;
        const uint32_t groupCount = static_cast<uint32_t>(groups.size());
        std::vector<uint8_t> handles(size_t(groupCount) * handleSize);
        VK_CHECK(rt.getRayTracingShaderGroupHandles(device, pipeline_, 0, groupCount,
                                                    handles.size(), handles.data()));
        const VkDeviceSize hitOffset = 2 * alignUp(stride, base);
        const VkDeviceSize hitBytes = stride * (groupCount - 2);
        std::vector<uint8_t> bytes(hitOffset + hitBytes, 0);
        std::memcpy(bytes.data(), handles.data(), handleSize);
        std::memcpy(bytes.data() + alignUp(stride, base), handles.data() + handleSize,
                    handleSize);
        for (uint32_t g = 2; g < groupCount; ++g)
            std::memcpy(bytes.data() + hitOffset + (g - 2) * stride,
                        handles.data() + size_t(g) * handleSize, handleSize);
        // Room to put the table's start on the base alignment whatever the allocation gives.
        table_ = Buffer(context, name_ + " shader binding table", bytes.size() + base,
                        VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR |
                            VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT);
        const VkDeviceAddress address = alignUp(table_.address(), base);
        std::vector<uint8_t> shifted(table_.size(), 0);
        std::memcpy(shifted.data() + (address - table_.address()), bytes.data(), bytes.size());
        table_.upload(shifted);
        rayGenRegion_ = {address, stride, stride};
        missRegion_ = {address + alignUp(stride, base), stride, stride};
        hitRegion_ = {address + hitOffset, stride, hitBytes};
    } catch (...) {
        for (VkShaderModule module : modules)
            vkDestroyShaderModule(device, module, nullptr);
        throw;
    }
}

RayTracingProgram::~RayTracingProgram() { release(); }

void RayTracingProgram::release() {
    VkDevice device = context_.device();
    if (pipeline_)
        vkDestroyPipeline(device, pipeline_, nullptr);
    if (layout_)
        vkDestroyPipelineLayout(device, layout_, nullptr);
    pipeline_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
}

void RayTracingProgram::traceIndirect(VkCommandBuffer cmd, const Buffer& args,
                                      VkDeviceSize offset, const void* push) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, layout_, 0, 1, &set_, 0,
                            nullptr);
    if (pushBytes_ && push)
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_RAYGEN_BIT_KHR, 0, pushBytes_, push);
    context_.rt().cmdTraceRaysIndirect(cmd, &rayGenRegion_, &missRegion_, &hitRegion_,
                                       &callableRegion_, args.address() + offset);
}

void rayTracingBarrier(VkCommandBuffer cmd) {
    const VkPipelineStageFlags stages = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT |
                                        VK_PIPELINE_STAGE_TRANSFER_BIT |
                                        VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR;
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT |
                            VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT;
    vkCmdPipelineBarrier(cmd, stages, stages | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT, 0, 1, &barrier,
                         0, nullptr, 0, nullptr);
}

} // namespace wf
