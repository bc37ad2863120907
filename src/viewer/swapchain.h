// The window's swapchain. The viewer never renders into swapchain images directly: it blits
// its finished frame into one (so the images need only TRANSFER_DST, which every platform
// offers), picks a UNORM format (the frame is sRGB-encoded already) and FIFO presentation
// (always available, no tearing). Recreated whole on resize or when out of date.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

namespace wf {

class Context;

class Swapchain {
public:
    // `wanted` is the framebuffer size, used when the surface leaves the extent to us.
    // `old` (may be null) is handed to the driver for reuse; the caller destroys it after.
    Swapchain(const Context& context, VkExtent2D wanted, VkSwapchainKHR old = VK_NULL_HANDLE);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    VkSwapchainKHR handle() const { return swapchain_; }
    VkExtent2D extent() const { return extent_; }
    VkFormat format() const { return format_; }
    uint32_t imageCount() const { return static_cast<uint32_t>(images_.size()); }
    VkImage image(uint32_t index) const { return images_[index]; }
    // Signalled by the presentation engine's read of image `index`, one per image so that a
    // semaphore is never reused while a present may still wait on it.
    VkSemaphore renderDone(uint32_t index) const { return renderDone_[index]; }

    // The next image, signalling `acquired`; nullopt when the swapchain is out of date.
    std::optional<uint32_t> acquire(VkSemaphore acquired);
    // False when the swapchain is out of date or suboptimal: recreate it before the next frame.
    bool present(uint32_t index);

private:
    const Context& context_;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkExtent2D extent_{};
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    std::vector<VkImage> images_;
    std::vector<VkSemaphore> renderDone_;
};

} // namespace wf
