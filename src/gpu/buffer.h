// A storage buffer with its own memory allocation (a wavefront tracer owns a dozen or two large
// buffers, so one allocation each is fine), move-only. Uploads and readbacks go through a
// host-visible staging buffer unless the memory is host visible already (lavapipe).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace wf {

class Context;

class Buffer {
public:
    Buffer() = default;
    // `name` is used in error messages and memory reports. Size 0 is rounded up to 16 bytes
    // so that an empty table still binds.
    Buffer(const Context& context, std::string name, VkDeviceSize size,
           VkBufferUsageFlags extraUsage = 0, bool hostVisible = false);
    ~Buffer();
    Buffer(Buffer&& other) noexcept;
    Buffer& operator=(Buffer&& other) noexcept;
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    VkBuffer handle() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    const std::string& name() const { return name_; }
    // Needs VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT and a context with ray tracing enabled.
    VkDeviceAddress address() const;
    explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }

    // The caller makes sure no submitted work still uses the buffer.
    void upload(const void* data, VkDeviceSize bytes);
    void download(void* data, VkDeviceSize bytes) const;

    template <typename T> void upload(const std::vector<T>& values) {
        upload(values.data(), values.size() * sizeof(T));
    }
    // Buffers whose device memory is allocated now, in the whole process: what a leak check
    // (the Python module's memory test) compares before and after.
    static size_t liveAllocations();

    template <typename T> std::vector<T> download() const {
        std::vector<T> values(size_ / sizeof(T));
        download(values.data(), values.size() * sizeof(T));
        return values;
    }

private:
    void release();

    const Context* context_ = nullptr;
    std::string name_;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize size_ = 0;
    void* mapped_ = nullptr; // non-null when the memory is host visible and coherent
};

} // namespace wf
