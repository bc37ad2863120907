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
// midpoint rule on a fine x fine grid (2^MAX_DEPTH: exact for the quadtree, whose cells are
// coarser).
std::vector<double> cellMass(const std::function<double(vec2)>& squarePdf, int binsX,
                             int binsY, int fine = 1 << MAX_DEPTH) {
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

// Parallax: the map from a leaf's centre to a vertex and back is one bijection, both ways with
// one Jacobian, within the bounds guide_tree.h states; no distance learnt: no change.
TEST(GuideTree, ParallaxMapsAreInverseWithOneJacobian) {
    std::mt19937 rng(21);
    for (int i = 0; i < 20000; ++i) {
        vec3 offset = (vec3(wf::test::uniform01(rng), wf::test::uniform01(rng),
                            wf::test::uniform01(rng)) - 0.5f) * 2.0f;
        float distance = 0.05f + 3.0f * wf::test::uniform01(rng);
        float radius = guideParallaxRadius(offset, distance);
        ASSERT_GE(radius, 1.5f * glm::length(offset) * 0.9999f);
        vec3 w = guideSquareToDir(vec2(wf::test::uniform01(rng), wf::test::uniform01(rng)));
        float toVertex, toCentre;
        vec3 wx = guideParallaxFromCentre(offset, radius, w, toVertex);
        vec3 back = guideParallaxToCentre(offset, radius, wx, toCentre);
        ASSERT_NEAR(glm::length(wx), 1.0f, 1e-5f);
        ASSERT_LT(glm::length(back - w), 2e-4f) << i;
        ASSERT_NEAR(toVertex, toCentre, 1e-3f * toVertex) << i;
        ASSERT_GE(toVertex, 0.11f);
        ASSERT_LE(toVertex, 3.8f);
    }
    float jacobian;
    const vec3 w = glm::normalize(vec3(0.2f, -0.7f, 0.4f));
    EXPECT_EQ(guideParallaxToCentre(vec3(0.5f), guideParallaxRadius(vec3(0.5f), 0.0f), w, jacobian),
              w);
    EXPECT_EQ(jacobian, 1.0f);
}

// The density at a vertex away from the leaf's centre (the quadtree's density there times the
// Jacobian) still integrates to 1 over the sphere, and sampling the quadtree then mapping the
// direction follows it (chi-square) with the pdf it returns.
TEST(GuideTree, ParallaxDensityIntegratesToOneAndSamplingFollowsIt) {
    Fixture f;
    const uint root = f.flat.samplingBase[0];
    const vec3 offset(0.3f, -0.25f, 0.45f);
    for (float distance : {0.4f, 1.2f, 5.0f}) {
        const float radius = guideParallaxRadius(offset, distance);
        auto pdfAt = [&](vec3 w) { return double(f.view.guidePdfAt(root, offset, radius, w)); };
        // Midpoint rule in (cos theta, phi), finer than the quadtree: the mapped density is
        // not constant over its cells.
        const int n = 1024;
        double integral = 0.0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                integral += pdfAt(wf::test::sphereDirection(-1.0 + 2.0 * (i + 0.5) / n,
                                                            2.0 * M_PI * (j + 0.5) / n)) *
                            (2.0 / n) * (2.0 * M_PI / n);
        EXPECT_NEAR(integral, 1.0, 5e-3) << "distance " << distance;

        const int binsX = 16, binsY = 32, samples = 400000;
        // Mapped, the quadtree's finest cells have curved edges: 8 x 8 points per cell.
        std::vector<double> expected = cellMass(
            [&](vec2 x) { return 4.0 * M_PI * pdfAt(guideSquareToDir(x)); }, binsX, binsY,
            8 << MAX_DEPTH);
        for (double& e : expected)
            e *= samples;
        std::mt19937 rng(22);
        std::vector<double> observed(expected.size(), 0.0);
        int mismatches = 0;
        for (int i = 0; i < samples; ++i) {
            float squarePdf, jacobian;
            vec2 x = f.view.guideSampleSquare(
                root, vec2(wf::test::uniform01(rng), wf::test::uniform01(rng)), squarePdf);
            vec3 w = guideParallaxFromCentre(offset, radius, guideSquareToDir(x), jacobian);
            double pdf = squarePdf * WF_GUIDE_INV_4PI * jacobian;
            if (std::abs(pdfAt(w) - pdf) > 1e-3 * pdf)
                ++mismatches;
            vec2 y = guideDirToSquare(w);
            int bx = std::min(int(y.x * binsX), binsX - 1), by = std::min(int(y.y * binsY), binsY - 1);
            observed[size_t(by * binsX + bx)] += 1.0;
        }
        EXPECT_GT(wf::test::chiSquarePValue(observed, expected), 1e-3) << "distance " << distance;
        EXPECT_LT(mismatches, samples / 1000) << "distance " << distance;
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

// A leaf's parallax from the GPU's counters: the frozen quadtree is seen from the centre its
// splats were seen from, at their energy-weighted mean distance; the records' mean position
// becomes the next building centre, moved into each child's box when the leaf splits.
TEST(GuideTree, LeavesLearnTheirParallaxFromTheCounters) {
    SDTree tree(vec3(-1.0f), vec3(1.0f));
    FlatGuide flat = tree.flatten();
    const vec3 boxCentre = tree.boxLo() + 0.5f * tree.boxSize();
    EXPECT_EQ(flat.spatial[0].radianceDistance, 0.0f) << "nothing learnt: no parallax";
    EXPECT_EQ(flat.spatial[0].buildingCentre, boxCentre);
    std::vector<std::uint32_t> counters(flat.splatCounterCount(), 0u);
    std::vector<std::uint32_t> stats(WF_GUIDE_LEAF_STATS, 0u);
    auto set64 = [&](std::uint32_t at, double value) {
        std::uint64_t fixed = std::uint64_t(value * WF_GUIDE_MOMENT_SCALE);
        stats[at] = std::uint32_t(fixed & 0xffffffffu);
        stats[at + 1] = std::uint32_t(fixed >> 32);
    };
    stats[0] = 1000; // records, at a mean position 0.25 beyond the box's corner on x, ...
    const vec3 mean = tree.boxLo() + vec3(0.25f, 0.5f, 1.5f);
    for (std::uint32_t axis = 0; axis < 3; ++axis)
        set64(WF_GUIDE_STAT_POSITION + 2 * axis, 1000.0 * (mean - tree.boxLo())[int(axis)]);
    set64(WF_GUIDE_STAT_ENERGY, 2.0e5); // ... whose splats came from 2.5 away on average
    set64(WF_GUIDE_STAT_DISTANCE, 2.5 * 2.0e5);
    tree.addSplats(flat, counters, stats);
    tree.endIteration(1e30, 0.01, 8); // no split
    flat = tree.flatten();
    EXPECT_EQ(flat.spatial[0].samplingCentre, boxCentre);
    EXPECT_NEAR(flat.spatial[0].radianceDistance, 2.5f, 1e-4f);
    EXPECT_LT(glm::length(flat.spatial[0].buildingCentre - mean), 1e-3f);

    // The next iteration splits the leaf along x: both children sample from the parent's
    // frozen view (its centre, its distance); their building centres are the mean moved into
    // each child's box. No record carried light: the distance is kept.
    stats.assign(WF_GUIDE_LEAF_STATS, 0u);
    stats[0] = 1000;
    for (std::uint32_t axis = 0; axis < 3; ++axis)
        set64(WF_GUIDE_STAT_POSITION + 2 * axis, 1000.0 * (mean - tree.boxLo())[int(axis)]);
    tree.addSplats(flat, counters, stats);
    tree.endIteration(600.0, 0.01, 8); // one split: the halves hold 500 each
    ASSERT_EQ(tree.leaves().size(), 2u);
    flat = tree.flatten();
    for (const auto& node : flat.spatial) {
        if ((node.child & WF_GUIDE_LEAF) == 0u)
            continue;
        EXPECT_LT(glm::length(node.samplingCentre - mean), 1e-3f);
        EXPECT_NEAR(node.radianceDistance, 2.5f, 1e-4f);
        vec3 inBox = tree.unitPosition(node.buildingCentre);
        EXPECT_GE(glm::min(inBox.x, glm::min(inBox.y, inBox.z)), -1e-5f);
        EXPECT_LE(glm::max(inBox.x, glm::max(inBox.y, inBox.z)), 1.0f + 1e-5f);
    }
    // The child holding the mean keeps it; the other takes the nearest point of its box.
    EXPECT_LT(glm::length(flat.spatial[flat.spatial[0].child].buildingCentre - mean), 1e-3f);
    EXPECT_NEAR(flat.spatial[flat.spatial[0].child + 1].buildingCentre.x,
                tree.boxLo().x + 0.5f * tree.boxSize().x, 1e-4f);
}

} // namespace
