#include "viewer/swapchain.h"

#include <algorithm>
#include <cstdio>

#include "errors.h"
#include "gpu/context.h"
#include "gpu/vk_check.h"

namespace wf {
namespace {

VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice device, VkSurfaceKHR surface) {
    uint32_t count = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, formats.data()));
    if (formats.empty())
        throw InternalError("the window's surface offers no image format");
    for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM,
                            VK_FORMAT_A8B8G8R8_UNORM_PACK32})
        for (const VkSurfaceFormatKHR& format : formats)
            if (format.format == wanted &&
                format.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
                return format;
    // An sRGB-only surface would encode the already encoded frame a second time.
    std::fprintf(stderr, "wavefront: warning: the window offers no 8-bit UNORM format; colours "
                         "will look too bright\n");
    return formats.front();
}

} // namespace

Swapchain::Swapchain(const Context& context, VkExtent2D wanted, VkSwapchainKHR old)
    : context_(context) {
    VkPhysicalDevice physical = context.physicalDevice();
    VkSurfaceKHR surface = context.surface();
    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface, &caps));
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw InternalError("the window's swapchain images cannot be transfer destinations on " +
                            context.deviceName() + "; the viewer blits its frame into them");
    extent_ = caps.currentExtent;
    if (extent_.width == UINT32_MAX) { // the surface takes the swapchain's size (Wayland)
        extent_.width = std::clamp(wanted.width, caps.minImageExtent.width,
                                   caps.maxImageExtent.width);
        extent_.height = std::clamp(wanted.height, caps.minImageExtent.height,
                                    caps.maxImageExtent.height);
    }
    const VkSurfaceFormatKHR format = chooseFormat(physical, surface);
    format_ = format.format;
    VkFormatProperties formatProps;
    vkGetPhysicalDeviceFormatProperties(physical, format_, &formatProps);
    if (!(formatProps.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT))
        throw InternalError("the window's image format cannot be a blit destination on " +
                            context.deviceName());

    uint32_t imageCount = caps.minImageCount + 1;
    if (caps.maxImageCount > 0)
        imageCount = std::min(imageCount, caps.maxImageCount);
    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface;
    info.minImageCount = imageCount;
    info.imageFormat = format.format;
    info.imageColorSpace = format.colorSpace;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    if (!(caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR))
        info.compositeAlpha = VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;
    info.clipped = VK_TRUE;
    info.oldSwapchain = old;
    VkDevice device = context.device();
    VK_CHECK(vkCreateSwapchainKHR(device, &info, nullptr, &swapchain_));

    uint32_t count = 0;
    VK_CHECK(vkGetSwapchainImagesKHR(device, swapchain_, &count, nullptr));
    images_.resize(count);
    VK_CHECK(vkGetSwapchainImagesKHR(device, swapchain_, &count, images_.data()));
    renderDone_.resize(count, VK_NULL_HANDLE);
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    for (VkSemaphore& semaphore : renderDone_)
        VK_CHECK(vkCreateSemaphore(device, &semaphoreInfo, nullptr, &semaphore));
}

Swapchain::~Swapchain() {
    VkDevice device = context_.device();
    for (VkSemaphore semaphore : renderDone_)
        if (semaphore)
            vkDestroySemaphore(device, semaphore, nullptr);
    if (swapchain_)
        vkDestroySwapchainKHR(device, swapchain_, nullptr);
}

std::optional<uint32_t> Swapchain::acquire(VkSemaphore acquired) {
    uint32_t index = 0;
    VkResult result = vkAcquireNextImageKHR(context_.device(), swapchain_, UINT64_MAX, acquired,
                                            VK_NULL_HANDLE, &index);
    if (result == VK_ERROR_OUT_OF_DATE_KHR)
        return std::nullopt;
    if (result != VK_SUBOPTIMAL_KHR) // suboptimal still acquired and signalled: use it
        VK_CHECK(result);
    return index;
}

bool Swapchain::present(uint32_t index) {
    VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &renderDone_[index];
    info.swapchainCount = 1;
    info.pSwapchains = &swapchain_;
    info.pImageIndices = &index;
    VkResult result = vkQueuePresentKHR(context_.queue(), &info);
    if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR)
        return false;
    VK_CHECK(result);
    return true;
}

} // namespace wf
