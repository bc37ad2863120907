#include "gpu/timestamp_timer.h"

#include "errors.h"
#include "gpu/context.h"
#include "gpu/vk_check.h"

namespace wf {

TimestampTimer::TimestampTimer(const Context& context, uint32_t maxPasses, bool perPass)
    : device_(context.device()), capacity_(maxPasses + 1),
      nanosecondsPerTick_(context.properties().limits.timestampPeriod), perPass_(perPass) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = capacity_;
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
    vkCmdResetQueryPool(cmd, pool_, 0, capacity_);
    names_.clear();
}

// Bottom of pipe: written once every earlier command has finished, so a mark ends the pass
// before it on any device.
void TimestampTimer::mark(VkCommandBuffer cmd, const char* passName) {
    if (!perPass_ && passName != nullptr) {
        if (!names_.empty())
            return; // one interval from the first mark to finish()
        passName = "waves";
    }
    if (names_.size() >= capacity_)
        throw InternalError("timestamp timer full: more than " + std::to_string(capacity_ - 1) +
                            " timed passes in one submit");
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_,
                        static_cast<uint32_t>(names_.size()));
    names_.push_back(passName);
}

void TimestampTimer::finish(VkCommandBuffer cmd) {
    if (!names_.empty() && names_.back() != nullptr)
        mark(cmd, nullptr); // a timestamp that starts no pass
}

std::map<std::string, double> TimestampTimer::collect() {
    std::map<std::string, double> milliseconds;
    if (names_.size() < 2)
        return milliseconds;
    std::vector<uint64_t> ticks(names_.size());
    VK_CHECK(vkGetQueryPoolResults(device_, pool_, 0, static_cast<uint32_t>(ticks.size()),
                                   ticks.size() * sizeof(uint64_t), ticks.data(),
                                   sizeof(uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    for (size_t i = 0; i + 1 < names_.size(); ++i) {
        if (names_[i] == nullptr)
            continue;
        uint64_t elapsed = (ticks[i + 1] - ticks[i]) & validMask_;
        milliseconds[names_[i]] += elapsed * nanosecondsPerTick_ * 1e-6;
    }
    return milliseconds;
}

} // namespace wf
