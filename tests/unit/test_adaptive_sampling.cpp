// The allocation of adaptive sampling (render/adaptive_sampling.h) on synthetic pilot
// statistics: counts follow sqrt(variance), meet the target or the budget with the smallest
// spend, stay within their caps, and the pilot statistics are the converge metric's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "image/error_metrics.h"
#include "render/adaptive_sampling.h"

namespace wf {
namespace {

TEST(AdaptiveSampling, LevelsRiseByAboutAQuarterAndEndAtTheCap) {
    const std::vector<uint32_t> levels = sampleLevels(4, 1024);
    EXPECT_EQ(levels.front(), 4u);
    EXPECT_EQ(levels.back(), 1024u);
    for (size_t i = 1; i < levels.size(); ++i) {
        EXPECT_GT(levels[i], levels[i - 1]);
        if (i + 1 < levels.size())
            EXPECT_LE(levels[i], uint32_t(std::lround(levels[i - 1] * 1.25)) + 1);
    }
    EXPECT_EQ(sampleLevels(8, 8), std::vector<uint32_t>{8});
}

TEST(AdaptiveSampling, BaseTwoLevelsArePowersOfTwo) {
    EXPECT_EQ(sampleLevels(8, 100, true), (std::vector<uint32_t>{8, 16, 32, 64, 100}));
    EXPECT_EQ(sampleLevels(6, 64, true), (std::vector<uint32_t>{6, 8, 16, 32, 64}));
    EXPECT_EQ(sampleLevels(8, 8, true), std::vector<uint32_t>{8});
}

TEST(AdaptiveSampling, RelativeVarianceIsTheConvergeMetricOfOneSample) {
    // One pixel, samples 0 and 2 in every channel: mean 1, sample variance 2.
    FilmMoments moments{{2, 2, 2}, {2}, {4, 4, 4}};
    const std::vector<double> v = relativeSampleVariance(moments);
    ASSERT_EQ(v.size(), 1u);
    EXPECT_NEAR(v[0], 2.0 / (1.0 + kRelMseEpsilon), 1e-12);
    EXPECT_NEAR(relativeErrorOfMean(moments)[0], v[0] / 2.0, 1e-12);
    // A single sample says nothing about the spread.
    EXPECT_EQ(relativeSampleVariance(FilmMoments{{1, 1, 1}, {1}, {1, 1, 1}})[0], 0.0);
}

TEST(AdaptiveSampling, DilationTakesTheNeighbourhoodMaximum) {
    std::vector<double> v(5 * 4, 0.0);
    v[2 * 5 + 2] = 7.0; // x 2, y 2
    const std::vector<double> d = dilate3x3(v, 5, 4);
    for (uint32_t y = 0; y < 4; ++y)
        for (uint32_t x = 0; x < 5; ++x) {
            const bool near = std::abs(int(x) - 2) <= 1 && std::abs(int(y) - 2) <= 1;
            EXPECT_EQ(d[y * 5 + x], near ? 7.0 : 0.0) << x << "," << y;
        }
}

std::vector<double> unevenVariances() {
    // Most pixels quiet, a few a thousand times noisier: a caustic in a diffuse room.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.5, 1.5);
    std::vector<double> v(4096);
    for (size_t i = 0; i < v.size(); ++i)
        v[i] = (i % 64 == 0 ? 1000.0 : 1.0) * u(rng);
    return v;
}

TEST(AdaptiveSampling, MeetsTheTargetWithFewerSamplesThanUniform) {
    const std::vector<double> v = unevenVariances();
    AdaptiveSettings settings;
    settings.targetError = 0.01; // every pixel above the minimum count
    settings.maxSpp = 1u << 16;
    settings.pilotSpp = 16;
    const SampleAllocation a = allocateSamples(v, v, settings);
    EXPECT_TRUE(a.targetMet);
    EXPECT_LE(a.predictedRelMse, settings.targetError);
    // The smallest spend: one level less everywhere would miss the target.
    EXPECT_GT(a.predictedRelMse, 0.5 * settings.targetError);
    // Uniform sampling needs mean(v) / R samples per pixel for the same predicted error.
    const double uniformSpp = meanOf(v) / settings.targetError;
    EXPECT_LT(a.meanSpp, 0.5 * uniformSpp);
    // The noisy pixels get more, in proportion to sqrt(v) up to the level rounding.
    for (size_t i = 0; i < v.size(); ++i)
        for (size_t j : {size_t(1), size_t(63)}) {
            const double ratio = double(a.spp[i]) / a.spp[(i + j) % v.size()];
            const double wanted = std::sqrt(v[i] / v[(i + j) % v.size()]);
            EXPECT_NEAR(std::log(ratio), std::log(wanted), std::log(1.25) + 1e-9) << i;
        }
}

TEST(AdaptiveSampling, SpendsTheBudgetAndKeepsTheCaps) {
    const std::vector<double> v = unevenVariances();
    AdaptiveSettings settings;
    settings.meanSpp = 64.0;
    settings.maxSpp = 512;
    settings.pilotSpp = 16;
    const SampleAllocation a = allocateSamples(v, v, settings);
    EXPECT_LE(a.meanSpp, 64.0);
    EXPECT_GT(a.meanSpp, 64.0 / 1.25);
    for (uint32_t n : a.spp) {
        EXPECT_GE(n, minSppFor(16));
        EXPECT_LE(n, 512u);
        EXPECT_TRUE(std::binary_search(a.levels.begin(), a.levels.end(), n));
    }
    // A target beyond the cap: every pixel at the cap, and it says so.
    settings.meanSpp = 0.0;
    settings.targetError = 1e-9;
    const SampleAllocation capped = allocateSamples(v, v, settings);
    EXPECT_FALSE(capped.targetMet);
    EXPECT_EQ(*std::min_element(capped.spp.begin(), capped.spp.end()), 512u);
}

TEST(AdaptiveSampling, ANoiselessImageGetsTheMinimum) {
    const std::vector<double> zero(100, 0.0);
    AdaptiveSettings settings;
    settings.targetError = 1e-3;
    settings.maxSpp = 256;
    const SampleAllocation a = allocateSamples(zero, zero, settings);
    EXPECT_TRUE(a.targetMet);
    EXPECT_EQ(a.meanSpp, double(minSppFor(pilotSppFor(256))));
}

TEST(AdaptiveSampling, PilotSeedsAreApartFromTheRenderSeeds) {
    for (uint32_t seed = 0; seed < 10000; ++seed) {
        EXPECT_GE(pilotSeedFor(seed), 10000u);
        EXPECT_NE(pilotSeedFor(seed), pilotSeedFor(seed + 1));
    }
}

} // namespace
} // namespace wf
