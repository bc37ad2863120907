// Statistics of every sampler on the sample dimensions the renderer reads: uniformity and
// discrepancy of the first dimensions, no correlation between dimensions meant to be
// independent, unbiased estimates over seeds, lower error than independent sampling on a smooth
// low-dimensional integrand, and blue-noise error across pixels for `bluenoise`.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>
#include <vector>

#include "chi_square.h"
#include "sampler_test_util.h"

namespace wf::test {
namespace {

using namespace gpu_types;

const uint32_t kBsdf0 = bounceDimension(0, WF_DIM_BSDF);

double meanOf(const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

// Mean squared L2-star discrepancy of the 2D pattern at `dim` over 16 pixels, relative to the
// expectation for independent points (1 = as uniform as random, lower = more uniform).
double relativeDiscrepancy(SamplerKind kind, uint32_t dim, uint32_t n) {
    double sum = 0.0;
    for (uint32_t pixel = 0; pixel < 16; ++pixel) {
        SampleSite site{pixel % 4, pixel / 4, 64, 5, n, true};
        std::vector<glm::vec2> points;
        for (uint32_t i = 0; i < n; ++i)
            points.push_back(samplePoint2D(kind, site, i, dim));
        sum += l2StarDiscrepancySquared(points);
    }
    return sum / 16.0 / randomL2StarDiscrepancySquared(n);
}

// The figures docs/samplers.md quotes; QMC and stratified patterns are far more uniform than random
// points in the pixel pair and in the first BSDF pair.
TEST(SamplerStatistics, DiscrepancyOfTheFirstDimensions) {
    std::printf("squared L2-star discrepancy / that of random points (16 pixels):\n");
    std::printf("%-12s %9s %9s %9s %9s\n", "sampler", "pixel 16", "pixel 64", "pixel 256",
                "bsdf 64");
    for (SamplerKind kind : allSamplers()) {
        double d16 = relativeDiscrepancy(kind, WF_DIM_PIXEL, 16);
        double d64 = relativeDiscrepancy(kind, WF_DIM_PIXEL, 64);
        double d256 = relativeDiscrepancy(kind, WF_DIM_PIXEL, 256);
        double b64 = relativeDiscrepancy(kind, kBsdf0, 64);
        std::printf("%-12s %9.3f %9.3f %9.3f %9.3f\n", samplerName(kind), d16, d64, d256, b64);
        if (kind == SamplerKind::Independent) {
            EXPECT_NEAR(d64, 1.0, 0.45);
            EXPECT_NEAR(b64, 1.0, 0.45);
        } else {
            EXPECT_LT(d64, 0.3) << samplerName(kind);
            EXPECT_LT(b64, 0.3) << samplerName(kind);
            EXPECT_LT(d256, d16) << samplerName(kind) << ": more samples, relatively better";
        }
    }
}

// Each dimension on its own is uniform: chi-square over 32 bins of 2048 independent draws
// (each from its own seed, so that the strong dependence between the samples of one pixel, the
// point of these patterns, does not void the test).
TEST(SamplerStatistics, EveryDimensionIsUniform) {
    for (SamplerKind kind : allSamplers()) {
        for (uint32_t dim : {0u, 1u, 2u, 3u, 4u, 5u, 6u, 7u, 8u, 9u, 17u, 42u, 129u}) {
            std::vector<double> counts(32, 0.0);
            const uint32_t draws = 2048;
            for (uint32_t d = 0; d < draws; ++d) {
                SampleSite site{d % 8, (d / 8) % 8, 64, 1000 + d, 12, true};
                ++counts[uint32_t(sampleCoordinate(kind, site, d % 12, dim) * 32.0f)];
            }
            std::vector<double> expected(32, draws / 32.0);
            EXPECT_GT(chiSquarePValue(counts, expected), 1e-4)
                << samplerName(kind) << " dimension " << dim;
        }
    }
}

// Pearson correlation between pairs of dimensions that the renderer treats as independent,
// over 256 pixels x 64 samples: a shared shuffle or a reused key would show up here.
TEST(SamplerStatistics, IndependentDimensionsAreUncorrelated) {
    const uint32_t pairs[][2] = {{0, 2},  {0, 5},   {1, 6},   {2, 3},  {3, 5},   {5, 13},
                                 {6, 14}, {7, 15},  {4, 12},  {0, 10}, {9, 17},  {5, 8},
                                 {2, 10}, {13, 21}, {11, 29}, {0, 1},  {5, 6},   {3, 4}};
    const uint32_t pixels = 256, n = 64;
    const double limit = 5.0 / std::sqrt(double(pixels * n));
    for (SamplerKind kind : allSamplers()) {
        for (const auto& pair : pairs) {
            double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0, count = 0;
            for (uint32_t pixel = 0; pixel < pixels; ++pixel) {
                SampleSite site{pixel % 16, pixel / 16, 64, 7, n, true};
                for (uint32_t i = 0; i < n; ++i, ++count) {
                    double a = sampleCoordinate(kind, site, i, pair[0]);
                    double b = sampleCoordinate(kind, site, i, pair[1]);
                    sa += a, sb += b, saa += a * a, sbb += b * b, sab += a * b;
                }
            }
            double cov = sab / count - sa * sb / (count * count);
            double r = cov / std::sqrt((saa / count - sa * sa / (count * count)) *
                                       (sbb / count - sb * sb / (count * count)));
            EXPECT_LT(std::abs(r), limit) << samplerName(kind) << " dimensions " << pair[0]
                                          << " and " << pair[1] << ": r = " << r;
        }
    }
}

// A known integral over the pixel pair, the light choice, the first BSDF pair, the first
// roulette dimension and the second bounce's BSDF pair: a disk indicator (discontinuous), a
// quadratic, and smooth factors. Integral: pi/4 * 1 * 1 * 1 * (e - 1).
double testIntegrand(SamplerKind kind, const SampleSite& site, uint32_t i) {
    glm::vec2 pixel = samplePoint2D(kind, site, i, WF_DIM_PIXEL);
    float choice = samplePoint1D(kind, site, i, bounceDimension(0, WF_DIM_LIGHT_CHOICE));
    glm::vec2 bsdf = samplePoint2D(kind, site, i, kBsdf0);
    float roulette = samplePoint1D(kind, site, i, bounceDimension(0, WF_DIM_ROULETTE));
    glm::vec2 next = samplePoint2D(kind, site, i, bounceDimension(1, WF_DIM_BSDF));
    double disk = pixel.x * pixel.x + pixel.y * pixel.y < 1.0f ? 1.0 : 0.0;
    return disk * 3.0 * choice * choice * (1.0 + std::sin(2.0 * M_PI * bsdf.x) * bsdf.y) *
           2.0 * roulette * std::exp(double(next.x)) * (2.0 * next.y);
}

const double kTestIntegral = M_PI / 4.0 * (std::exp(1.0) - 1.0);

// Randomized samplers are unbiased: the mean over 200 seeds of the estimate (16 pixels each)
// agrees with the integral within 4 standard errors. Sets of 10 (a partial 4 x 3 grid) and
// 24 samples of sets of 12 (a repetition) check the finite sets' corner cases.
TEST(SamplerStatistics, RandomizedSamplersAreUnbiased) {
    for (SamplerKind kind : allSamplers()) {
        for (uint32_t setSize : {16u, 10u, 12u}) {
            const uint32_t n = setSize == 12 ? 24 : setSize;
            std::vector<double> perSeed;
            for (uint32_t seed = 0; seed < 200; ++seed) {
                double sum = 0.0;
                for (uint32_t pixel = 0; pixel < 16; ++pixel) {
                    SampleSite site{pixel % 4, pixel / 4, 64, seed * 7919u + 1, setSize, true};
                    for (uint32_t i = 0; i < n; ++i)
                        sum += testIntegrand(kind, site, i);
                }
                perSeed.push_back(sum / (16.0 * n));
            }
            double mean = meanOf(perSeed), variance = 0.0;
            for (double v : perSeed)
                variance += (v - mean) * (v - mean) / double(perSeed.size() - 1);
            double standardError = std::sqrt(variance / double(perSeed.size()));
            EXPECT_NEAR(mean, kTestIntegral, 4.0 * standardError + 1e-6)
                << samplerName(kind) << " set " << setSize;
        }
    }
}

// On a smooth integrand of the pixel pair the QMC and stratified patterns beat independent
// sampling by far at 64 samples (RMSE over 64 seeds x 4 pixels).
TEST(SamplerStatistics, QmcBeatsIndependentOnASmoothLowDimensionalIntegrand) {
    auto rmse = [](SamplerKind kind) {
        double squares = 0.0, count = 0.0;
        const double exact = (std::exp(1.0) - 1.0) * (1.0 - std::cos(1.0));
        for (uint32_t seed = 0; seed < 64; ++seed) {
            for (uint32_t pixel = 0; pixel < 4; ++pixel, ++count) {
                SampleSite site{pixel, 0, 64, seed, 64, true};
                double sum = 0.0;
                for (uint32_t i = 0; i < 64; ++i) {
                    glm::vec2 p = samplePoint2D(kind, site, i, WF_DIM_PIXEL);
                    sum += std::exp(double(p.x)) * std::sin(double(p.y));
                }
                squares += (sum / 64.0 - exact) * (sum / 64.0 - exact);
            }
        }
        return std::sqrt(squares / count);
    };
    const double independent = rmse(SamplerKind::Independent);
    for (SamplerKind kind : allSamplers()) {
        const double ratio = rmse(kind) / independent;
        std::printf("%-12s RMSE / independent's at 64 spp: %.4f\n", samplerName(kind), ratio);
        if (kind != SamplerKind::Independent)
            EXPECT_LT(ratio, 0.25) << samplerName(kind);
    }
}

// Fraction of an image's energy (mean removed) at spatial frequencies below 1/8 of the
// Nyquist band: about 1/64 for white noise, far less for blue noise.
double lowFrequencyFraction(const std::vector<double>& image, int size) {
    const double mean = meanOf(image);
    double total = 0.0, low = 0.0;
    for (double v : image)
        total += (v - mean) * (v - mean) * image.size();
    const int band = size / 16;
    for (int fy = -band; fy < band; ++fy) {
        for (int fx = -band; fx < band; ++fx) {
            double re = 0.0, im = 0.0;
            for (int y = 0; y < size; ++y) {
                for (int x = 0; x < size; ++x) {
                    double phase = 2.0 * M_PI * double(fx * x + fy * y) / size;
                    re += (image[y * size + x] - mean) * std::cos(phase);
                    im -= (image[y * size + x] - mean) * std::sin(phase);
                }
            }
            low += re * re + im * im;
        }
    }
    return low / total;
}

// `bluenoise` spreads the error of a 1-sample estimate as blue noise over the screen: little
// energy at low frequencies, where independent samples put their share.
TEST(SamplerStatistics, BlueNoiseErrorHasNoLowFrequencies) {
    const int size = 64;
    auto lowFraction = [&](SamplerKind kind, uint32_t samples) {
        std::vector<double> error(size * size);
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) {
                SampleSite site{uint32_t(x), uint32_t(y), uint32_t(size), 4, samples, true};
                double sum = 0.0;
                for (uint32_t i = 0; i < samples; ++i) {
                    glm::vec2 p = samplePoint2D(kind, site, i, kBsdf0);
                    sum += p.x * p.x + (p.y < 0.4f ? 1.0 : 0.0);
                }
                error[y * size + x] = sum / samples;
            }
        }
        return lowFrequencyFraction(error, size);
    };
    const double white = 1.0 / 64.0;
    for (uint32_t samples : {1u, 4u}) {
        const double blue = lowFraction(SamplerKind::BlueNoise, samples);
        const double sobol = lowFraction(SamplerKind::Sobol, samples);
        std::printf("low-frequency error energy / white noise's at %u spp: bluenoise %.3f, "
                    "sobol %.3f\n", samples, blue / white, sobol / white);
        if (samples == 1) {
            EXPECT_LT(blue, 0.2 * white);
            EXPECT_GT(sobol, 0.5 * white);
        }
    }
}

} // namespace
} // namespace wf::test
