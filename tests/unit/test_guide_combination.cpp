// The combination of a guided render's iterations (src/render/guiding/guide_combination.cpp):
// weights that are the iterations' shares of the samples, whatever the images hold, so that
// rare bright samples keep their weight (heavy-tailed images combine to their expectation,
// which inverse-variance weights estimated from the images did not), and the combined film's
// mean and variance of the mean those of the weighted sum.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "render/guiding/guide_combination.h"

namespace {

using wf::FilmMoments;
using wf::guiding::CombinedImage;
using wf::guiding::ImageCombiner;

constexpr uint32_t kPixels = 400;

// A film of `spp` samples per pixel, each sample's rgb from draw().
template <typename Draw>
FilmMoments filmOf(uint32_t spp, Draw draw) {
    FilmMoments m;
    m.sum.assign(kPixels * 3, 0.0f);
    m.squares.assign(kPixels * 3, 0.0f);
    m.count.assign(kPixels, float(spp));
    m.largest.assign(kPixels, 0.0f);
    for (uint32_t p = 0; p < kPixels; ++p)
        for (uint32_t s = 0; s < spp; ++s) {
            const std::array<float, 3> rgb = draw();
            for (int c = 0; c < 3; ++c) {
                m.sum[3 * p + c] += rgb[c];
                m.squares[3 * p + c] += rgb[c] * rgb[c];
                m.largest[p] = std::max(m.largest[p], rgb[c]);
            }
        }
    return m;
}

// A film whose samples are normal around `mean` with standard deviation `sigma`, drawn with
// `rng`, each channel on its own.
FilmMoments film(uint32_t spp, float mean, float sigma, std::mt19937& rng) {
    std::normal_distribution<float> sample(mean, sigma);
    return filmOf(spp, [&]() {
        const float r = sample(rng), g = sample(rng), b = sample(rng);
        return std::array<float, 3>{r, g, b};
    });
}

TEST(GuideCombination, WeighsBySamplesWhateverTheImagesHold) {
    std::mt19937 rng(3);
    ImageCombiner combiner(kPixels);
    combiner.add(film(1, 1.0f, 0.5f, rng), 1);
    combiner.add(film(4, 1.0f, 20.0f, rng), 4); // far noisier: the same weight per sample
    combiner.add(film(16, 1.0f, 1.0f, rng), 16);
    const CombinedImage image = combiner.combine();
    ASSERT_EQ(image.weights.size(), 3u);
    EXPECT_NEAR(image.weights[0], 1.0 / 21.0, 1e-12);
    EXPECT_NEAR(image.weights[1], 4.0 / 21.0, 1e-12);
    EXPECT_NEAR(image.weights[2], 16.0 / 21.0, 1e-12);
    EXPECT_EQ(image.samplesPerPixel, 21u);
    EXPECT_EQ(image.film[3], 21.0f);
}

// Images whose pixels are 0 but for rare bright samples (a caustic's fireflies): over many
// renders the combination's mean is the truth within 5 standard errors. Weights that fall
// where an image caught a bright sample (inverse variance estimated from it) under-count
// them: with those, this fails (about 30% low).
TEST(GuideCombination, RareBrightSamplesKeepTheirWeight) {
    std::mt19937 rng(6);
    std::bernoulli_distribution bright(0.002);
    constexpr double kValue = 50.0, kTruth = kValue * 0.002;
    auto fireflies = [&](uint32_t spp) {
        return filmOf(spp, [&]() {
            const float x = bright(rng) ? float(kValue) : 0.0f;
            return std::array<float, 3>{x, x, x};
        });
    };
    constexpr int kRenders = 400;
    double sum = 0.0, squares = 0.0;
    for (int r = 0; r < kRenders; ++r) {
        ImageCombiner combiner(kPixels);
        combiner.add(fireflies(2), 2);
        combiner.add(fireflies(4), 4);
        combiner.add(fireflies(8), 8);
        const CombinedImage image = combiner.combine();
        double mean = 0.0;
        for (uint32_t p = 0; p < kPixels; ++p)
            mean += image.film[4 * p] / image.film[4 * p + 3];
        mean /= kPixels;
        sum += mean;
        squares += mean * mean;
    }
    const double mean = sum / kRenders;
    const double standardError =
        std::sqrt((squares / kRenders - mean * mean) / (kRenders - 1));
    EXPECT_NEAR(mean, kTruth, 5.0 * standardError);
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
// combination agrees with the truth within 5 standard errors.
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
}

} // namespace
