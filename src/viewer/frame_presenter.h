// Puts one viewer frame on screen:
//   display pass -> display buffer -> copy -> frame image -> overlay render pass -> blit ->
//   swapchain image -> present
// The frame image (RGBA8, window-sized) is the viewer's own: the overlay draws on it, it is
// what a screenshot's PNG reads back, and only its final blit touches the swapchain. A frame is
// one submit, and presentFrame waits for it, so the host may touch the film right after.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/buffer.h"

namespace wf {

class Context;
class Swapchain;

class FramePresenter {
public:
    using Recorder = std::function<void(VkCommandBuffer)>;

    // `framebufferSize` must not be zero (a minimised window waits before coming here).
    FramePresenter(const Context& context, VkExtent2D framebufferSize);
    ~FramePresenter();
    FramePresenter(const FramePresenter&) = delete;
    FramePresenter& operator=(const FramePresenter&) = delete;

    // Recreates the swapchain and everything window-sized; the display buffer is new after it.
    void resize(VkExtent2D framebufferSize);
    VkExtent2D extent() const { return extent_; }
    const Buffer& displayBuffer() const { return displayBuffer_; }
    VkRenderPass overlayRenderPass() const { return renderPass_; }

    // `display` fills the display buffer (one packed RGBA8 per pixel), `overlay` records draws
    // inside the overlay render pass. With keepPixels the frame as shown is read back for
    // shownPixels(). False when the swapchain was out of date: nothing was shown, resize first.
    bool presentFrame(const Recorder& display, const Recorder& overlay, bool keepPixels);
    // RGBA8, top row first, extent() sized: the last frame presented with keepPixels.
    std::vector<uint8_t> shownPixels() const;

private:
    void createFrameImage();
    void destroyFrameImage();
    void recordFrame(VkCommandBuffer cmd, uint32_t imageIndex, const Recorder& display,
                     const Recorder& overlay, bool keepPixels);

    const Context& context_;
    VkDevice device_;
    std::unique_ptr<Swapchain> swapchain_;
    VkExtent2D extent_{};
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory imageMemory_ = VK_NULL_HANDLE;
    VkImageView imageView_ = VK_NULL_HANDLE;
    VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
    Buffer displayBuffer_;
    Buffer readback_;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    VkSemaphore acquired_ = VK_NULL_HANDLE;
};

} // namespace wf
