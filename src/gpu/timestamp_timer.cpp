#include "gpu/timestamp_timer.h"

#include "errors.h"
#include "gpu/context.h"
#include "gpu/vk_check.h"

namespace wf {

TimestampTimer::TimestampTimer(const Context& context, uint32_t maxIntervals)
    : device_(context.device()), capacity_(maxIntervals),
      nanosecondsPerTick_(context.properties().limits.timestampPeriod) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 2 * maxIntervals;
    VK_CHECK(vkCreateQueryPool(device_, &info, nullptr, &pool_));
    // Timestamps wrap at timestampValidBits; 64 bits on every device we know, but be exact.
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice(), &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice(), &familyCount,
                                             families.data());
    uint32_t bits = families[context.queueFamily()].timestampValidBits;
    validMask_ = bits >= 64 ? ~0ull : ((1ull << bits) - 1);
}

TimestampTimer::~TimestampTimer() { vkDestroyQueryPool(device_, pool_, nullptr); }

void TimestampTimer::reset(VkCommandBuffer cmd) {
    vkCmdResetQueryPool(cmd, pool_, 0, 2 * capacity_);
    names_.clear();
}

void TimestampTimer::begin(VkCommandBuffer cmd, const char* passName) {
    if (names_.size() >= capacity_)
        throw InternalError("timestamp timer full: more than " + std::to_string(capacity_) +
                            " timed passes in one submit");
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool_,
                        2 * static_cast<uint32_t>(names_.size()));
    names_.push_back(passName);
}

void TimestampTimer::end(VkCommandBuffer cmd) {
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_,
                        2 * static_cast<uint32_t>(names_.size()) - 1);
}

std::map<std::string, double> TimestampTimer::collect() {
    std::map<std::string, double> milliseconds;
    if (names_.empty())
        return milliseconds;
    std::vector<uint64_t> ticks(2 * names_.size());
    VK_CHECK(vkGetQueryPoolResults(device_, pool_, 0, static_cast<uint32_t>(ticks.size()),
                                   ticks.size() * sizeof(uint64_t), ticks.data(),
                                   sizeof(uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    for (size_t i = 0; i < names_.size(); ++i) {
        uint64_t elapsed = (ticks[2 * i + 1] - ticks[2 * i]) & validMask_;
        milliseconds[names_[i]] += elapsed * nanosecondsPerTick_ * 1e-6;
    }
    return milliseconds;
}

} // namespace wf
