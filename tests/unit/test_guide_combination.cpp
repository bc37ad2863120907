// The inverse-variance combination of a guided render's iterations
// (src/render/guiding/guide_combination.cpp): weights inverse to each image's relative
// variance and summing to one, single-sample images left out, and the combined film's mean and
// variance of the mean those of the weighted sum.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "render/guiding/guide_combination.h"

namespace {

using wf::FilmMoments;
using wf::guiding::CombinedImage;
using wf::guiding::ImageCombiner;

constexpr uint32_t kPixels = 400;

// A film of `spp` samples per pixel, each pixel's samples normal around `mean` with standard
// deviation `sigma`, drawn with `rng`.
FilmMoments film(uint32_t spp, float mean, float sigma, std::mt19937& rng) {
    std::normal_distribution<float> sample(mean, sigma);
    FilmMoments m;
    m.sum.assign(kPixels * 3, 0.0f);
    m.squares.assign(kPixels * 3, 0.0f);
    m.count.assign(kPixels, float(spp));
    m.largest.assign(kPixels, 0.0f);
    for (uint32_t p = 0; p < kPixels; ++p)
        for (uint32_t s = 0; s < spp; ++s)
            for (int c = 0; c < 3; ++c) {
                float x = sample(rng);
                m.sum[3 * p + c] += x;
                m.squares[3 * p + c] += x * x;
                m.largest[p] = std::max(m.largest[p], x);
            }
    return m;
}

TEST(GuideCombination, WeighsByInverseVarianceAndLeavesOutSingleSamples) {
    std::mt19937 rng(3);
    ImageCombiner combiner(kPixels);
    combiner.add(film(1, 1.0f, 0.5f, rng), 1);   // no variance estimate: left out
    combiner.add(film(4, 1.0f, 2.0f, rng), 4);   // variance of the mean 1.0
    combiner.add(film(16, 1.0f, 1.0f, rng), 16); // 1/16: weight 16x the one before
    const CombinedImage image = combiner.combine();
    ASSERT_EQ(image.weights.size(), 3u);
    EXPECT_EQ(image.weights[0], 0.0);
    EXPECT_NEAR(image.weights[1] + image.weights[2], 1.0, 1e-12);
    EXPECT_NEAR(image.weights[2] / image.weights[1], 16.0, 16.0 * 0.25); // estimated variances
    EXPECT_EQ(image.samplesPerPixel, 20u);
    EXPECT_EQ(image.film[3], 20.0f);
}

TEST(GuideCombination, FilmCarriesTheWeightedMeanAndItsVariance) {
    std::mt19937 rng(4);
    ImageCombiner combiner(kPixels);
    FilmMoments a = film(8, 2.0f, 1.0f, rng), b = film(8, 2.0f, 3.0f, rng);
    combiner.add(a, 8);
    combiner.add(b, 8);
    const CombinedImage image = combiner.combine();
    const double wa = image.weights[0], wb = image.weights[1];
    for (uint32_t p = 0; p < kPixels; p += 37) {
        const double n = image.film[4 * p + 3];
        const double ma = a.sum[3 * p] / 8.0, mb = b.sum[3 * p] / 8.0;
        EXPECT_NEAR(image.film[4 * p] / n, wa * ma + wb * mb, 1e-4);
        const double expected = wa * wa * wf::varianceOfMean(a.sum[3 * p], a.squares[3 * p], 8) +
                                wb * wb * wf::varianceOfMean(b.sum[3 * p], b.squares[3 * p], 8);
        EXPECT_NEAR(wf::varianceOfMean(image.film[4 * p], image.moments[4 * p], n), expected,
                    1e-3 * expected + 1e-6);
    }
}

// Images of equal expectation combine to that expectation: the mean over many pixels of the
// combination agrees with the truth within 5 standard errors, and is closer than the noisier
// image's alone.
TEST(GuideCombination, CombinationKeepsTheExpectation) {
    std::mt19937 rng(5);
    ImageCombiner combiner(kPixels);
    combiner.add(film(4, 0.5f, 4.0f, rng), 4);
    combiner.add(film(8, 0.5f, 1.0f, rng), 8);
    combiner.add(film(16, 0.5f, 0.5f, rng), 16);
    const CombinedImage image = combiner.combine();
    double sum = 0.0, variance = 0.0;
    for (uint32_t p = 0; p < kPixels; ++p) {
        const double n = image.film[4 * p + 3];
        sum += image.film[4 * p] / n;
        variance += wf::varianceOfMean(image.film[4 * p], image.moments[4 * p], n);
    }
    const double mean = sum / kPixels, standardError = std::sqrt(variance) / kPixels;
    EXPECT_NEAR(mean, 0.5, 5.0 * standardError);
    EXPECT_LT(standardError, 0.5 / std::sqrt(16.0 * kPixels)); // better than the best alone
}

} // namespace
