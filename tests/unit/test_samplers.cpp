// Structure of the sample patterns (shaders/sampling/sampler_*.h): Sobol's (0, 2)-sequence nets
// in every power-of-two block, the stratification of the finite sets, permutations that are
// permutations, the first points of the radical inverses, and the blue-noise mask.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "render/samplers/blue_noise.h"
#include "render/samplers/sampler_tables.h"
#include "sampler_test_util.h"

namespace wf::test {
namespace {

using namespace gpu_types;

// Every elementary interval of area 2^-m (2^a x 2^(m-a) boxes) holds exactly one of the 2^m
// points: the definition of a (0, m, 2)-net in base 2.
bool isZeroNet(const std::vector<glm::vec2>& points, int m) {
    const uint32_t n = 1u << m;
    for (int a = 0; a <= m; ++a) {
        std::vector<int> count(n, 0);
        for (const glm::vec2& p : points) {
            uint32_t bx = uint32_t(p.x * float(1u << a)), by = uint32_t(p.y * float(1u << (m - a)));
            ++count[by * (1u << a) + bx];
        }
        if (std::any_of(count.begin(), count.end(), [](int c) { return c != 1; }))
            return false;
    }
    return true;
}

// The column loop that sobolDimension1's xor-shift form replaces.
uint32_t sobolDimension1Reference(uint32_t index) {
    uint32_t result = 0, column = 0x80000000u;
    for (; index != 0; index >>= 1, column ^= column >> 1)
        if (index & 1)
            result ^= column;
    return result;
}

TEST(Samplers, SobolSecondDimensionMatchesItsGeneratorMatrix) {
    uint32_t x = 12345;
    for (int i = 0; i < 200000; ++i) {
        x = x * 1664525u + 1013904223u;
        ASSERT_EQ(sobolDimension1(x), sobolDimension1Reference(x)) << x;
        ASSERT_EQ(sobolDimension1(uint32_t(i)), sobolDimension1Reference(uint32_t(i)));
    }
}

// Sobol and blue noise: in every pixel, every aligned block of 2^m consecutive samples (so
// every power-of-two prefix, and what --spp-offset parts cover) is a (0, m, 2)-net, for the
// pixel pair and for the pairs of later bounces. Checked on the first three blocks.
TEST(Samplers, SobolPairsAreZeroTwoSequencesInEveryPixel) {
    for (SamplerKind kind : {SamplerKind::Sobol, SamplerKind::BlueNoise}) {
        for (bool randomize : {true, false}) {
            for (uint32_t pixel = 0; pixel < 6; ++pixel) {
                SampleSite site{pixel * 7, pixel, 64, 3 + pixel, 0, randomize};
                for (uint32_t dim : {WF_DIM_PIXEL, bounceDimension(0, WF_DIM_BSDF),
                                     bounceDimension(3, WF_DIM_LIGHT_POINT)}) {
                    for (int m = 0; m <= 8; ++m) {
                        for (uint32_t block = 0; block < 3; ++block) {
                            std::vector<glm::vec2> points;
                            for (uint32_t i = 0; i < (1u << m); ++i)
                                points.push_back(
                                    samplePoint2D(kind, site, (block << m) + i, dim));
                            ASSERT_TRUE(isZeroNet(points, m))
                                << samplerName(kind) << " dim " << dim << " m " << m
                                << " block " << block << " randomize " << randomize;
                        }
                    }
                }
            }
        }
    }
}

// 1D dimensions: every aligned block of 2^m samples has one point per interval of 2^-m.
TEST(Samplers, SobolOneDimensionalDimensionsAreStratifiedInEveryBlock) {
    for (SamplerKind kind : {SamplerKind::Sobol, SamplerKind::BlueNoise}) {
        SampleSite site{5, 9, 64, 77, 0, true};
        for (int m = 0; m <= 10; ++m) {
            std::vector<int> count(1u << m, 0);
            for (uint32_t i = 0; i < (1u << m); ++i)
                ++count[uint32_t(samplePoint1D(kind, site, (5u << m) + i,
                                               bounceDimension(1, WF_DIM_ROULETTE)) *
                                 float(1u << m))];
            EXPECT_TRUE(std::all_of(count.begin(), count.end(), [](int c) { return c == 1; }))
                << samplerName(kind) << " m " << m;
        }
    }
}

TEST(Samplers, OwenScrambledIndicesKeepPowerOfTwoBlocksTogether) {
    for (uint32_t seed : {0u, 1u, 0xdeadbeefu, 123456789u}) {
        for (int k = 0; k <= 12; ++k) {
            std::set<uint32_t> blocks;
            std::set<uint32_t> indices;
            for (uint32_t i = 0; i < (1u << k); ++i) {
                uint32_t shuffled = owenScramble(i, seed);
                blocks.insert(k == 32 ? 0 : shuffled >> k);
                indices.insert(shuffled);
            }
            EXPECT_EQ(blocks.size(), 1u) << "seed " << seed << " k " << k;
            EXPECT_EQ(indices.size(), size_t(1u << k));
        }
    }
}

TEST(Samplers, PermuteIndexIsAPermutation) {
    for (uint32_t n : {1u, 2u, 3u, 5u, 7u, 12u, 16u, 100u, 1000u, 4097u}) {
        for (uint32_t key : {0u, 1u, 0x9e3779b9u, 0xffffffffu, 31337u}) {
            std::vector<int> seen(n, 0);
            for (uint32_t i = 0; i < n; ++i) {
                uint32_t j = permuteIndex(i, n, key);
                ASSERT_LT(j, n);
                ++seen[j];
            }
            EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }))
                << "n " << n << " key " << key;
        }
    }
}

// Stratified and multijitter: a set of N samples puts one sample in each of N distinct grid
// cells, and 1D dimensions one in each of N strata; multijitter is also stratified in both 1D
// projections when N fills the grid.
TEST(Samplers, FiniteSetsAreStratified) {
    for (SamplerKind kind : {SamplerKind::Stratified, SamplerKind::Multijitter}) {
        for (uint32_t n : {1u, 4u, 10u, 16u, 25u, 64u}) {
            SampleSite site{3, 4, 64, 9, n, true};
            const uint32_t nx = stratifiedGridWidth(n), ny = (n + nx - 1) / nx;
            for (uint32_t repetition = 0; repetition < 2; ++repetition) {
                std::set<uint32_t> cells;
                std::vector<int> columns(n, 0), rows(n, 0), strata(n, 0);
                for (uint32_t i = 0; i < n; ++i) {
                    const uint32_t index = repetition * n + i;
                    glm::vec2 p = samplePoint2D(kind, site, index, bounceDimension(0, WF_DIM_BSDF));
                    cells.insert(uint32_t(p.y * float(ny)) * nx + uint32_t(p.x * float(nx)));
                    ++columns[uint32_t(p.x * float(n))];
                    ++rows[uint32_t(p.y * float(n))];
                    ++strata[uint32_t(samplePoint1D(kind, site, index, 7) * float(n))];
                }
                EXPECT_EQ(cells.size(), size_t(n)) << samplerName(kind) << " n " << n;
                auto once = [](const std::vector<int>& v) {
                    return std::all_of(v.begin(), v.end(), [](int c) { return c == 1; });
                };
                EXPECT_TRUE(once(strata)) << samplerName(kind) << " n " << n;
                if (kind == SamplerKind::Multijitter && nx * ny == n) {
                    EXPECT_TRUE(once(columns)) << "n " << n;
                    EXPECT_TRUE(once(rows)) << "n " << n;
                }
            }
        }
    }
}

TEST(Samplers, RadicalInversesWithoutRandomizationAreTheTextbookPoints) {
    SampleSite site{0, 0, 64, 0, 8, false};
    EXPECT_EQ(samplePoint2D(SamplerKind::Halton, site, 1, 0).x, 0.5f);
    EXPECT_NEAR(samplePoint2D(SamplerKind::Halton, site, 1, 0).y, 1.0f / 3.0f, 1e-6f);
    EXPECT_NEAR(samplePoint2D(SamplerKind::Halton, site, 5, 0).y, 7.0f / 9.0f, 1e-6f);
    EXPECT_NEAR(samplePoint1D(SamplerKind::Halton, site, 3, 2), 3.0f / 5.0f, 1e-6f);
    for (uint32_t i = 0; i < 8; ++i) {
        glm::vec2 p = samplePoint2D(SamplerKind::Hammersley, site, i, 0);
        EXPECT_EQ(p.x, float(i) / 8.0f);
        EXPECT_EQ(p.y, uintToUnitFloat(reverseBits32(i)));
    }
    // Hammersley's dimension d >= 1 is Halton's dimension d - 1: 3 = 10 in base 3, so 1/9.
    EXPECT_NEAR(samplePoint1D(SamplerKind::Hammersley, site, 3, 2), 1.0f / 9.0f, 1e-6f);
    EXPECT_EQ(samplePoint1D(SamplerKind::Hammersley, site, 3, 2),
              samplePoint1D(SamplerKind::Halton, site, 3, 1));
    const std::vector<uint32_t> primes = firstPrimes(WF_SAMPLER_PRIME_COUNT);
    EXPECT_EQ(primes[0], 2u);
    EXPECT_EQ(primes[9], 29u);
    EXPECT_EQ(primes.back(), 8161u); // the 1024th prime
    EXPECT_EQ(samplerTable(WF_SAMPLER_TABLE_PRIMES + 9), 29u);
}

// The independent sampler is the renderer's original hash, sample for sample.
TEST(Samplers, IndependentIsThePcgHash) {
    uvec4 h = pcg4d(uvec4(17u, 3u, 5u, 11u));
    EXPECT_EQ(independentSample2D(17, 3, 5, 11), glm::vec2(uintToUnitFloat(h.x),
                                                           uintToUnitFloat(h.y)));
    EXPECT_EQ(sample1D(17, 3, 5, 11), uintToUnitFloat(h.x)); // C++ default: independent
}

TEST(Samplers, EveryValueIsInTheUnitInterval) {
    for (SamplerKind kind : allSamplers()) {
        for (bool randomize : {true, false}) {
            SampleSite site{127, 1, 128, 0xffffffffu, 7, randomize};
            for (uint32_t i : {0u, 1u, 6u, 7u, 1000u, 0xfffffffeu}) {
                for (uint32_t dim : {0u, 2u, 5u, 1000u, 1023u, 1024u, 5000u}) {
                    glm::vec2 p = samplePoint2D(kind, site, i, dim);
                    float q = samplePoint1D(kind, site, i, dim);
                    EXPECT_TRUE(p.x >= 0.0f && p.x < 1.0f && p.y >= 0.0f && p.y < 1.0f &&
                                q >= 0.0f && q < 1.0f)
                        << samplerName(kind) << " i " << i << " dim " << dim;
                }
            }
        }
    }
}

TEST(BlueNoiseMask, IsAPermutationOfRanks) {
    const std::vector<uint32_t> mask = voidAndClusterMask(32, 1.5, 7);
    std::vector<uint32_t> sorted = mask;
    std::sort(sorted.begin(), sorted.end());
    for (uint32_t i = 0; i < sorted.size(); ++i)
        ASSERT_EQ(sorted[i], i);
    EXPECT_EQ(mask, voidAndClusterMask(32, 1.5, 7)); // deterministic
    EXPECT_NE(mask, voidAndClusterMask(32, 1.5, 8));
}

} // namespace
} // namespace wf::test
