// GPU time per named pass from timestamp queries. A wave writes one timestamp before each
// dispatch (mark) and one after the last (finish); the interval from a mark to the next
// timestamp is the marked pass's, barrier included. After the wave's fence, collect() sums
// the intervals by pass name. One timestamp per pass rather than two around each: lavapipe
// runs every timestamp as a rasterizer job that wakes its threads, and halving them was worth
// several percent of a frame there. Without perPass only the wave's first mark and finish()
// write one (a single interval named "waves"): each timestamp costs lavapipe about 0.07 ms,
// 4-5 ms of a 64x64 wave of 16 bounces, which renders that read no pass times need not pay.
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
    TimestampTimer(const Context& context, uint32_t maxPasses, bool perPass = true);
    ~TimestampTimer();
    TimestampTimer(const TimestampTimer&) = delete;
    TimestampTimer& operator=(const TimestampTimer&) = delete;

    void reset(VkCommandBuffer cmd); // before the first mark() of a command buffer
    // Ends the running interval, if any, and starts one for `passName` (null: none).
    void mark(VkCommandBuffer cmd, const char* passName);
    void finish(VkCommandBuffer cmd); // ends the running interval
    // Milliseconds per pass name for the intervals recorded since reset().
    std::map<std::string, double> collect();

private:
    VkDevice device_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    uint32_t capacity_; // timestamps
    double nanosecondsPerTick_;
    uint64_t validMask_;
    bool perPass_;
    std::vector<const char*> names_; // per timestamp: the pass it starts, null after finish()
};

} // namespace wf
