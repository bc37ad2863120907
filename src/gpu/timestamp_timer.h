// GPU time per named pass from timestamp queries. A wave brackets each dispatch with
// begin/end; after the wave's fence, collect() sums the intervals by pass name.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace wf {

class Context;

class TimestampTimer {
public:
    TimestampTimer(const Context& context, uint32_t maxIntervals);
    ~TimestampTimer();
    TimestampTimer(const TimestampTimer&) = delete;
    TimestampTimer& operator=(const TimestampTimer&) = delete;

    void reset(VkCommandBuffer cmd); // before the first begin() of a command buffer
    void begin(VkCommandBuffer cmd, const char* passName);
    void end(VkCommandBuffer cmd);
    // Milliseconds per pass name for the intervals recorded since reset().
    std::map<std::string, double> collect();

private:
    VkDevice device_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    uint32_t capacity_;
    double nanosecondsPerTick_;
    uint64_t validMask_;
    std::vector<const char*> names_;
};

} // namespace wf
