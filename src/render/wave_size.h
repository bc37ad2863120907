// How many paths a wave traces. At most the path capacity: the device's dispatch limit, the
// guide's training records (guided renders), the render's own paths. The first wave's size is
// a guess (a CPU device traces ~1e5-1e6 paths/s, a GPU far more); later waves follow the
// measured time of full-size waves, aiming at 60% of the submit budget.
#pragma once
#include <cstdint>

#include "render/render_settings.h"

namespace wf {

// The most paths one wave of a render of `pixels` pixels with `settings` holds.
uint32_t wavePathCapacity(const RenderSettings& settings, uint64_t pixels);

class WaveSize {
public:
    WaveSize() = default;
    // `submitBudgetSeconds` 0: every wave at the capacity.
    WaveSize(uint32_t capacity, double submitBudgetSeconds, bool cpuDevice);
    uint32_t paths() const { return paths_; } // the current target
    // A wave of `paths` paths took `seconds`.
    void adapt(uint32_t paths, double seconds);

private:
    uint32_t capacity_ = 1;
    uint32_t paths_ = 1;
    double submitBudgetSeconds_ = 0.0;
    double secondsPerPath_ = 0.0; // measured, for sizing waves to the submit budget
};

} // namespace wf
