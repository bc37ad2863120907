// The learnt BSDF share of the guided mixture (guideCandidateMoment in
// shaders/guiding/guide_tree.h, SDTree::learnFractions in src/render/guiding/sd_tree.cpp):
// records drawn with one share estimate every candidate's second moment (against quadrature),
// the least one is chosen, and leaves keep, flatten and pass on what they learnt.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "chi_square.h"
#include "guiding/guide_tree.h"
#include "render/guiding/sd_tree.h"
#include "sampling/sampling.h"

namespace {

using glm::vec2;
using glm::vec3;
using namespace wf::gpu_types;
using wf::guiding::chooseBsdfFraction;
using wf::guiding::FlatGuide;
using wf::guiding::SDTree;

using Moments = std::array<double, WF_GUIDE_FRACTIONS>;

// A stand-in guide: uniform within a cone of half-angle acos(cosMax) around `axis`.
struct ConeGuide {
    vec3 axis;
    float cosMax;
    float pdf(vec3 w) const {
        return glm::dot(w, axis) >= cosMax ? 1.0f / (2.0f * float(M_PI) * (1.0f - cosMax)) : 0.0f;
    }
    vec3 sample(vec2 u) const {
        float cosTheta = 1.0f - u.x * (1.0f - cosMax);
        float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
        float phi = 2.0f * float(M_PI) * u.y;
        vec3 t = glm::normalize(glm::cross(std::abs(axis.x) < 0.9f ? vec3(1, 0, 0) : vec3(0, 1, 0),
                                           axis));
        vec3 b = glm::cross(axis, t);
        return glm::normalize(sinTheta * std::cos(phi) * t + sinTheta * std::sin(phi) * b +
                              cosTheta * axis);
    }
};

float bsdfPdf(vec3 w) { return cosineHemispherePdf(w.z); } // a Lambertian lobe around +z

// The exact second moment of f |cos| L / p under share `fraction`, by the midpoint rule on an
// equal-area grid of the sphere.
double exactMoment(const std::function<float(vec3)>& integrand, const ConeGuide& guide,
                   float fraction) {
    const int n = 1024;
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            vec3 w = guideSquareToDir(vec2((i + 0.5f) / n, (j + 0.5f) / n));
            double f = integrand(w);
            if (f > 0.0)
                sum += f * f / guideMixturePdf(bsdfPdf(w), guide.pdf(w), fraction);
        }
    return sum * 4.0 * M_PI / (double(n) * n);
}

struct Estimate {
    Moments mean{}, standardError{};
};

// Records drawn from the mixture with share `used`, as the training passes draw them.
Estimate estimateMoments(const std::function<float(vec3)>& integrand, const ConeGuide& guide,
                         float used, int records, unsigned seed) {
    std::mt19937 rng(seed);
    Moments sum{}, sumSquares{};
    for (int r = 0; r < records; ++r) {
        vec2 u(wf::test::uniform01(rng), wf::test::uniform01(rng));
        vec3 w = wf::test::uniform01(rng) < used ? sampleCosineHemisphere(u) : guide.sample(u);
        float pdf = guideMixturePdf(bsdfPdf(w), guide.pdf(w), used);
        float estimate = pdf > 0.0f ? integrand(w) / pdf : 0.0f;
        for (uint j = 0; j < WF_GUIDE_FRACTIONS; ++j) {
            double m = guideCandidateMoment(estimate, bsdfPdf(w), guide.pdf(w), used,
                                            guideFractionCandidate(j));
            sum[j] += m;
            sumSquares[j] += m * m;
        }
    }
    Estimate e;
    for (std::size_t j = 0; j < WF_GUIDE_FRACTIONS; ++j) {
        e.mean[j] = sum[j] / records;
        double variance = sumSquares[j] / records - e.mean[j] * e.mean[j];
        e.standardError[j] = std::sqrt(std::max(variance, 0.0) / records);
    }
    return e;
}

int exactBest(const Moments& exact) {
    int best = 0;
    for (std::size_t j = 1; j < exact.size(); ++j)
        if (exact[j] < exact[std::size_t(best)])
            best = int(j);
    return best;
}

// Two integrands: light from where the guide points (its share should fall), and light from
// everywhere but there (the guide mismatched: BSDF sampling alone would be best).
TEST(GuideFraction, RecordsEstimateEachCandidatesMomentAndPickTheLeast) {
    const vec3 lightDirection = glm::normalize(vec3(0.5f, 0.2f, 0.8f));
    const ConeGuide guide{lightDirection, 0.97f};
    const std::function<float(vec3)> cases[2] = {
        [&](vec3 w) {
            float cosine = std::max(w.z, 0.0f);
            return float(0.8 / M_PI) * cosine * (glm::dot(w, lightDirection) > 0.98f ? 40.0f : 0.2f);
        },
        [&](vec3 w) {
            float cosine = std::max(w.z, 0.0f);
            return float(0.8 / M_PI) * cosine * (glm::dot(w, lightDirection) > 0.9f ? 0.0f : 1.0f);
        }};
    const int expectedBest[2] = {0, int(WF_GUIDE_FRACTIONS) - 1};
    for (int c = 0; c < 2; ++c) {
        Moments exact{};
        for (uint j = 0; j < WF_GUIDE_FRACTIONS; ++j)
            exact[j] = exactMoment(cases[c], guide, guideFractionCandidate(j));
        ASSERT_EQ(exactBest(exact), expectedBest[c]) << "case " << c << ": the test's premise";
        for (float used : {0.5f, 0.9f}) {
            Estimate e = estimateMoments(cases[c], guide, used, 400000, 17 + c);
            for (std::size_t j = 0; j < WF_GUIDE_FRACTIONS; ++j)
                EXPECT_NEAR(e.mean[j], exact[j], 5.0 * e.standardError[j] + 1e-3 * exact[j])
                    << "case " << c << ", share used " << used << ", candidate " << j;
            EXPECT_EQ(chooseBsdfFraction(e.mean), expectedBest[c])
                << "case " << c << ", share used " << used;
        }
    }
}

TEST(GuideFraction, CandidatesArePositiveSoTheMixtureCoversTheBsdf) {
    for (uint j = 0; j < WF_GUIDE_FRACTIONS; ++j) {
        EXPECT_GT(guideFractionCandidate(j), 0.0f);
        // At most 1: the BSDF alone, where the guide does not help (the last candidate).
        EXPECT_LE(guideFractionCandidate(j), 1.0f);
        if (j > 0)
            EXPECT_GT(guideFractionCandidate(j), guideFractionCandidate(j - 1));
    }
    EXPECT_EQ(chooseBsdfFraction(Moments{}), -1); // no record carried light: nothing learnt
}

// The GPU's per-leaf counters: the record count, then each candidate's moment as a 64-bit
// fixed-point sum in two words.
void setMoment(std::vector<std::uint32_t>& stats, std::size_t leaf, std::size_t j, double value) {
    std::uint64_t fixed = std::uint64_t(value * WF_GUIDE_MOMENT_SCALE);
    stats[leaf * WF_GUIDE_LEAF_STATS + 1 + 2 * j] = std::uint32_t(fixed & 0xffffffffu);
    stats[leaf * WF_GUIDE_LEAF_STATS + 2 + 2 * j] = std::uint32_t(fixed >> 32);
}

TEST(GuideFraction, LeavesLearnFlattenAndPassOnTheirShare) {
    SDTree tree(vec3(-1.0f), vec3(1.0f));
    FlatGuide flat = tree.flatten();
    ASSERT_EQ(flat.samplingBase.size(), 1u);
    std::vector<std::uint32_t> counters(flat.splatCounterCount(), 0u);
    std::vector<std::uint32_t> stats(WF_GUIDE_LEAF_STATS, 0u);
    stats[0] = 1000; // records
    // Sums past 2^32 units: the high word counts.
    for (std::size_t j = 0; j < WF_GUIDE_FRACTIONS; ++j)
        setMoment(stats, 0, j, 3.0e6 + (j == 2 ? 0.0 : 1.0e6));
    tree.addSplats(flat, counters, stats);
    EXPECT_NEAR(tree.leaves()[0].moments[2], 3.0e6, 1.0);
    EXPECT_NEAR(tree.leaves()[0].moments[0], 4.0e6, 1.0);
    tree.learnFractions(256.0);
    EXPECT_EQ(tree.leaves()[0].bsdfFraction, guideFractionCandidate(2));
    EXPECT_EQ(tree.leaves()[0].moments[2], 0.0) << "the moments restart every iteration";
    EXPECT_EQ(tree.flatten().spatial[0].bsdfFraction, guideFractionCandidate(2));

    // The leaf splits (1000 records past a threshold of 100): its children keep the share,
    // and one with too few records of its own next time keeps it too.
    tree.endIteration(100.0, 0.01, 8);
    ASSERT_GT(tree.leaves().size(), 1u);
    for (const auto& leaf : tree.leaves())
        EXPECT_EQ(leaf.bsdfFraction, guideFractionCandidate(2));
    flat = tree.flatten();
    stats.assign(flat.samplingBase.size() * WF_GUIDE_LEAF_STATS, 0u);
    stats[0] = 100; // leaf 0: too few records
    setMoment(stats, 0, 0, 1.0);
    stats[WF_GUIDE_LEAF_STATS] = 300; // leaf 1: enough, least with the last candidate
    for (std::size_t j = 0; j < WF_GUIDE_FRACTIONS; ++j)
        setMoment(stats, 1, j, j + 1 == WF_GUIDE_FRACTIONS ? 1.0 : 2.0);
    counters.assign(flat.splatCounterCount(), 0u);
    tree.addSplats(flat, counters, stats);
    tree.learnFractions(256.0);
    EXPECT_EQ(tree.leaves()[0].bsdfFraction, guideFractionCandidate(2));
    EXPECT_EQ(tree.leaves()[1].bsdfFraction, guideFractionCandidate(WF_GUIDE_FRACTIONS - 1));

    // Enough records, none of which carried light (every moment 0): nothing to guide
    // towards, so BSDF sampling alone; too few records still keep the share they had.
    flat = tree.flatten();
    stats.assign(flat.samplingBase.size() * WF_GUIDE_LEAF_STATS, 0u);
    stats[0] = 100;
    stats[WF_GUIDE_LEAF_STATS] = 300;
    counters.assign(flat.splatCounterCount(), 0u);
    tree.addSplats(flat, counters, stats);
    tree.leaf(1).bsdfFraction = guideFractionCandidate(0);
    tree.learnFractions(256.0);
    EXPECT_EQ(tree.leaves()[0].bsdfFraction, guideFractionCandidate(2));
    EXPECT_EQ(tree.leaves()[1].bsdfFraction, 1.0f);
}

// A share below 1 pays where it cuts the variance of the records' whole-path estimates by at
// least kMinVarianceCut: the same moments choose share 0.7 either way, which pays where the
// vertex's part is most of the path's variance, not where the path's variance is far larger
// (NEE's direct light).
TEST(GuideFraction, AShareBelowOneMustCutThePathsVariance) {
    for (const double pathVariance : {0.8e4, 1.0e6}) {
        SDTree tree(vec3(-1.0f), vec3(1.0f));
        FlatGuide flat = tree.flatten();
        std::vector<std::uint32_t> counters(flat.splatCounterCount(), 0u);
        std::vector<std::uint32_t> stats(WF_GUIDE_LEAF_STATS, 0u);
        const double records = 1000.0, mean = 10.0;
        stats[0] = std::uint32_t(records);
        for (std::size_t j = 0; j < WF_GUIDE_FRACTIONS; ++j) // the least, 7e3, with share 0.7
            setMoment(stats, 0, j, j == 2 ? 7.0e3 : 1.0e4);
        // Sum of squares and sum of the whole-path estimates: variance x records = pathVariance.
        auto set64 = [&](std::uint32_t at, double value) {
            const auto fixed = std::uint64_t(value * WF_GUIDE_MOMENT_SCALE);
            stats[at] = std::uint32_t(fixed & 0xffffffffu);
            stats[at + 1] = std::uint32_t(fixed >> 32);
        };
        set64(WF_GUIDE_STAT_TOTAL, pathVariance + records * mean * mean);
        set64(WF_GUIDE_STAT_TOTAL_SUM, records * mean);
        tree.addSplats(flat, counters, stats);
        tree.learnFractions(256.0);
        // The cut, 3e3, is 0.375 of 8e3 (kept) and 0.003 of 1e6 (not enough).
        ASSERT_EQ(wf::guiding::kMinVarianceCut, 0.3);
        EXPECT_EQ(tree.leaves()[0].bsdfFraction, guideFractionCandidate(2)) << pathVariance;
        EXPECT_EQ(tree.leaves()[0].guidePays, pathVariance < 1.0e5) << pathVariance;
        EXPECT_EQ(tree.stats().payingLeaves, pathVariance < 1.0e5 ? 1u : 0u) << pathVariance;
    }
}

// A new tree has learnt nothing: its leaves say 0, so the shaders use the renderer's default.
TEST(GuideFraction, UnlearntLeavesFlattenToTheDefault) {
    SDTree tree(vec3(-1.0f), vec3(1.0f));
    EXPECT_EQ(tree.flatten().spatial[0].bsdfFraction, 0.0f);
    EXPECT_DOUBLE_EQ(tree.stats(0.5f).meanBsdfFraction, 0.5);
}

} // namespace
