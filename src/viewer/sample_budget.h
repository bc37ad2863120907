// How much path tracing a viewer frame does. Each frame renders whole samples per pixel, as
// many as fit the frame-time target by the measured cost of one; when one sample is over the
// target, a still camera gets the part of a sample that fits (render_targets.cpp), and a
// moving one a preview at 1/d of the resolution instead (d = previewDivisor).
#pragma once
#include <cstdint>

namespace wf {

class SampleBudget {
public:
    explicit SampleBudget(double targetSeconds, uint32_t maxSamplesPerFrame = 64);

    void setTarget(double targetSeconds) { targetSeconds_ = targetSeconds; }
    // Samples per pixel for the next frame: at least 1, at most double the last frame's (so a
    // noisy timing cannot overshoot by much) and at most maxSamplesPerFrame.
    uint32_t nextSamples() const;
    // Reports a frame's samples (a fraction for part of one) and the seconds they took.
    void record(double samples, double seconds);
    // Smoothed seconds per sample per pixel; 0 until the first record().
    double secondsPerSample() const { return secondsPerSample_; }

private:
    double targetSeconds_;
    uint32_t maxSamples_;
    uint32_t lastSamples_ = 1;
    double secondsPerSample_ = 0.0;
};

// The smallest divisor d in {1, 2, 4, 8} for which one sample of a (width/d) x (height/d)
// image is expected to fit `targetSeconds`, given the measured seconds per path (0: unknown,
// then 1). 8 when even that is over the target: the preview must stay cheap, not exact.
uint32_t previewDivisor(uint32_t width, uint32_t height, double secondsPerPath,
                        double targetSeconds);

} // namespace wf
