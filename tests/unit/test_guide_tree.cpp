// The path guide's SD-tree (src/render/guiding/sd_tree.cpp, shaders/guiding/guide_tree.h): the
// quadtree's pdf integrates to 1, sampling follows it (chi-square), sampling's pdf is the
// evaluated one, the BSDF mixture is positive wherever the BSDF is, and splitting, propagation
// and the GPU's fixed-point splat layout keep the sums.
#include <gtest/gtest.h>

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
using wf::guiding::DirTree;
using wf::guiding::FlatGuide;
using wf::guiding::SDTree;

constexpr std::uint32_t MAX_DEPTH = 8; // quadtrees no finer than a 256 x 256 grid

// A leaf trained on radiance from a small bright disk around `peak` plus a dim uniform sky,
// over three iterations, so its quadtree is several levels deep and uneven.
SDTree trainedTree(unsigned seed) {
    SDTree tree(vec3(-1.0f), vec3(1.0f));
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const vec3 peak = glm::normalize(vec3(0.3f, -0.5f, 0.8f));
    for (int iteration = 0; iteration < 3; ++iteration) {
        for (int i = 0; i < 20000; ++i) {
            vec3 p(u(rng) * 2.0f - 1.0f, u(rng) * 2.0f - 1.0f, u(rng) * 2.0f - 1.0f);
            vec3 w = guideSquareToDir(vec2(u(rng), u(rng)));
            double value = glm::dot(w, peak) > 0.95f ? 50.0 : 0.1;
            if (w.z < -0.5f)
                value = 0.0; // a dark cap: zero-probability quadrants
            tree.record(p, w, value);
        }
        tree.endIteration(8000.0, 0.01, MAX_DEPTH);
    }
    return tree;
}

// Probability of each of binsX x binsY cells of the unit square under squarePdf, by the
// midpoint rule on the 2^MAX_DEPTH grid (exact for the quadtree, whose cells are coarser).
std::vector<double> cellMass(const std::function<double(vec2)>& squarePdf, int binsX,
                             int binsY) {
    const int fine = 1 << MAX_DEPTH;
    std::vector<double> mass(size_t(binsX * binsY), 0.0);
    for (int i = 0; i < fine; ++i)
        for (int j = 0; j < fine; ++j) {
            vec2 x((i + 0.5f) / fine, (j + 0.5f) / fine);
            int bx = i * binsX / fine, by = j * binsY / fine;
            mass[size_t(by * binsX + bx)] += squarePdf(x) / (double(fine) * fine);
        }
    return mass;
}

struct Fixture {
    SDTree tree = trainedTree(7);
    FlatGuide flat = tree.flatten();
    GuideTreeView view{&flat.spatial, &flat.sampling, &flat.building};
};

TEST(GuideTree, TrainedTreeIsUneven) {
    Fixture f;
    auto s = f.tree.stats();
    EXPECT_GT(s.spatialLeaves, 1u);
    EXPECT_GE(s.maxDirDepth, 4u);
    EXPECT_LE(s.maxDirDepth, MAX_DEPTH);
}

TEST(GuideTree, PdfIntegratesToOneOverTheSphere) {
    Fixture f;
    for (std::uint32_t l : {0u, 1u}) {
        uint root = f.flat.samplingBase[l];
        // Midpoint rule in (cos theta, phi) with d omega = d cos d phi: through the direction
        // mapping, so the 1 / 4 pi is checked too.
        const int n = 1 << MAX_DEPTH;
        double integral = 0.0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                vec3 w = wf::test::sphereDirection(-1.0 + 2.0 * (i + 0.5) / n,
                                                   2.0 * M_PI * (j + 0.5) / n);
                integral += f.view.guidePdf(root, w) * (2.0 / n) * (2.0 * M_PI / n);
            }
        EXPECT_NEAR(integral, 1.0, 1e-3) << "leaf " << l;
    }
}

TEST(GuideTree, SamplingMatchesPdf) {
    Fixture f;
    const uint root = f.flat.samplingBase[0];
    const int binsX = 16, binsY = 32, samples = 400000;
    std::vector<double> expected =
        cellMass([&](vec2 x) { return f.view.guidePdfSquare(root, x); }, binsX, binsY);
    for (double& e : expected)
        e *= samples;
    std::mt19937 rng(11);
    std::vector<double> observed(expected.size(), 0.0);
    for (int i = 0; i < samples; ++i) {
        float pdf;
        vec3 w = f.view.guideSample(root, vec2(wf::test::uniform01(rng), wf::test::uniform01(rng)),
                                    pdf);
        vec2 x = guideDirToSquare(w);
        int bx = std::min(int(x.x * binsX), binsX - 1), by = std::min(int(x.y * binsY), binsY - 1);
        observed[size_t(by * binsX + bx)] += 1.0;
    }
    EXPECT_GT(wf::test::chiSquarePValue(observed, expected), 1e-3);
}

TEST(GuideTree, SampledPdfEqualsEvaluatedPdf) {
    Fixture f;
    std::mt19937 rng(12);
    int mismatches = 0;
    const int samples = 100000;
    for (int i = 0; i < samples; ++i) {
        uint root = f.flat.samplingBase[size_t(i) % f.flat.samplingBase.size()];
        float pdf;
        vec3 w = f.view.guideSample(root, vec2(wf::test::uniform01(rng), wf::test::uniform01(rng)),
                                    pdf);
        ASSERT_GT(pdf, 0.0f);
        float evaluated = f.view.guidePdf(root, w);
        if (std::abs(evaluated - pdf) > 1e-4f * pdf)
            ++mismatches;
    }
    // Only a direction that rounds across a cell edge on its way through the sphere may differ.
    EXPECT_LT(mismatches, samples / 1000);
}

// The shade pass's single walk (guideSampleOrPdfSquare) is exactly guideSampleSquare when it
// draws and guidePdfSquare when it evaluates: the same point, the same density, bit for bit.
TEST(GuideTree, OneWalkSamplesAndEvaluatesAsTheTwoWalks) {
    Fixture f;
    std::mt19937 rng(13);
    for (int i = 0; i < 20000; ++i) {
        uint root = f.flat.samplingBase[size_t(i) % f.flat.samplingBase.size()];
        vec2 u(wf::test::uniform01(rng), wf::test::uniform01(rng));
        float sampledPdf, walkPdf;
        vec2 x = f.view.guideSampleSquare(root, u, sampledPdf);
        vec2 y = f.view.guideSampleOrPdfSquare(root, true, u, vec2(0.0f), walkPdf);
        ASSERT_EQ(x, y);
        ASSERT_EQ(sampledPdf, walkPdf);
        vec2 point(wf::test::uniform01(rng), wf::test::uniform01(rng));
        y = f.view.guideSampleOrPdfSquare(root, false, vec2(0.0f), point, walkPdf);
        ASSERT_EQ(point, y);
        ASSERT_EQ(f.view.guidePdfSquare(root, point), walkPdf);
    }
}

TEST(GuideTree, MixtureIsPositiveWhereTheBsdfIsAndSamplesItsPdf) {
    Fixture f;
    const uint root = f.flat.samplingBase[0];
    // The trained guide is zero somewhere (the dark cap); a cosine lobe around -z reaches it.
    auto bsdfPdf = [](vec3 w) { return cosineHemispherePdf(-w.z); };
    auto mixture = [&](vec3 w) { return guideMixturePdf(bsdfPdf(w), f.view.guidePdf(root, w), 0.5f); };
    int guideZero = 0;
    const int n = 128;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            vec3 w = guideSquareToDir(vec2((i + 0.5f) / n, (j + 0.5f) / n));
            guideZero += f.view.guidePdf(root, w) == 0.0f ? 1 : 0;
            if (bsdfPdf(w) > 0.0f)
                EXPECT_GT(mixture(w), 0.0f);
        }
    EXPECT_GT(guideZero, 0) << "the test wants a guide with zero-probability cells";

    const int binsX = 16, binsY = 32, samples = 400000;
    std::vector<double> expected =
        cellMass([&](vec2 x) { return 4.0 * M_PI * mixture(guideSquareToDir(x)); }, binsX, binsY);
    for (double& e : expected)
        e *= samples;
    std::mt19937 rng(13);
    std::vector<double> observed(expected.size(), 0.0);
    for (int i = 0; i < samples; ++i) {
        float lobe = wf::test::uniform01(rng);
        vec2 u(wf::test::uniform01(rng), wf::test::uniform01(rng));
        float pdf;
        vec3 w = lobe < 0.5f ? -sampleCosineHemisphere(u) : f.view.guideSample(root, u, pdf);
        vec2 x = guideDirToSquare(w);
        int bx = std::min(int(x.x * binsX), binsX - 1), by = std::min(int(x.y * binsY), binsY - 1);
        observed[size_t(by * binsX + bx)] += 1.0;
    }
    EXPECT_GT(wf::test::chiSquarePValue(observed, expected), 1e-3);
}

TEST(GuideTree, PropagationKeepsTheSplattedSum) {
    DirTree tree;
    tree = [] {
        DirTree seed;
        seed.record(vec2(0.1f, 0.1f), 1.0);
        seed.propagate();
        return seed.refined(0.01, MAX_DEPTH); // a deep tree around (0.1, 0.1)
    }();
    ASSERT_GT(tree.nodes.size(), 4u);
    std::mt19937 rng(3);
    double recorded = 0.0;
    for (int i = 0; i < 5000; ++i) {
        double v = wf::test::uniform01(rng);
        tree.record(vec2(wf::test::uniform01(rng), wf::test::uniform01(rng)), v);
        recorded += v;
    }
    tree.propagate();
    EXPECT_NEAR(tree.total(), recorded, 1e-9 * recorded);
    for (const DirTree::Node& n : tree.nodes)
        for (int q = 0; q < 4; ++q)
            if (n.child[q] != 0) {
                const auto& s = tree.nodes[n.child[q]].sum;
                EXPECT_DOUBLE_EQ(n.sum[q], s[0] + s[1] + s[2] + s[3]);
            }
}

TEST(GuideTree, RefinementSubdividesExactlyTheHeavyQuadrants) {
    DirTree tree;
    std::mt19937 rng(4);
    for (int i = 0; i < 2000; ++i)
        tree.record(vec2(0.3f * wf::test::uniform01(rng), wf::test::uniform01(rng)), 1.0);
    tree.propagate();
    DirTree next = tree.refined(0.3, MAX_DEPTH);
    // The root's quadrants x < 0.5 hold all the energy (about half each): subdivided; the
    // others hold none: leaves. All sums start at zero.
    EXPECT_NE(next.nodes[0].child[0], 0u);
    EXPECT_NE(next.nodes[0].child[2], 0u);
    EXPECT_EQ(next.nodes[0].child[1], 0u);
    EXPECT_EQ(next.nodes[0].child[3], 0u);
    for (const DirTree::Node& n : next.nodes)
        for (double s : n.sum)
            EXPECT_EQ(s, 0.0);
}

TEST(GuideTree, SpatialSplitKeepsCountsAndDistributions) {
    SDTree tree(vec3(0.0f), vec3(1.0f));
    std::mt19937 rng(5);
    for (int i = 0; i < 1000; ++i)
        tree.record(vec3(wf::test::uniform01(rng)), guideSquareToDir(vec2(0.2f, 0.7f)), 2.0);
    tree.endIteration(300.0, 0.01, MAX_DEPTH); // 1000 splats: split into 4 leaves of 250
    ASSERT_EQ(tree.leaves().size(), 4u);
    FlatGuide flat = tree.flatten();
    GuideTreeView view{&flat.spatial, &flat.sampling, &flat.building};
    for (std::size_t l = 0; l < 4; ++l) {
        // Every leaf froze a copy of its parent's quadtree: the same distribution everywhere.
        // (four leaves, not the depth limit's many: each split halved the count)
        EXPECT_DOUBLE_EQ(tree.leaves()[l].sampling.total(), 2000.0);
        // (one node deep yet: all the energy in the quadrant x < 1/2, y >= 1/2)
        EXPECT_FLOAT_EQ(view.guidePdfSquare(flat.samplingBase[l], vec2(0.2f, 0.7f)), 4.0f);
        EXPECT_FLOAT_EQ(view.guidePdfSquare(flat.samplingBase[l], vec2(0.7f, 0.2f)), 0.0f);
    }
    // The flat lookup finds the host's leaves.
    for (int i = 0; i < 1000; ++i) {
        vec3 p(wf::test::uniform01(rng), wf::test::uniform01(rng), wf::test::uniform01(rng));
        uint node = view.guideSpatialLeaf(tree.unitPosition(p));
        EXPECT_EQ(flat.spatial[node].child & ~WF_GUIDE_LEAF, tree.leafIndexAt(p));
    }
}

TEST(GuideTree, FixedPointSplatsMatchHostRecords) {
    Fixture f;
    SDTree host = f.tree; // records on the host ...
    std::vector<std::uint32_t> counters(f.flat.splatCounterCount(), 0u);
    std::vector<std::uint32_t> leafStats(f.flat.samplingBase.size() * WF_GUIDE_LEAF_STATS, 0u);
    std::mt19937 rng(6);
    double recorded = 0.0;
    for (int i = 0; i < 20000; ++i) {
        vec3 p(wf::test::uniform01(rng) * 2.0f - 1.0f, wf::test::uniform01(rng) * 2.0f - 1.0f,
               wf::test::uniform01(rng) * 2.0f - 1.0f);
        vec3 w = guideSquareToDir(vec2(wf::test::uniform01(rng), wf::test::uniform01(rng)));
        float value = 100.0f * wf::test::uniform01(rng);
        host.record(p, w, value);
        recorded += value;
        // ... and as the GPU splats: leaf by the flat lookup, 64-bit fixed point in two words.
        uint node = f.view.guideSpatialLeaf(f.tree.unitPosition(p));
        uint cell = f.view.guideBuildingCell(f.flat.spatial[node].buildingRoot, guideDirToSquare(w));
        std::uint32_t add = std::uint32_t(std::min(value, WF_GUIDE_MAX_SPLAT) * WF_GUIDE_FIXED_SCALE);
        std::uint32_t old = counters[2 * cell];
        counters[2 * cell] = old + add;
        if (counters[2 * cell] < old)
            counters[2 * cell + 1] += 1u;
        leafStats[(f.flat.spatial[node].child & ~WF_GUIDE_LEAF) * WF_GUIDE_LEAF_STATS] += 1u;
    }
    SDTree gpu = f.tree;
    gpu.addSplats(f.flat, counters, leafStats);
    double hostSum = 0.0, gpuSum = 0.0;
    for (std::size_t l = 0; l < host.leaves().size(); ++l) {
        DirTree a = host.leaves()[l].building, b = gpu.leaves()[l].building;
        a.propagate();
        b.propagate();
        EXPECT_NEAR(a.total(), b.total(), 1e-4 * std::max(1.0, a.total()));
        EXPECT_EQ(host.leaves()[l].samples, gpu.leaves()[l].samples);
        hostSum += a.total();
        gpuSum += b.total();
    }
    EXPECT_NEAR(hostSum, recorded, 1e-6 * recorded);
    EXPECT_NEAR(gpuSum, recorded, 1e-4 * recorded);
}

} // namespace
