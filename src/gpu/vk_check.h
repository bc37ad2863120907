// VK_CHECK names the failing call, its VkResult and where it happened, and throws
// wf::InternalError (exit code 1): no Vulkan result is ever ignored.
#pragma once
#include <string>

#include <vulkan/vulkan.h>

namespace wf {

const char* vkResultName(VkResult result);
[[noreturn]] void throwVkError(const char* call, VkResult result, const char* file, int line);

} // namespace wf

#define VK_CHECK(call)                                                                         \
    do {                                                                                       \
        VkResult wfResult_ = (call);                                                           \
        if (wfResult_ != VK_SUCCESS)                                                           \
            ::wf::throwVkError(#call, wfResult_, __FILE__, __LINE__);                          \
    } while (0)
