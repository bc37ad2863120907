#include "gpu/vk_check.h"

#include <cstring>

#include "errors.h"

namespace wf {

// vulkan/vk_enum_string_helper.h is not packaged in Debian 12, hence this list.
const char* vkResultName(VkResult result) {
    switch (result) {
#define WF_CASE(name) case name: return #name;
        WF_CASE(VK_SUCCESS)
        WF_CASE(VK_NOT_READY)
        WF_CASE(VK_TIMEOUT)
        WF_CASE(VK_EVENT_SET)
        WF_CASE(VK_EVENT_RESET)
        WF_CASE(VK_INCOMPLETE)
        WF_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
        WF_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        WF_CASE(VK_ERROR_INITIALIZATION_FAILED)
        WF_CASE(VK_ERROR_DEVICE_LOST)
        WF_CASE(VK_ERROR_MEMORY_MAP_FAILED)
        WF_CASE(VK_ERROR_LAYER_NOT_PRESENT)
        WF_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
        WF_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        WF_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
        WF_CASE(VK_ERROR_TOO_MANY_OBJECTS)
        WF_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
        WF_CASE(VK_ERROR_FRAGMENTED_POOL)
        WF_CASE(VK_ERROR_UNKNOWN)
        WF_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
        WF_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
        WF_CASE(VK_ERROR_FRAGMENTATION)
        WF_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
        WF_CASE(VK_PIPELINE_COMPILE_REQUIRED)
        WF_CASE(VK_ERROR_SURFACE_LOST_KHR)
        WF_CASE(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
        WF_CASE(VK_SUBOPTIMAL_KHR)
        WF_CASE(VK_ERROR_OUT_OF_DATE_KHR)
        WF_CASE(VK_ERROR_VALIDATION_FAILED_EXT)
#undef WF_CASE
    default:
        return "VK_RESULT_UNKNOWN";
    }
}

void throwVkError(const char* call, VkResult result, const char* file, int line) {
    // Keep only the call's name, not its argument list, so the message stays one short line.
    std::string name(call);
    if (auto paren = name.find('('); paren != std::string::npos)
        name.resize(paren);
    const char* base = std::strrchr(file, '/');
    throw InternalError(name + " failed: " + vkResultName(result) + " at " +
                        (base ? base + 1 : file) + ":" + std::to_string(line));
}

} // namespace wf
