// The error estimate every render makes of itself (render/film_error.h, image/error_estimate.h):
// on simulated films of known distributions it matches the squared error the means really
// have, and it says when it cannot be trusted.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "image/error_metrics.h"
#include "render/film_error.h"

namespace wf {
namespace {

// A film of `pixels` pixels, each the mean of `n` samples from `draw` (all channels equal),
// and the relMSE of those means against the true mean `mu`.
template <typename Draw>
std::pair<FilmMoments, double> simulate(uint32_t pixels, uint32_t n, double mu, Draw draw) {
    FilmMoments film;
    film.sum.assign(3 * pixels, 0.0f);
    film.squares.assign(3 * pixels, 0.0f);
    film.count.assign(pixels, float(n));
    film.largest.assign(pixels, 0.0f);
    double measured = 0.0;
    for (uint32_t i = 0; i < pixels; ++i) {
        double sum = 0.0;
        for (uint32_t s = 0; s < n; ++s) {
            const float x = draw();
            sum += x;
            for (int c = 0; c < 3; ++c) {
                film.sum[3 * i + c] += x;
                film.squares[3 * i + c] += x * x;
            }
            film.largest[i] = std::max(film.largest[i], x);
        }
        const double d = sum / n - mu;
        measured += d * d / (mu * mu + kRelMseEpsilon);
    }
    return {film, measured / pixels};
}

TEST(ErrorEstimate, MatchesTheMeasuredErrorOfIndependentSamples) {
    std::mt19937 rng(7);
    for (uint32_t n : {4u, 16u, 256u}) {
        std::exponential_distribution<float> exponential(2.0f); // mean 0.5, sd 0.5
        auto [film, measured] = simulate(4096, n, 0.5, [&] { return exponential(rng); });
        const ErrorEstimate e = estimateFilmError(film, SamplerKind::Independent);
        // From 4 samples, r^2 is estimated from the same few: 15% high (a ratio's bias).
        EXPECT_NEAR(e.relMse / measured, 1.0, n < 16 ? 0.2 : 0.1) << n << " samples";
        // At 4 samples the largest holds most of a pixel's sum of squares: too few to vouch.
        EXPECT_EQ(e.reliable, n >= 16) << n << " samples: " << e.reason;
        EXPECT_FALSE(e.upperBound);
        EXPECT_LT(e.standardError, 0.1 * e.relMse);
    }
}

TEST(ErrorEstimate, CorrelatedSamplersGiveAnUpperBound) {
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    auto [film, measured] = simulate(256, 16, 0.5, [&] { return uniform(rng); });
    EXPECT_TRUE(estimateFilmError(film, SamplerKind::Sobol).upperBound);
    EXPECT_NE(describeErrorEstimate(estimateFilmError(film, SamplerKind::Sobol)).find("<="),
              std::string::npos);
}

// Stratified samples (one per stratum of [0, 1), as a low-discrepancy sequence would place
// them) of f(u) = u: their mean's error is far below independent samples' variance over n.
// With two replicates (each pixel's samples interleaved into two independently stratified
// halves, as --error-replicates 2 makes them), the replicates' spread measures it.
std::pair<FilmMoments, double> stratifiedReplicates(uint32_t pixels, uint32_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    FilmMoments film;
    film.sum.assign(3 * pixels, 0.0f);
    film.squares.assign(3 * pixels, 0.0f);
    film.count.assign(pixels, float(n));
    film.largest.assign(pixels, 0.0f);
    film.replicates = 2;
    film.replicateSums.assign(size_t(pixels) * 4, 0.0f);
    double measured = 0.0;
    for (uint32_t i = 0; i < pixels; ++i) {
        double sum = 0.0;
        for (uint32_t s = 0; s < n; ++s) {
            const uint32_t replicate = s % 2, stratum = s / 2, strata = n / 2;
            const float x = (float(stratum) + uniform(rng)) / float(strata);
            sum += x;
            for (int c = 0; c < 3; ++c) {
                film.sum[3 * i + c] += x;
                film.squares[3 * i + c] += x * x;
                if (replicate == 1)
                    film.replicateSums[4 * i + c] += x;
            }
            if (replicate == 1)
                film.replicateSums[4 * i + 3] += 1.0f;
            film.largest[i] = std::max(film.largest[i], x);
        }
        const double d = sum / n - 0.5;
        measured += d * d / (0.25 + kRelMseEpsilon);
    }
    return {film, measured / pixels};
}

TEST(ErrorEstimate, ReplicatesCalibrateCorrelatedSamples) {
    for (uint32_t n : {16u, 64u}) {
        auto [film, measured] = stratifiedReplicates(4096, n, 12 + n);
        const ErrorEstimate e = estimateFilmError(film, SamplerKind::Sobol);
        EXPECT_FALSE(e.upperBound);
        EXPECT_EQ(e.replicates, 2u);
        EXPECT_TRUE(e.reliable) << e.reason;
        EXPECT_NEAR(e.relMse / measured, 1.0, 0.1) << n << " samples";
        // The variance of independent samples overstates it by about the strata's count.
        FilmMoments plain = film;
        plain.replicates = 1;
        plain.replicateSums.clear();
        const ErrorEstimate bound = estimateFilmError(plain, SamplerKind::Sobol);
        EXPECT_TRUE(bound.upperBound);
        EXPECT_GT(bound.relMse, 4.0 * measured) << n << " samples";
    }
}

TEST(ErrorEstimate, ReplicatesNeedASampleEach) {
    auto [film, measured] = stratifiedReplicates(4, 4, 3);
    film.count[0] = 2.0f; // replicate 1 holds both: replicate 0 none
    film.replicateSums[3] = 2.0f;
    const ErrorEstimate e = estimateFilmError(film, SamplerKind::Sobol);
    EXPECT_EQ(e.pixels, 3u);
    EXPECT_FALSE(e.reliable);
}

TEST(ErrorEstimate, AFewPixelsCarryingItMakeItUnreliable) {
    // Independent samples, all quiet but in 8 of 4,096 pixels: one render's error rests on them.
    std::mt19937 rng(13);
    std::normal_distribution<float> quiet(1.0f, 0.001f), loud(1.0f, 0.5f);
    uint32_t pixel = 0;
    auto [film, measured] = simulate(4096, 64, 1.0, [&]() {
        const bool isLoud = (pixel++ / 64) % 512 == 0;
        return isLoud ? loud(rng) : quiet(rng);
    });
    const ErrorEstimate e = estimateFilmError(film, SamplerKind::Independent);
    EXPECT_LT(e.effectivePixels, 10.0);
    EXPECT_FALSE(e.reliable);
    EXPECT_NE(e.reason.find("pixels carry it"), std::string::npos) << e.reason;
}

TEST(ErrorEstimate, CorrelatedPartsMergeToABound) {
    ErrorEstimate a;
    a.relMse = 0.04, a.standardError = 0.001, a.reliable = true, a.pixels = a.pixelsTotal = 4;
    a.effectivePixels = 100.0;
    a.replicates = 2;
    EXPECT_TRUE(mergeErrorEstimates({a, a}, {64.0, 64.0}, true).upperBound);
    EXPECT_FALSE(mergeErrorEstimates({a, a}, {64.0, 64.0}, false).upperBound);
    EXPECT_FALSE(mergeErrorEstimates({a}, {64.0}, true).upperBound);
}

// Mostly 0.1, and with probability p 1,000: a caustic path found now and then.
std::pair<FilmMoments, double> fireflies(double p, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    return simulate(1024, 64, 0.1 * (1 - p) + 1000 * p,
                    [&] { return uniform(rng) < p ? 1000.0f : 0.1f; });
}

TEST(ErrorEstimate, AFewFirefliesMakeItUnreliable) {
    // About 6 in the 65,536 samples: the variance is known only to within its own size.
    auto [film, measured] = fireflies(1e-4, 9);
    const ErrorEstimate e = estimateFilmError(film, SamplerKind::Independent);
    EXPECT_FALSE(e.reliable);
    EXPECT_NE(e.reason.find("heavy tails"), std::string::npos) << e.reason;
    EXPECT_GT(e.singleSampleShare, 0.5 * e.relMse);
}

TEST(ErrorEstimate, FirefliesInHalfThePixelsAreFlagged) {
    // About 0.64 a pixel: the half that found none look quiet and carry half the error.
    auto [film, measured] = fireflies(1e-2, 10);
    const ErrorEstimate e = estimateFilmError(film, SamplerKind::Independent);
    EXPECT_LT(e.relMse, 0.7 * measured);
    EXPECT_FALSE(e.reliable);
    EXPECT_NE(e.reason.find("one sample holds most"), std::string::npos) << e.reason;
}

TEST(ErrorEstimate, FirefliesInEveryPixelAreEvidenceEnough) {
    // About 13 a pixel: every pixel has seen the tail, and the estimate holds.
    auto [film, measured] = fireflies(2e-1, 11);
    const ErrorEstimate e = estimateFilmError(film, SamplerKind::Independent);
    EXPECT_TRUE(e.reliable) << e.reason;
    EXPECT_NEAR(e.relMse / measured, 1.0, 0.25);
}

TEST(ErrorEstimate, PixelsOfOneSampleHaveNone) {
    FilmMoments film{{1, 1, 1, 2, 2, 2}, {1, 2}, {1, 1, 1, 3, 3, 3}, {1, 2}};
    const ErrorEstimate e = estimateFilmError(film, SamplerKind::Independent);
    EXPECT_EQ(e.pixels, 1u);
    EXPECT_EQ(e.pixelsTotal, 2u);
    EXPECT_FALSE(e.reliable);
    EXPECT_NE(e.reason.find("fewer than 2 samples"), std::string::npos);
}

TEST(ErrorEstimate, PartsMergeAsTheirSampleWeightedMean) {
    ErrorEstimate a, b;
    a.relMse = 0.04, a.standardError = 0.001, a.reliable = true, a.pixels = a.pixelsTotal = 4;
    a.effectivePixels = 100.0;
    b = a;
    b.relMse = 0.02;
    // Equal halves: the mean of two means has a quarter of the sum of their errors.
    const ErrorEstimate merged = mergeErrorEstimates({a, b}, {64.0, 64.0}, false);
    EXPECT_DOUBLE_EQ(merged.relMse, 0.25 * 0.04 + 0.25 * 0.02);
    EXPECT_TRUE(merged.reliable);
    b.reliable = false;
    b.reason = "heavy tails";
    EXPECT_FALSE(mergeErrorEstimates({a, b}, {64.0, 192.0}, false).reliable);
}

} // namespace
} // namespace wf
