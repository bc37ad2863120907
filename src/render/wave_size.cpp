#include "render/wave_size.h"

#include <algorithm>

#include "passes/workgroup.h"

namespace wf {

uint32_t wavePathCapacity(const RenderSettings& settings, uint64_t pixels) {
    const uint64_t maxPaths = uint64_t(kMaxGroupsX) * kWorkgroupSize;
    // Guided renders keep 4 training records of 64 bytes per path: at most 2^19 paths keep
    // them within a 128 MiB storage buffer.
    const uint64_t guideMaxPaths = settings.guiding ? uint64_t(1) << 19 : maxPaths;
    return static_cast<uint32_t>(std::max<uint64_t>(
        1, std::min({uint64_t(settings.maxPathsPerWave), maxPaths, guideMaxPaths,
                     pixels * settings.samplesPerPixel})));
}

WaveSize::WaveSize(uint32_t capacity, double submitBudgetSeconds, bool cpuDevice)
    : capacity_(capacity),
      paths_(submitBudgetSeconds > 0.0 && cpuDevice ? std::min(capacity, 1u << 12) : capacity),
      submitBudgetSeconds_(submitBudgetSeconds) {}

void WaveSize::adapt(uint32_t paths, double seconds) {
    // Only full-size waves say how long a full-size wave takes: the image's last pixel range
    // may be tiny, and fixed costs would dominate it.
    if (submitBudgetSeconds_ <= 0.0 || 2ull * paths < paths_ || seconds <= 0.0)
        return;
    // The cost per path follows a slowdown at once and a speed-up slowly, as waves over other
    // pixels (or a busier machine) may cost more; waves aim at 60% of the budget and grow at
    // most 4x at a time.
    secondsPerPath_ = std::max(seconds / paths, 0.75 * secondsPerPath_);
    const double wanted = 0.6 * submitBudgetSeconds_ / secondsPerPath_;
    const double grown = std::min(wanted, 4.0 * paths_);
    const uint32_t floor = std::min(capacity_, 1024u);
    paths_ = static_cast<uint32_t>(std::clamp(grown, double(floor), double(capacity_)));
}

} // namespace wf
