// The viewer's frame pacing on the CPU: the samples per frame converge to what fits the
// target, never drop below one, grow at most twofold per frame; the preview divisor is the
// smallest that fits.
#include <gtest/gtest.h>

#include "viewer/sample_budget.h"

namespace wf {
namespace {

TEST(SampleBudget, StartsAtOneAndConvergesToTheTarget) {
    SampleBudget budget(0.040);
    EXPECT_EQ(budget.nextSamples(), 1u);
    uint32_t samples = 1;
    for (int frame = 0; frame < 20; ++frame) {
        budget.record(samples, samples * 0.004); // 4 ms per sample
        const uint32_t next = budget.nextSamples();
        EXPECT_LE(next, 2 * samples);
        samples = next;
    }
    EXPECT_EQ(samples, 10u);
}

TEST(SampleBudget, AlwaysAtLeastOneSample) {
    SampleBudget budget(0.010);
    budget.record(1, 0.9); // one sample takes 90 times the target (lavapipe, 800x600)
    EXPECT_EQ(budget.nextSamples(), 1u);
}

TEST(SampleBudget, CappedPerFrame) {
    SampleBudget budget(10.0, 16);
    for (int frame = 0; frame < 10; ++frame)
        budget.record(budget.nextSamples(), 1e-6);
    EXPECT_EQ(budget.nextSamples(), 16u);
}

TEST(PreviewDivisor, SmallestThatFits) {
    // 800x600 at 2 microseconds per path: 0.96 s for a full sample.
    EXPECT_EQ(previewDivisor(800, 600, 2e-6, 2.0), 1u);
    EXPECT_EQ(previewDivisor(800, 600, 2e-6, 0.3), 2u);
    EXPECT_EQ(previewDivisor(800, 600, 2e-6, 0.033), 8u);
    EXPECT_EQ(previewDivisor(800, 600, 2e-6, 0.001), 8u); // never coarser than 1/8
    EXPECT_EQ(previewDivisor(800, 600, 0.0, 0.001), 1u);  // nothing measured yet
}

} // namespace
} // namespace wf
