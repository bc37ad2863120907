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

// How a shader reads a buffer. Read-only tables that passes fetch at scattered indices, and the
// path state a pass reads, are bound as storage texel buffers of 32-bit uints (GLSL
// `readonly uimageBuffer`, read with imageLoad): lavapipe turns a storage-buffer load into a
// branchy loop over the lanes, 2.5-3x slower per vec4, and a texelFetch of a uint format into
// a call to a sampling function that makes the caller spill its registers, where imageLoad is
// one inlined gather (docs/architecture.md, "Reading memory on lavapipe"). A table picks the
// texel that divides its struct: UintTexels (RGBA32UI, 16 bytes), Uint2Texels (RG32UI,
// 8 bytes) or Uint1Texels (R32UI, 4 bytes); shaders unpack floats with uintBitsToFloat, so the
// bits are exactly those stored. Small read-only blocks every invocation reads at the same
// address are uniform buffers (std140).
enum class BufferAccess { Storage, UintTexels, Uint2Texels, Uint1Texels, Uniform };

// Bytes per texel of a texel access (0 for Storage and Uniform).
uint32_t texelBytes(BufferAccess access);

struct DescriptorBinding {
    uint32_t binding;
    const Buffer* buffer;
    BufferAccess access = BufferAccess::Storage;
};
using DescriptorBindings = std::vector<DescriptorBinding>;

// The top-level acceleration structure of ray-traced scenes, at its own binding.
struct AccelerationBinding {
    uint32_t binding = 0;
    VkAccelerationStructureKHR topLevel = VK_NULL_HANDLE; // none: no such binding
};

// Buffers by binding number; only the bindings a scene needs are present. With a top level,
// the set is visible to the ray-tracing stages too.
class DescriptorTable {
public:
    DescriptorTable(const Context& context, const DescriptorBindings& bindings,
                    const AccelerationBinding& acceleration = {});
    ~DescriptorTable();
    DescriptorTable(const DescriptorTable&) = delete;
    DescriptorTable& operator=(const DescriptorTable&) = delete;

    VkDescriptorSetLayout layout() const { return layout_; }
    VkDescriptorSet set() const { return set_; }

    // Points the same bindings at other buffers (a new frame's scene): the layout, the set and
    // so every pipeline made over the table stay. InternalError when `bindings` differ from the
    // table's in number, binding or kind. No command buffer using the set may be in flight.
    void rewrite(const Context& context, const DescriptorBindings& bindings,
                 const AccelerationBinding& acceleration = {});

private:
    void create(const Context& context, const DescriptorBindings& bindings,
                const AccelerationBinding& acceleration);
    void write(const Context& context, const DescriptorBindings& bindings,
               const AccelerationBinding& acceleration);
    void release();

    VkDevice device_;
    VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    std::vector<VkBufferView> views_; // one per texel-buffer binding
    // (binding, descriptor type) as created, the acceleration binding last: what rewrite keeps.
    std::vector<std::pair<uint32_t, int>> shape_;
};

// A pipeline layout over the table's one descriptor set, with `pushBytes` of push constants
// for `stages` (none when 0), and a shader module: what compute and ray-tracing pipelines share.
VkPipelineLayout createPipelineLayout(VkDevice device, const DescriptorTable& table,
                                      VkShaderStageFlags stages, uint32_t pushBytes);
VkShaderModule createShaderModule(VkDevice device, const std::vector<uint32_t>& spirv);

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
