// Compute pipelines and the one descriptor set they share. Every pass binds the same set (the
// scene's buffers and the path state), so passes differ only in shader and push constants.
// Dispatches carry the pass name into error messages and timer labels.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

namespace wf {

class Buffer;
class Context;

// Storage buffers by binding number; only the bindings a scene needs are present.
class DescriptorTable {
public:
    DescriptorTable(const Context& context,
                    const std::vector<std::pair<uint32_t, const Buffer*>>& bindings);
    ~DescriptorTable();
    DescriptorTable(const DescriptorTable&) = delete;
    DescriptorTable& operator=(const DescriptorTable&) = delete;

    VkDescriptorSetLayout layout() const { return layout_; }
    VkDescriptorSet set() const { return set_; }

private:
    VkDevice device_;
    VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
};

class ComputeProgram {
public:
    ComputeProgram(const Context& context, std::string name, const std::vector<uint32_t>& spirv,
                   const DescriptorTable& table, uint32_t pushConstantBytes);
    ~ComputeProgram();
    ComputeProgram(const ComputeProgram&) = delete;
    ComputeProgram& operator=(const ComputeProgram&) = delete;

    const std::string& name() const { return name_; }

    void dispatch(VkCommandBuffer cmd, uint32_t groupsX, const void* push = nullptr) const;
    void dispatchIndirect(VkCommandBuffer cmd, const Buffer& args, VkDeviceSize offset,
                          const void* push = nullptr) const;

private:
    void bind(VkCommandBuffer cmd, const void* push) const;
    void release();

    VkDevice device_;
    std::string name_;
    VkDescriptorSet set_;
    uint32_t pushBytes_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

// A full barrier between passes: compute writes become visible to compute reads and to the
// indirect-argument fetch of the next dispatch.
void computeBarrier(VkCommandBuffer cmd);

} // namespace wf
