#include "gpu/compute_program.h"

#include <map>

#include "errors.h"
#include "gpu/buffer.h"
#include "gpu/context.h"
#include "gpu/ray_tracing_program.h"
#include "gpu/vk_check.h"

namespace wf {

namespace {

VkDescriptorType descriptorType(BufferAccess access) {
    if (texelBytes(access) != 0)
        return VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
    return access == BufferAccess::Uniform ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER
                                           : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}

// Integer formats only: a float format could flush denormals or canonicalise NaNs. All three
// must support storage texel buffers on every Vulkan device.
VkFormat texelFormat(BufferAccess access) {
    switch (access) {
    case BufferAccess::Uint1Texels:
        return VK_FORMAT_R32_UINT;
    case BufferAccess::Uint2Texels:
        return VK_FORMAT_R32G32_UINT;
    default:
        return VK_FORMAT_R32G32B32A32_UINT;
    }
}

} // namespace

uint32_t texelBytes(BufferAccess access) {
    switch (access) {
    case BufferAccess::UintTexels:
        return 16;
    case BufferAccess::Uint2Texels:
        return 8;
    case BufferAccess::Uint1Texels:
        return 4;
    case BufferAccess::Storage:
    case BufferAccess::Uniform:
        break;
    }
    return 0;
}

DescriptorTable::DescriptorTable(const Context& context, const DescriptorBindings& bindings,
                                 const AccelerationBinding& acceleration)
    : device_(context.device()) {
    try {
        create(context, bindings, acceleration);
    } catch (...) {
        release();
        throw;
    }
}

void DescriptorTable::create(const Context& context, const DescriptorBindings& bindings,
                             const AccelerationBinding& acceleration) {
    std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
    std::map<VkDescriptorType, uint32_t> typeCounts;
    const bool traced = acceleration.topLevel != VK_NULL_HANDLE;
    const VkShaderStageFlags stages =
        VK_SHADER_STAGE_COMPUTE_BIT | (traced ? kRayTracingStages : VkShaderStageFlags(0));
    for (const DescriptorBinding& entry : bindings) {
        VkDescriptorSetLayoutBinding layoutBinding{};
        layoutBinding.binding = entry.binding;
        layoutBinding.descriptorType = descriptorType(entry.access);
        layoutBinding.descriptorCount = 1;
        layoutBinding.stageFlags = stages;
        layoutBindings.push_back(layoutBinding);
        ++typeCounts[layoutBinding.descriptorType];
    }
    if (traced) {
        VkDescriptorSetLayoutBinding layoutBinding{};
        layoutBinding.binding = acceleration.binding;
        layoutBinding.descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
        layoutBinding.descriptorCount = 1;
        layoutBinding.stageFlags = stages;
        layoutBindings.push_back(layoutBinding);
        ++typeCounts[layoutBinding.descriptorType];
    }
    const VkPhysicalDeviceLimits& limits = context.properties().limits;
    const auto typeCount = [&](VkDescriptorType type) {
        const auto found = typeCounts.find(type);
        return found == typeCounts.end() ? 0u : found->second;
    };
    const uint32_t texelBuffers = typeCount(VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER);
    const uint32_t storageBuffers = typeCount(VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    if (texelBuffers > limits.maxPerStageDescriptorStorageImages ||
        storageBuffers > limits.maxPerStageDescriptorStorageBuffers)
        throw InternalError("the passes' descriptor set needs " + std::to_string(texelBuffers) +
                            " storage texel buffers and " + std::to_string(storageBuffers) +
                            " storage buffers, over this device's per-stage limits");
    VkDescriptorSetLayoutCreateInfo layoutInfo{
        VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    layoutInfo.bindingCount = static_cast<uint32_t>(layoutBindings.size());
    layoutInfo.pBindings = layoutBindings.data();
    VK_CHECK(vkCreateDescriptorSetLayout(device_, &layoutInfo, nullptr, &layout_));

    std::vector<VkDescriptorPoolSize> poolSizes;
    for (const auto& [type, count] : typeCounts)
        poolSizes.push_back({type, count});
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = static_cast<uint32_t>(poolSizes.size());
    poolInfo.pPoolSizes = poolSizes.data();
    VK_CHECK(vkCreateDescriptorPool(device_, &poolInfo, nullptr, &pool_));

    VkDescriptorSetAllocateInfo allocInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocInfo.descriptorPool = pool_;
    allocInfo.descriptorSetCount = 1;
    allocInfo.pSetLayouts = &layout_;
    VK_CHECK(vkAllocateDescriptorSets(device_, &allocInfo, &set_));

    for (const VkDescriptorSetLayoutBinding& b : layoutBindings)
        shape_.emplace_back(b.binding, int(b.descriptorType));
    write(context, bindings, acceleration);
}

void DescriptorTable::rewrite(const Context& context, const DescriptorBindings& bindings,
                              const AccelerationBinding& acceleration) {
    std::vector<std::pair<uint32_t, int>> shape;
    for (const DescriptorBinding& entry : bindings)
        shape.emplace_back(entry.binding, int(descriptorType(entry.access)));
    if (acceleration.topLevel != VK_NULL_HANDLE)
        shape.emplace_back(acceleration.binding,
                           int(VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR));
    if (shape != shape_)
        throw InternalError("DescriptorTable::rewrite: other bindings than the table was made "
                            "with");
    std::vector<VkBufferView> old = std::move(views_);
    views_.clear();
    try {
        write(context, bindings, acceleration);
    } catch (...) {
        for (VkBufferView view : views_)
            vkDestroyBufferView(device_, view, nullptr);
        views_ = std::move(old);
        throw;
    }
    // The set no longer refers to the old views once the update above has returned.
    for (VkBufferView view : old)
        vkDestroyBufferView(device_, view, nullptr);
}

void DescriptorTable::write(const Context& context, const DescriptorBindings& bindings,
                            const AccelerationBinding& acceleration) {
    const bool traced = acceleration.topLevel != VK_NULL_HANDLE;
    const uint64_t maxTexels = context.properties().limits.maxTexelBufferElements;
    std::vector<VkDescriptorBufferInfo> infos(bindings.size());
    std::vector<VkWriteDescriptorSet> writes(bindings.size());
    views_.reserve(bindings.size());
    for (size_t i = 0; i < bindings.size(); ++i) {
        const DescriptorBinding& entry = bindings[i];
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = set_;
        writes[i].dstBinding = entry.binding;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = descriptorType(entry.access);
        if (const VkDeviceSize bytes = texelBytes(entry.access); bytes != 0) {
            const VkDeviceSize texels = entry.buffer->size() / bytes;
            if (texels > maxTexels)
                throw InputError("buffer '" + entry.buffer->name() + "' holds " +
                                 std::to_string(texels) + " texels, over the device's limit of " +
                                 std::to_string(maxTexels));
            VkBufferViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
            viewInfo.buffer = entry.buffer->handle();
            viewInfo.format = texelFormat(entry.access);
            viewInfo.range = texels * bytes;
            VkBufferView view = VK_NULL_HANDLE;
            VK_CHECK(vkCreateBufferView(device_, &viewInfo, nullptr, &view));
            views_.push_back(view);
            writes[i].pTexelBufferView = &views_.back();
        } else {
            if (entry.access == BufferAccess::Uniform &&
                entry.buffer->size() > context.properties().limits.maxUniformBufferRange)
                throw InternalError("buffer '" + entry.buffer->name() +
                                    "' is over the device's uniform buffer range");
            infos[i] = {entry.buffer->handle(), 0, VK_WHOLE_SIZE};
            writes[i].pBufferInfo = &infos[i];
        }
    }
    VkWriteDescriptorSetAccelerationStructureKHR topLevel{
        VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
    if (traced) {
        topLevel.accelerationStructureCount = 1;
        topLevel.pAccelerationStructures = &acceleration.topLevel;
        VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        write.pNext = &topLevel;
        write.dstSet = set_;
        write.dstBinding = acceleration.binding;
        write.descriptorCount = 1;
        write.descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
        writes.push_back(write);
    }
    vkUpdateDescriptorSets(device_, static_cast<uint32_t>(writes.size()), writes.data(), 0,
                           nullptr);
}

DescriptorTable::~DescriptorTable() { release(); }

void DescriptorTable::release() {
    for (VkBufferView view : views_)
        vkDestroyBufferView(device_, view, nullptr);
    views_.clear();
    if (pool_)
        vkDestroyDescriptorPool(device_, pool_, nullptr);
    if (layout_)
        vkDestroyDescriptorSetLayout(device_, layout_, nullptr);
    pool_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
}

VkPipelineLayout createPipelineLayout(VkDevice device, const DescriptorTable& table,
                                      VkShaderStageFlags stages, uint32_t pushBytes) {
    VkPushConstantRange range{stages, 0, pushBytes};
    VkDescriptorSetLayout setLayout = table.layout();
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &setLayout;
    layoutInfo.pushConstantRangeCount = pushBytes ? 1 : 0;
    layoutInfo.pPushConstantRanges = &range;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VK_CHECK(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout));
    return layout;
}

VkShaderModule createShaderModule(VkDevice device, const std::vector<uint32_t>& spirv) {
    VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    moduleInfo.codeSize = spirv.size() * sizeof(uint32_t);
    moduleInfo.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    VK_CHECK(vkCreateShaderModule(device, &moduleInfo, nullptr, &module));
    return module;
}

ComputeProgram::ComputeProgram(const Context& context, std::string name,
                               const std::vector<uint32_t>& spirv, const DescriptorTable& table,
                               uint32_t pushConstantBytes)
    : device_(context.device()), name_(std::move(name)), set_(table.set()),
      pushBytes_(pushConstantBytes) {
    try {
        layout_ = createPipelineLayout(device_, table, VK_SHADER_STAGE_COMPUTE_BIT,
                                       pushConstantBytes);
        VkShaderModule module = createShaderModule(device_, spirv);

        VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
        pipelineInfo.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
        pipelineInfo.stage.module = module;
        pipelineInfo.stage.pName = "main";
        pipelineInfo.layout = layout_;
        VkResult result = vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &pipelineInfo,
                                                   nullptr, &pipeline_);
        vkDestroyShaderModule(device_, module, nullptr);
        VK_CHECK(result);
    } catch (const InternalError& error) {
        release();
        throw InternalError(std::string(error.what()) + " (pass \"" + name_ + "\")");
    }
}

ComputeProgram::~ComputeProgram() { release(); }

void ComputeProgram::release() {
    if (pipeline_)
        vkDestroyPipeline(device_, pipeline_, nullptr);
    if (layout_)
        vkDestroyPipelineLayout(device_, layout_, nullptr);
    pipeline_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
}

void ComputeProgram::bind(VkCommandBuffer cmd, const void* push) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_, 0,
                            nullptr);
    if (pushBytes_ && push)
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes_, push);
}

void ComputeProgram::dispatch(VkCommandBuffer cmd, uint32_t groupsX, const void* push) const {
    bind(cmd, push);
    vkCmdDispatch(cmd, groupsX, 1, 1);
}

void ComputeProgram::dispatchIndirect(VkCommandBuffer cmd, const Buffer& args,
                                      VkDeviceSize offset, const void* push) const {
    bind(cmd, push);
    vkCmdDispatchIndirect(cmd, args.handle(), offset);
}

void computeBarrier(VkCommandBuffer cmd) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT |
                            VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT;
    vkCmdPipelineBarrier(cmd,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT |
                             VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                         0, 1, &barrier, 0, nullptr, 0, nullptr);
}

} // namespace wf
