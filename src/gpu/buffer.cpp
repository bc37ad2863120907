#include "gpu/buffer.h"

#include <atomic>
#include <cstring>
#include <utility>

#include "errors.h"
#include "gpu/context.h"
#include "gpu/vk_check.h"

namespace wf {
namespace {
std::atomic<size_t> liveBufferAllocations{0};
} // namespace

size_t Buffer::liveAllocations() { return liveBufferAllocations.load(); }

Buffer::Buffer(const Context& context, std::string name, VkDeviceSize size,
               VkBufferUsageFlags extraUsage, bool hostVisible)
    : context_(&context), name_(std::move(name)), size_(size < 16 ? 16 : size) {
    const auto& limits = context.properties().limits;
    // Acceleration structures, their inputs and binding tables are never bound to a shader as
    // buffers, so the storage-buffer range does not bound them (a large scene's exceed it).
    const bool rayTracingOnly =
        extraUsage & (VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR |
                      VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                      VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR);
    if (size_ > limits.maxStorageBufferRange && !rayTracingOnly)
        throw InputError("buffer '" + name_ + "' needs " + std::to_string(size_ >> 20) +
                         " MiB, over the device's storage buffer limit of " +
                         std::to_string(limits.maxStorageBufferRange >> 20) + " MiB");
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size_;
    // Any buffer may be bound in any of DescriptorTable's BufferAccess ways.
    info.usage = rayTracingOnly ? VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                      VK_BUFFER_USAGE_TRANSFER_DST_BIT | extraUsage
                                : VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                      VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT |
                                      VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT |
                                      VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                      VK_BUFFER_USAGE_TRANSFER_DST_BIT | extraUsage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkDevice device = context.device();
    VK_CHECK(vkCreateBuffer(device, &info, nullptr, &buffer_));

    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device, buffer_, &requirements);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = requirements.size;
    // Buffers that ray tracing reads by address (structure inputs, shader binding tables).
    VkMemoryAllocateFlagsInfo addressFlags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
    addressFlags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
    if (extraUsage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT)
        alloc.pNext = &addressFlags;
    const VkMemoryPropertyFlags hostFlags =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    try {
        alloc.memoryTypeIndex = context.findMemoryType(
            requirements.memoryTypeBits,
            hostVisible ? hostFlags : VkMemoryPropertyFlags(VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT));
        VK_CHECK(vkAllocateMemory(device, &alloc, nullptr, &memory_));
        ++liveBufferAllocations;
        VK_CHECK(vkBindBufferMemory(device, buffer_, memory_, 0));
        // Map whenever the chosen type happens to be host visible (every type on lavapipe),
        // which spares a staging copy.
        VkPhysicalDeviceMemoryProperties memProps;
        vkGetPhysicalDeviceMemoryProperties(context.physicalDevice(), &memProps);
        if ((memProps.memoryTypes[alloc.memoryTypeIndex].propertyFlags & hostFlags) == hostFlags)
            VK_CHECK(vkMapMemory(device, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
    } catch (...) {
        release();
        throw;
    }
}

Buffer::~Buffer() { release(); }

VkDeviceAddress Buffer::address() const {
    VkBufferDeviceAddressInfo info{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
    info.buffer = buffer_;
    return context_->rt().getBufferDeviceAddress(context_->device(), &info);
}

Buffer::Buffer(Buffer&& other) noexcept { *this = std::move(other); }

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this != &other) {
        release();
        context_ = std::exchange(other.context_, nullptr);
        name_ = std::move(other.name_);
        buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
        memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
        size_ = std::exchange(other.size_, 0);
        mapped_ = std::exchange(other.mapped_, nullptr);
    }
    return *this;
}

void Buffer::release() {
    if (!context_)
        return;
    VkDevice device = context_->device();
    if (mapped_)
        vkUnmapMemory(device, memory_);
    if (buffer_)
        vkDestroyBuffer(device, buffer_, nullptr);
    if (memory_) {
        vkFreeMemory(device, memory_, nullptr);
        --liveBufferAllocations;
    }
    buffer_ = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
    mapped_ = nullptr;
}

void Buffer::upload(const void* data, VkDeviceSize bytes) {
    if (bytes > size_)
        throw InternalError("upload of " + std::to_string(bytes) + " bytes overflows buffer '" +
                            name_ + "'");
    if (bytes == 0)
        return;
    if (mapped_) {
        std::memcpy(mapped_, data, bytes);
        return;
    }
    Buffer staging(*context_, name_ + " (staging)", bytes, 0, true);
    std::memcpy(staging.mapped_, data, bytes);
    context_->submitAndWait([&](VkCommandBuffer cmd) {
        VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cmd, staging.buffer_, buffer_, 1, &region);
    });
}

void Buffer::download(void* data, VkDeviceSize bytes) const {
    if (bytes > size_)
        throw InternalError("download of " + std::to_string(bytes) +
                            " bytes overflows buffer '" + name_ + "'");
    if (bytes == 0)
        return;
    if (mapped_) {
        std::memcpy(data, mapped_, bytes);
        return;
    }
    Buffer staging(*context_, name_ + " (readback)", bytes, 0, true);
    context_->submitAndWait([&](VkCommandBuffer cmd) {
        VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cmd, buffer_, staging.buffer_, 1, &region);
    });
    std::memcpy(data, staging.mapped_, bytes);
}

} // namespace wf
