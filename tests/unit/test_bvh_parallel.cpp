// The parallel binned-SAH builder: the same tree for any thread count, and trees whose SAH
// cost is within 5% of a full-sweep SAH builder's (every split between sorted centroids on
// every axis, the slow exact greedy method binning approximates).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include "scene/bvh/bvh_builder.h"

namespace wf {
namespace {

using glm::vec3;

std::vector<Triangle> soup(int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Triangle> tris(count);
    for (Triangle& t : tris) {
        const vec3 c(10.0f * u(rng), 10.0f * u(rng), 10.0f * u(rng));
        const float size = 0.02f + 0.3f * u(rng) * u(rng) * u(rng); // mostly small, a few large
        t = Triangle{c, 0, c + size * vec3(u(rng), u(rng), u(rng)), 0,
                     c + size * vec3(u(rng), u(rng), u(rng)), 0};
    }
    return tris;
}

std::vector<Triangle> terrain(int side) {
    auto height = [](float x, float z) {
        return 0.3f * std::sin(3.0f * x) * std::cos(2.0f * z) + 0.05f * std::sin(17.0f * x + 5.0f * z);
    };
    std::vector<Triangle> tris;
    for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j) {
            const float x0 = float(i) / side, x1 = float(i + 1) / side;
            const float z0 = float(j) / side, z1 = float(j + 1) / side;
            const vec3 a(x0, height(x0, z0), z0), b(x1, height(x1, z0), z0);
            const vec3 c(x1, height(x1, z1), z1), d(x0, height(x0, z1), z1);
            tris.push_back(Triangle{a, 0, b, 0, c, 0});
            tris.push_back(Triangle{a, 0, c, 0, d, 0});
        }
    return tris;
}

TEST(BvhParallel, SameTreeForAnyThreadCount) {
    // Large enough that subtrees go to other threads and the top levels are binned over samples.
    const std::vector<Triangle> input = soup(300000, 3);
    std::vector<Triangle> firstTriangles;
    std::vector<BvhNode> firstNodes;
    for (std::uint32_t threads : {1u, 2u, 3u, 8u}) {
        std::vector<Triangle> tris = input;
        std::vector<BvhNode> nodes;
        BvhBuildOptions options;
        options.threads = threads;
        const BvhBuildStats stats = buildBvh(tris, nodes, options);
        EXPECT_EQ(stats.nodeCount, nodes.size());
        if (firstNodes.empty()) {
            firstTriangles = std::move(tris);
            firstNodes = std::move(nodes);
            continue;
        }
        ASSERT_EQ(nodes.size(), firstNodes.size()) << threads << " threads";
        EXPECT_EQ(std::memcmp(nodes.data(), firstNodes.data(), nodes.size() * sizeof(BvhNode)), 0)
            << threads << " threads";
        EXPECT_EQ(std::memcmp(tris.data(), firstTriangles.data(), tris.size() * sizeof(Triangle)),
                  0)
            << threads << " threads";
    }
}

// The exact greedy top-down SAH: at each node, every split between consecutive centroids on
// each axis; the same leaf rules and costs as BvhBuildOptions. Returns the cost summed over
// nodes as area x (traversal or intersection cost); the caller divides by the root's area.
struct Box {
    vec3 lo{1e30f}, hi{-1e30f};
    void grow(const Box& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    double halfArea() const {
        const glm::dvec3 e = glm::dvec3(hi) - glm::dvec3(lo);
        return lo.x > hi.x ? 0.0 : e.x * e.y + e.y * e.z + e.z * e.x;
    }
};

double sweepCost(std::vector<Box>& boxes, size_t begin, size_t end, const BvhBuildOptions& o) {
    const size_t n = end - begin;
    Box all;
    for (size_t i = begin; i < end; ++i)
        all.grow(boxes[i]);
    const double area = all.halfArea(), leafCost = o.intersectionCost * n * area;
    if (n <= o.maxLeafSize)
        return leafCost;
    double best = 1e300;
    int bestAxis = -1;
    size_t bestMid = 0;
    std::vector<double> rightArea(n + 1);
    for (int axis = 0; axis < 3; ++axis) {
        std::sort(boxes.begin() + begin, boxes.begin() + end, [axis](const Box& a, const Box& b) {
            return a.lo[axis] + a.hi[axis] < b.lo[axis] + b.hi[axis];
        });
        Box acc;
        for (size_t k = n; k-- > 1;) {
            acc.grow(boxes[begin + k]);
            rightArea[k] = acc.halfArea();
        }
        acc = Box{};
        for (size_t k = 1; k < n; ++k) {
            acc.grow(boxes[begin + k - 1]);
            const double cost = o.traversalCost * area +
                                o.intersectionCost * (acc.halfArea() * k + rightArea[k] * (n - k));
            if (cost < best)
                best = cost, bestAxis = axis, bestMid = k;
        }
    }
    if (best >= leafCost && n <= o.maxSahLeafSize)
        return leafCost;
    std::sort(boxes.begin() + begin, boxes.begin() + end, [bestAxis](const Box& a, const Box& b) {
        return a.lo[bestAxis] + a.hi[bestAxis] < b.lo[bestAxis] + b.hi[bestAxis];
    });
    return o.traversalCost * area + sweepCost(boxes, begin, begin + bestMid, o) +
           sweepCost(boxes, begin + bestMid, end, o);
}

TEST(BvhParallel, SahWithinFivePercentOfAFullSweep) {
    // The larger two are binned over samples at their top levels (nodes of 16384 or more).
    const std::vector<std::vector<Triangle>> meshes = {soup(20000, 5), terrain(100),
                                                       soup(100000, 6), terrain(250)};
    for (const std::vector<Triangle>& mesh : meshes) {
        std::vector<Box> boxes;
        Box root;
        for (const Triangle& t : mesh) {
            Box b{glm::min(t.p0, glm::min(t.p1, t.p2)), glm::max(t.p0, glm::max(t.p1, t.p2))};
            boxes.push_back(b);
            root.grow(b);
        }
        const BvhBuildOptions options;
        const double sweep = sweepCost(boxes, 0, boxes.size(), options) / root.halfArea();
        std::vector<Triangle> tris = mesh;
        std::vector<BvhNode> nodes;
        const double binned = buildBvh(tris, nodes, options).sahCost;
        std::printf("%zu triangles: SAH cost binned %.4f, full sweep %.4f (%.2f%%)\n",
                    mesh.size(), binned, sweep, 100.0 * (binned / sweep - 1.0));
        EXPECT_LT(binned, 1.05 * sweep);
        EXPECT_GT(binned, 0.9 * sweep); // the sweep is the better greedy method
    }
}

} // namespace
} // namespace wf
