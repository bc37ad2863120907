#include "gpu/acceleration_structure.h"

#include <algorithm>
#include <chrono>
#include <cstring>

#include "errors.h"
#include "gpu/context.h"
#include "gpu/vk_check.h"

namespace wf {
namespace {

constexpr VkBufferUsageFlags kAddressed = VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
    return (value + alignment - 1) / alignment * alignment;
}

// The structures are read many times per pixel and built once per scene.
constexpr VkBuildAccelerationStructureFlagsKHR kBuildFlags =
    VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;

void buildBarrier(VkCommandBuffer cmd, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
    barrier.dstAccessMask = dstAccess;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, dstStage, 0,
                         1, &barrier, 0, nullptr, 0, nullptr);
}

} // namespace

AccelerationStructureSet::AccelerationStructureSet(const Context& context,
                                                   const std::vector<BottomLevelInput>& bottom,
                                                   const std::vector<TopLevelInstance>& instances)
    : context_(context) {
    if (!context.rayTracingEnabled())
        throw InternalError("acceleration structures need a context with ray tracing enabled");
    const RayTracingFunctions& rt = context.rt();
    VkDevice device = context.device();
    const VkDeviceSize scratchAlignment = context.minScratchAlignment();
    const auto create = [&](Built& built, VkAccelerationStructureTypeKHR type,
                            VkDeviceSize size, const char* name) {
        built.storage = Buffer(context, name, size,
                               VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR | kAddressed);
        VkAccelerationStructureCreateInfoKHR info{
            VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
        info.buffer = built.storage.handle();
        info.size = size;
        info.type = type;
        VK_CHECK(rt.createAccelerationStructure(device, &info, nullptr, &built.handle));
    };
    try {
        // Bottom levels: geometry, sizes, storage; scratch regions side by side in one buffer.
        const size_t count = bottom.size();
        std::vector<VkAccelerationStructureGeometryKHR> geometries(count);
        std::vector<VkAccelerationStructureBuildGeometryInfoKHR> builds(count);
        std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges(count);
        std::vector<VkDeviceSize> scratchOffsets(count);
        VkDeviceSize scratchBytes = 0;
        bottom_.resize(count);
        for (size_t i = 0; i < count; ++i) {
            const BottomLevelInput& input = bottom[i];
            VkAccelerationStructureGeometryKHR& geometry = geometries[i];
            geometry = {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
            geometry.flags = input.opaque ? VK_GEOMETRY_OPAQUE_BIT_KHR
                                          : VK_GEOMETRY_NO_DUPLICATE_ANY_HIT_INVOCATION_BIT_KHR;
            if (input.triangles) {
                geometry.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
                auto& triangles = geometry.geometry.triangles;
                triangles = {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR};
                triangles.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
                triangles.vertexData.deviceAddress = input.data;
                triangles.vertexStride = 16;
                triangles.maxVertex = std::max(input.primitiveCount * 3, 1u) - 1;
                triangles.indexType = VK_INDEX_TYPE_NONE_KHR;
            } else {
                geometry.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
                auto& boxes = geometry.geometry.aabbs;
                boxes = {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR};
                boxes.data.deviceAddress = input.data;
                boxes.stride = sizeof(VkAabbPositionsKHR);
            }
            VkAccelerationStructureBuildGeometryInfoKHR& build = builds[i];
            build = {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
            build.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
            build.flags = kBuildFlags;
            build.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
            build.geometryCount = 1;
            build.pGeometries = &geometry;
            VkAccelerationStructureBuildSizesInfoKHR sizes{
                VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
            rt.getAccelerationStructureBuildSizes(device,
                                                  VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                                                  &build, &input.primitiveCount, &sizes);
            create(bottom_[i], VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
                   sizes.accelerationStructureSize,
                   input.triangles ? "bottom-level structure (triangles)"
                                   : "bottom-level structure (spheres)");
            build.dstAccelerationStructure = bottom_[i].handle;
            scratchOffsets[i] = scratchBytes;
            scratchBytes += alignUp(sizes.buildScratchSize, scratchAlignment);
            ranges[i] = {input.primitiveCount, 0, 0, 0};
        }

        // The top level over the placements.
        std::vector<VkAccelerationStructureInstanceKHR> placed(instances.size());
        for (size_t i = 0; i < instances.size(); ++i) {
            const TopLevelInstance& instance = instances[i];
            if (instance.bottomLevel >= count || instance.customIndex >= (1u << 24))
                throw InternalError("top-level instance " + std::to_string(i) + " is malformed");
            VkAccelerationStructureDeviceAddressInfoKHR addressInfo{
                VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
            addressInfo.accelerationStructure = bottom_[instance.bottomLevel].handle;
            placed[i].transform = instance.worldFromObject;
            placed[i].instanceCustomIndex = instance.customIndex;
            placed[i].mask = 0xff;
            placed[i].instanceShaderBindingTableRecordOffset = instance.hitGroup;
            // No ray asks for face culling; the flag says so for mirrored placements too.
            placed[i].flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR;
            placed[i].accelerationStructureReference =
                rt.getAccelerationStructureDeviceAddress(device, &addressInfo);
        }
        Buffer instanceBuffer(context, "top-level instances",
                              placed.size() * sizeof(VkAccelerationStructureInstanceKHR),
                              VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                                  kAddressed);
        if (!placed.empty())
            instanceBuffer.upload(placed);
        VkAccelerationStructureGeometryKHR topGeometry{
            VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
        topGeometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
        topGeometry.geometry.instances = {
            VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR};
        topGeometry.geometry.instances.data.deviceAddress = instanceBuffer.address();
        VkAccelerationStructureBuildGeometryInfoKHR topBuild{
            VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
        topBuild.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
        topBuild.flags = kBuildFlags;
        topBuild.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
        topBuild.geometryCount = 1;
        topBuild.pGeometries = &topGeometry;
        const uint32_t instanceCount = static_cast<uint32_t>(placed.size());
        VkAccelerationStructureBuildSizesInfoKHR topSizes{
            VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
        rt.getAccelerationStructureBuildSizes(device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                                              &topBuild, &instanceCount, &topSizes);
        create(top_, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR,
               topSizes.accelerationStructureSize, "top-level structure");
        topLevel_ = top_.handle;
        topBuild.dstAccelerationStructure = top_.handle;

        // The top level reuses the scratch after the bottom levels are done with it.
        scratchBytes = std::max(scratchBytes, alignUp(topSizes.buildScratchSize, scratchAlignment));
        Buffer scratch(context, "structure build scratch", scratchBytes + scratchAlignment,
                       kAddressed);
        const VkDeviceAddress scratchBase = alignUp(scratch.address(), scratchAlignment);
        std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> rangePointers(count);
        for (size_t i = 0; i < count; ++i) {
            builds[i].scratchData.deviceAddress = scratchBase + scratchOffsets[i];
            rangePointers[i] = &ranges[i];
        }
        topBuild.scratchData.deviceAddress = scratchBase;
        const VkAccelerationStructureBuildRangeInfoKHR topRange{instanceCount, 0, 0, 0};
        const VkAccelerationStructureBuildRangeInfoKHR* topRangePointer = &topRange;

        const auto start = std::chrono::steady_clock::now();
        context.submitAndWait([&](VkCommandBuffer cmd) {
            if (count > 0)
                rt.cmdBuildAccelerationStructures(cmd, static_cast<uint32_t>(count), builds.data(),
                                                  rangePointers.data());
            buildBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                         VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR |
                             VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR);
            rt.cmdBuildAccelerationStructures(cmd, 1, &topBuild, &topRangePointer);
            buildBarrier(cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR,
                         VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR);
        });
        buildSeconds_ =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    } catch (...) {
        release();
        throw;
    }
}

AccelerationStructureSet::~AccelerationStructureSet() { release(); }

void AccelerationStructureSet::release() {
    VkDevice device = context_.device();
    for (Built& built : bottom_)
        if (built.handle)
            context_.rt().destroyAccelerationStructure(device, built.handle, nullptr);
    bottom_.clear();
    if (top_.handle)
        context_.rt().destroyAccelerationStructure(device, top_.handle, nullptr);
    top_.handle = VK_NULL_HANDLE;
    topLevel_ = VK_NULL_HANDLE;
}

uint64_t AccelerationStructureSet::bytes() const {
    uint64_t total = top_.storage.size();
    for (const Built& built : bottom_)
        total += built.storage.size();
    return total;
}

} // namespace wf
