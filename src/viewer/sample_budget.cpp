#include "viewer/sample_budget.h"

#include <algorithm>
#include <cmath>

namespace wf {

SampleBudget::SampleBudget(double targetSeconds, uint32_t maxSamplesPerFrame)
    : targetSeconds_(targetSeconds), maxSamples_(std::max(maxSamplesPerFrame, 1u)) {}

uint32_t SampleBudget::nextSamples() const {
    if (secondsPerSample_ <= 0.0)
        return 1;
    const double fit = std::floor(targetSeconds_ / secondsPerSample_);
    const double cap = std::min<double>(maxSamples_, 2.0 * lastSamples_);
    return static_cast<uint32_t>(std::clamp(fit, 1.0, cap));
}

void SampleBudget::record(double samples, double seconds) {
    if (!(samples > 0.0))
        return;
    lastSamples_ = std::max(1u, static_cast<uint32_t>(samples));
    const double perSample = seconds / samples;
    // Smoothing over a few frames: one slow frame (the OS, a resize) must not halve the next.
    secondsPerSample_ =
        secondsPerSample_ > 0.0 ? 0.6 * secondsPerSample_ + 0.4 * perSample : perSample;
}

uint32_t previewDivisor(uint32_t width, uint32_t height, double secondsPerPath,
                        double targetSeconds) {
    if (secondsPerPath <= 0.0)
        return 1;
    for (uint32_t d = 1; d < 8; d *= 2) {
        const double pixels = double(std::max(width / d, 1u)) * std::max(height / d, 1u);
        if (pixels * secondsPerPath <= targetSeconds)
            return d;
    }
    return 8;
}

} // namespace wf
