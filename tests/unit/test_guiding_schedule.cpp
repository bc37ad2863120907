// The guide's schedule (src/render/guiding/guiding_schedule.cpp): iterations of 1, 2, 4, ...
// spp leave the image at least half of the budget and of a time limit, the image phase fits
// the limit, and --guiding auto's rule.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <vector>

#include "errors.h"
#include "render/guiding/guiding_schedule.h"

namespace {

using wf::guiding::decideGuiding;
using wf::guiding::GuideSceneTraits;
using wf::guiding::GuideSchedule;
using wf::guiding::GuidingMode;

constexpr uint32_t kNoMax = 0xffffffffu;

struct ScheduleRun {
    std::vector<uint32_t> training; // spp of each training iteration
    std::vector<uint32_t> image;    // spp of each image pass
    double trainingSeconds = 0.0, seconds = 0.0;
    uint32_t done = 0;
    bool stoppedUnused = false;
};

// A renderer whose passes cost secondsPerSpp each sample (training ones trainCost), that
// takes the schedule's every answer whole, as renderGuided's advance() may take fewer.
// guideSampled(k): whether the guide built by iteration k is sampled (some leaf's share < 1);
// pixels: the image's (64x64 unless given).
ScheduleRun simulate(uint32_t budget, double limit, double trainCost, double imageCost,
                     uint32_t maxIterations = kNoMax,
                     const std::function<bool(size_t)>& guideSampled = nullptr,
                     uint32_t pixels = 64 * 64) {
    GuideSchedule schedule(budget, limit, maxIterations);
    ScheduleRun run;
    while (const uint32_t spp = schedule.nextTrainingSpp(run.done, run.seconds)) {
        schedule.endIteration(!guideSampled || guideSampled(run.training.size()),
                              uint64_t(pixels) * spp);
        run.training.push_back(spp);
        run.done += spp;
        run.seconds += spp * trainCost;
    }
    run.stoppedUnused = schedule.stoppedUnused();
    run.trainingSeconds = run.seconds;
    while (const uint32_t spp = schedule.nextImageSpp(run.done, run.seconds)) {
        // One wave of at most 4 spp, as advance() takes at most what a wave holds.
        const uint32_t taken = std::min(spp, 4u);
        run.image.push_back(taken);
        run.done += taken;
        run.seconds += taken * imageCost;
        if (run.image.size() > 100000)
            break;
    }
    return run;
}

uint32_t sum(const std::vector<uint32_t>& v) {
    uint32_t s = 0;
    for (uint32_t x : v)
        s += x;
    return s;
}

TEST(GuidingSchedule, DoublingIterationsKeepHalfOfTheBudget) {
    for (uint32_t budget = 1; budget <= 5000; ++budget) {
        const ScheduleRun run = simulate(budget, 0.0, 1.0, 1.0);
        const uint32_t trained = sum(run.training);
        for (size_t k = 0; k < run.training.size(); ++k)
            ASSERT_EQ(run.training[k], 1u << k) << budget;
        ASSERT_LE(2 * trained, budget) << budget;
        // Training stops only when the next doubling would take the image below half.
        ASSERT_GT(2ull * (trained + (1u << run.training.size())), budget) << budget;
        ASSERT_EQ(run.done, budget) << budget;
        ASSERT_GE(sum(run.image), 1u);
    }
    EXPECT_EQ(simulate(64, 0.0, 1.0, 1.0).training, (std::vector<uint32_t>{1, 2, 4, 8, 16}));
    EXPECT_TRUE(simulate(1, 0.0, 1.0, 1.0).training.empty());
}

TEST(GuidingSchedule, MaxIterationsCapsTraining) {
    EXPECT_TRUE(simulate(1024, 0.0, 1.0, 1.0, 0).training.empty());
    EXPECT_EQ(simulate(1024, 0.0, 1.0, 1.0, 3).training, (std::vector<uint32_t>{1, 2, 4}));
    EXPECT_EQ(simulate(1024, 0.0, 1.0, 1.0, 0).done, 1024u);
}

TEST(GuidingSchedule, TrainingStopsWhereTheLearntSharesLeaveTheGuideUnused) {
    const auto never = [](size_t) { return false; };
    // Unused after every iteration: at 64x64 iterations 1 and 2 (7 spp of 4096 pixels) are
    // the first pair that may stop it.
    ScheduleRun run = simulate(1024, 0.0, 1.0, 1.0, kNoMax, never);
    EXPECT_EQ(run.training, (std::vector<uint32_t>{1, 2, 4}));
    EXPECT_TRUE(run.stoppedUnused);
    EXPECT_EQ(run.done, 1024u); // the image takes the rest
    // A smaller image needs more samples per pixel first: at 32x32, 31 spp (iteration 4).
    run = simulate(1024, 0.0, 1.0, 1.0, kNoMax, never, 32 * 32);
    EXPECT_EQ(run.training, (std::vector<uint32_t>{1, 2, 4, 8, 16}));
    EXPECT_TRUE(run.stoppedUnused);
    // A larger one no sooner than iteration 2: the first two never learn a share that pays.
    run = simulate(1024, 0.0, 1.0, 1.0, kNoMax, never, 1024 * 1024);
    EXPECT_EQ(run.training, (std::vector<uint32_t>{1, 2, 4}));
    EXPECT_TRUE(run.stoppedUnused);
    // Sampled from iteration 2 on (the narrow gap): the whole schedule.
    run = simulate(1024, 0.0, 1.0, 1.0, kNoMax, [](size_t k) { return k >= 2; });
    EXPECT_EQ(run.training, (std::vector<uint32_t>{1, 2, 4, 8, 16, 32, 64, 128, 256}));
    EXPECT_FALSE(run.stoppedUnused);
    // One iteration alone unused is not enough; two in a row are.
    run = simulate(1024, 0.0, 1.0, 1.0, kNoMax, [](size_t k) { return k == 2 || k == 4; });
    EXPECT_EQ(run.training, (std::vector<uint32_t>{1, 2, 4, 8, 16, 32, 64}));
    EXPECT_TRUE(run.stoppedUnused);
    // A budget that ends training first: not stopped by the rule.
    run = simulate(8, 0.0, 1.0, 1.0, kNoMax, never);
    EXPECT_EQ(run.training, (std::vector<uint32_t>{1, 2}));
    EXPECT_FALSE(run.stoppedUnused);
}

TEST(GuidingSchedule, TrainingFitsHalfOfTheTimeLimit) {
    // A budget too large to bind: the limit decides. Training costs 2.5x an image sample.
    for (double limit : {10.0, 37.0, 100.0, 1000.0, 12345.0}) {
        const ScheduleRun run = simulate(1u << 30, limit, 2.5, 1.0);
        ASSERT_FALSE(run.training.empty());
        if (run.training.size() > 1)
            EXPECT_LE(run.trainingSeconds, 0.5 * limit) << limit;
        // Not stopped early: the next doubling would have passed half the limit.
        EXPECT_GT(run.trainingSeconds + 2.5 * (1u << run.training.size()), 0.5 * limit) << limit;
        // The image phase stops within the limit (paces are constant here) and has samples.
        EXPECT_LE(run.seconds, limit + 1e-9) << limit;
        EXPECT_GT(run.seconds, limit - 4.0 * 1.0 - 1e-9) << limit; // within a wave of the end
        EXPECT_GE(sum(run.image), 1u);
    }
}

TEST(GuidingSchedule, ALimitShorterThanOneIterationStillTrainsOnceAndRendersOnce) {
    const ScheduleRun run = simulate(1024, 0.5, 1.0, 1.0);
    EXPECT_EQ(run.training, (std::vector<uint32_t>{1}));
    EXPECT_EQ(run.image, (std::vector<uint32_t>{1}));
}

TEST(GuidingSchedule, TheSppBudgetStillBindsUnderALimit) {
    const ScheduleRun run = simulate(64, 1e9, 1.0, 1.0);
    EXPECT_EQ(run.training, (std::vector<uint32_t>{1, 2, 4, 8, 16}));
    EXPECT_EQ(run.done, 64u);
}

TEST(GuidingSchedule, ProgressiveIterationsDouble) {
    EXPECT_EQ(wf::guiding::progressiveTrainingEnd(0, 5), 1u);
    EXPECT_EQ(wf::guiding::progressiveTrainingEnd(4, 5), 16u);
    EXPECT_EQ(wf::guiding::progressiveTrainingEnd(5, 5), 0u);
    EXPECT_EQ(wf::guiding::progressiveTrainingEnd(0, 0), 0u);
}

TEST(GuidingMode, ParsesThreeWords) {
    EXPECT_EQ(wf::guiding::parseGuidingMode("off"), GuidingMode::Off);
    EXPECT_EQ(wf::guiding::parseGuidingMode("on"), GuidingMode::On);
    EXPECT_EQ(wf::guiding::parseGuidingMode("auto"), GuidingMode::Auto);
    EXPECT_THROW(wf::guiding::parseGuidingMode("yes"), wf::UsageError);
}

TEST(GuidingAuto, AskedModesAreKept) {
    const GuideSceneTraits none{};
    EXPECT_TRUE(decideGuiding(GuidingMode::On, none, 64).on);
    EXPECT_FALSE(decideGuiding(GuidingMode::Off, {true, true, true}, 64).on);
}

TEST(GuidingAuto, NothingToGuideStaysOff) {
    // All-delta scenes (the guide never samples) and scenes where nothing emits.
    EXPECT_FALSE(decideGuiding(GuidingMode::Auto, {false, true, true}, 4096).on);
    EXPECT_EQ(decideGuiding(GuidingMode::Auto, {false, true, true}, 4096).predictedGain, 0.0);
    EXPECT_FALSE(decideGuiding(GuidingMode::Auto, {true, true, false}, 4096).on);
    EXPECT_FALSE(decideGuiding(GuidingMode::Auto, {true, true, true}, 2).on);
}

TEST(GuidingAuto, MeasuredGainsKeepEveryGalleryKindOff) {
    // The least equal-time gains measured (docs/guiding.md, "auto") are losses on caustic
    // scenes and on diffuse ones: auto must not turn on where guiding was measured to lose.
    for (uint32_t spp = 4; spp <= 70000; spp += spp < 5000 ? 1 : 997) {
        const auto caustic = decideGuiding(GuidingMode::Auto, {true, true, true}, spp);
        const auto diffuse = decideGuiding(GuidingMode::Auto, {true, false, true}, spp);
        ASSERT_FALSE(caustic.on) << spp;
        ASSERT_FALSE(diffuse.on) << spp;
        ASSERT_GT(caustic.predictedGain, 0.0) << spp;
        ASSERT_LT(caustic.predictedGain, 1.0) << spp;
        ASSERT_LT(diffuse.predictedGain, 1.0) << spp;
        ASSERT_NE(caustic.reason.find("auto: off (predicted efficiency"), std::string::npos);
        ASSERT_NE(diffuse.reason.find("diffuse/glossy"), std::string::npos) << spp;
    }
}

} // namespace
