// The builder's trees, walked by the traversal the GPU runs (through CpuBvh), must answer
// every ray exactly as brute force over all triangles with the same intersectTriangle does,
// on random soups and on meshes made of the degenerate cases that break naive builders.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "scene/bvh/bvh_builder.h"
#include "scene/bvh/bvh_cpu.h"
#include "shaders/sampling/sampling.h"

namespace {

using glm::vec3;
using wf::BvhNode;
using wf::Triangle;
using wf::gpu_types::intersectTriangle;
using wf::gpu_types::sampleUniformTriangle;
using wf::gpu_types::triangleHitPoint;

const float INF = std::numeric_limits<float>::infinity();

Triangle makeTriangle(vec3 p0, vec3 p1, vec3 p2) {
    Triangle t{};
    t.p0 = p0;
    t.p1 = p1;
    t.p2 = p2;
    return t;
}

// Closest hit by testing every triangle; hit.t == tMax and no triangle on a miss.
bool bruteClosest(const std::vector<Triangle>& tris, vec3 o, vec3 d, float tMax, float& tBest) {
    tBest = tMax;
    bool found = false;
    for (const Triangle& tri : tris) {
        float t, b1, b2;
        if (intersectTriangle(o, d, tri.p0, tri.p1, tri.p2, tBest, t, b1, b2)) {
            tBest = t;
            found = true;
        }
    }
    return found;
}

// Validates the flattened layout: ranges cover each triangle once, children nest in parents.
void checkStructure(const std::vector<BvhNode>& nodes, const std::vector<Triangle>& tris,
                    const wf::BvhBuildStats& stats) {
    ASSERT_EQ(stats.nodeCount, nodes.size());
    EXPECT_LE(stats.maxDepth, wf::BVH_MAX_DEPTH);
    EXPECT_TRUE(std::isfinite(stats.sahCost));
    std::vector<int> covered(tris.size(), 0);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> stack = {{0u, 0u}}; // node, depth
    std::uint32_t leaves = 0, maxDepth = 0;
    while (!stack.empty()) {
        auto [i, depth] = stack.back();
        stack.pop_back();
        const BvhNode& n = nodes[i];
        maxDepth = std::max(maxDepth, depth);
        if (n.count > 0) {
            ++leaves;
            for (std::uint32_t k = n.rightOrFirst; k < n.rightOrFirst + n.count; ++k) {
                ++covered[k];
                for (vec3 p : {tris[k].p0, tris[k].p1, tris[k].p2}) {
                    EXPECT_TRUE(glm::all(glm::lessThanEqual(n.lo, p)) &&
                                glm::all(glm::lessThanEqual(p, n.hi)));
                }
            }
            continue;
        }
        ASSERT_LT(n.rightOrFirst, nodes.size());
        ASSERT_GT(n.rightOrFirst, i + 1);
        for (std::uint32_t c : {i + 1, n.rightOrFirst}) {
            EXPECT_TRUE(glm::all(glm::lessThanEqual(n.lo, nodes[c].lo)) &&
                        glm::all(glm::lessThanEqual(nodes[c].hi, n.hi)));
            stack.push_back({c, depth + 1});
        }
    }
    EXPECT_EQ(leaves, stats.leafCount);
    EXPECT_EQ(maxDepth, stats.maxDepth);
    for (int c : covered) {
        ASSERT_EQ(c, 1);
    }
}

// Fires `rays` rays from inside and around the mesh's bounds, a third of them along axes or
// in coordinate planes (zero direction components of either sign), some starting exactly on
// the planes z = k the sheet meshes use, some aimed at a triangle, and compares CpuBvh with
// brute force. t must match exactly unless `coplanar`: overlapping coplanar triangles report
// t differing in the last bits (Möller-Trumbore's error grows as 1 / cos at grazing angles),
// and a box whose rounded entry distance lies between two of them is rightly pruned.
void compareWithBruteForce(std::vector<Triangle> tris, int rays, std::uint32_t seed,
                           bool coplanar = false, const wf::BvhBuildOptions& opts = {}) {
    std::vector<BvhNode> nodes;
    wf::BvhBuildStats stats = wf::buildBvh(tris, nodes, opts);
    checkStructure(nodes, tris, stats);
    wf::CpuBvh bvh(nodes, tris);

    vec3 lo(INF), hi(-INF);
    for (const Triangle& t : tris) {
        lo = glm::min(lo, glm::min(t.p0, glm::min(t.p1, t.p2)));
        hi = glm::max(hi, glm::max(t.p0, glm::max(t.p1, t.p2)));
    }
    vec3 margin = 0.2f * (hi - lo) + vec3(0.1f);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::normal_distribution<float> gauss;
    int hits = 0, exact = 0;
    for (int r = 0; r < rays; ++r) {
        vec3 u(uniform(rng), uniform(rng), uniform(rng));
        vec3 o = lo - margin + (hi - lo + 2.0f * margin) * u;
        if (r % 5 == 0) {
            o.z = std::round(o.z); // on a sheet's plane
        }
        vec3 d(gauss(rng), gauss(rng), gauss(rng));
        int kind = r % 6;
        if (kind == 3 || kind == 5) { // aimed at a random point of a random triangle
            const Triangle& target = tris[rng() % tris.size()];
            glm::vec2 b = sampleUniformTriangle(glm::vec2(uniform(rng), uniform(rng)));
            d = triangleHitPoint(target.p0, target.p1, target.p2, b.x, b.y) - o;
        }
        if (kind == 1) { // along an axis, either sign
            int a = int(uniform(rng) * 3.0f) % 3;
            float s = d[a] < 0.0f ? -1.0f : 1.0f;
            d = vec3(uniform(rng) < 0.5f ? 0.0f : -0.0f);
            d[a] = s;
        } else if (kind == 2) { // in a coordinate plane
            d[int(uniform(rng) * 3.0f) % 3] = uniform(rng) < 0.5f ? 0.0f : -0.0f;
        }
        if (glm::length(d) == 0.0f) {
            d = vec3(0.0f, 0.0f, 1.0f);
        }
        float tMax = (r % 4 == 3) ? uniform(rng) * glm::length(hi - lo) : INF;

        float tBrute;
        bool bruteHit = bruteClosest(tris, o, d, tMax, tBrute);
        wf::HitRecord hit;
        bool bvhHit = bvh.traceClosest(o, d, tMax, hit);
        ASSERT_EQ(bvhHit, bruteHit) << "ray " << r;
        ASSERT_EQ(bvh.traceAny(o, d, tMax), bruteHit) << "ray " << r;
        if (!bvhHit) {
            EXPECT_EQ(hit.triangle, WF_NO_TRIANGLE);
            continue;
        }
        ++hits;
        ASSERT_LT(hit.triangle, tris.size());
        const Triangle& tri = tris[hit.triangle];
        if (coplanar) {
            vec3 n = glm::normalize(glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0));
            float cosine = std::abs(glm::dot(n, glm::normalize(d)));
            ASSERT_NEAR(hit.t, tBrute, 1e-5f * tBrute / cosine) << "ray " << r;
            exact += hit.t == tBrute;
        } else {
            ASSERT_EQ(hit.t, tBrute) << "ray " << r;
        }
        float t, b1, b2;
        ASSERT_TRUE(intersectTriangle(o, d, tri.p0, tri.p1, tri.p2, INF, t, b1, b2));
        EXPECT_EQ(t, hit.t);
        EXPECT_EQ(b1, hit.b1);
        EXPECT_EQ(b2, hit.b2);
    }
    EXPECT_GT(hits, rays / 20) << "too few hits for the comparison to mean much";
    // The bound the host uses to choose the register stack is never exceeded.
    EXPECT_LE(bvh.deepestStack(), bvh.stackNeed());
    if (coplanar) {
        std::printf("coplanar mesh: %d of %d hits have exactly the brute-force t\n", exact, hits);
    }
}

std::vector<Triangle> randomSoup(int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-10.0f, 10.0f);
    std::uniform_real_distribution<float> logSize(-2.0f, 0.5f);
    std::vector<Triangle> tris;
    for (int i = 0; i < count; ++i) {
        vec3 c(pos(rng), pos(rng), pos(rng));
        float s = std::pow(10.0f, logSize(rng));
        auto corner = [&] { return c + s * vec3(pos(rng), pos(rng), pos(rng)) * 0.1f; };
        tris.push_back(makeTriangle(corner(), corner(), corner()));
    }
    return tris;
}

// Zero-area, collinear, duplicated, coincident-centroid, axis-aligned sheets and coplanar
// overlapping triangles, shuffled together.
std::vector<Triangle> degenerateMesh(std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-4.0f, 4.0f);
    auto dyadic = [&] { return std::round(pos(rng) * 64.0f) / 64.0f; };
    std::vector<Triangle> tris;
    for (int i = 0; i < 300; ++i) { // two equal vertices; all three equal
        vec3 a(pos(rng), pos(rng), pos(rng)), b(pos(rng), pos(rng), pos(rng));
        tris.push_back(makeTriangle(a, a, b));
        tris.push_back(makeTriangle(b, b, b));
    }
    for (int i = 0; i < 300; ++i) { // exactly collinear: dyadic points, exact arithmetic
        vec3 a(dyadic(), dyadic(), dyadic()), v(dyadic(), dyadic(), dyadic());
        tris.push_back(makeTriangle(a, a + 0.25f * v, a + 0.5f * v));
    }
    Triangle dup = makeTriangle(vec3(-1, -1, 0.5f), vec3(1, -1, 0.7f), vec3(0, 1, 0.6f));
    for (int i = 0; i < 500; ++i) {
        tris.push_back(dup);
    }
    for (int i = 0; i < 200; ++i) { // same centroid, different orientations
        vec3 e(pos(rng), pos(rng), pos(rng));
        tris.push_back(makeTriangle(vec3(1.5f) + e, vec3(1.5f) - e, vec3(1.5f)));
    }
    for (int z = -3; z <= 3; ++z) { // axis-aligned grid sheets at z = k
        for (int x = -4; x < 4; ++x) {
            for (int y = -4; y < 4; ++y) {
                vec3 p{float(x), float(y), float(z)};
                vec3 px = p + vec3(1, 0, 0), py = p + vec3(0, 1, 0);
                tris.push_back(makeTriangle(p, px, py));
                tris.push_back(makeTriangle(px, p + vec3(1, 1, 0), py));
            }
        }
    }
    std::shuffle(tris.begin(), tris.end(), rng);
    return tris;
}

TEST(Bvh, RandomSoupsMatchBruteForce) {
    compareWithBruteForce(randomSoup(1000, 1u), 4000, 11u);
    compareWithBruteForce(randomSoup(10000, 2u), 3000, 12u);
}

// Nodes of 16384 refs or more are binned over a sample and take their children's boxes from
// the partition: every box must still bound its triangles, and traversal find every hit. Trees
// of 65536 nodes or more are paired on several threads (the second soup).
TEST(Bvh, SampledTopLevelsMatchBruteForce) {
    compareWithBruteForce(randomSoup(100000, 4u), 1000, 14u);
    compareWithBruteForce(randomSoup(200000, 5u), 300, 15u);
}

TEST(Bvh, DegenerateMeshMatchesBruteForce) {
    compareWithBruteForce(degenerateMesh(3u), 6000, 13u);
}

TEST(Bvh, AllTrianglesInOnePlane) {
    std::mt19937 rng(4u);
    std::uniform_real_distribution<float> pos(-5.0f, 5.0f);
    std::vector<Triangle> flat, tilted;
    for (int i = 0; i < 2000; ++i) {
        vec3 a(pos(rng), pos(rng), 0.0f), b(pos(rng), pos(rng), 0.0f), c(pos(rng), pos(rng), 0.0f);
        flat.push_back(makeTriangle(a, b, c));
        // The same triangles lifted onto the tilted plane z = x + 2y (up to rounding).
        auto lift = [](vec3 p) { return vec3(p.x, p.y, p.x + 2.0f * p.y); };
        tilted.push_back(makeTriangle(lift(a), lift(b), lift(c)));
    }
    compareWithBruteForce(flat, 4000, 14u, true);
    compareWithBruteForce(tilted, 4000, 15u, true);
}

TEST(Bvh, DepthStaysBoundedOnExponentialSpacing) {
    // Centroids at 1.01^i: every SAH split peels off only the last few triangles, which would
    // need thousands of levels without the median fallback.
    std::vector<Triangle> tris;
    for (int i = 0; i < 5000; ++i) {
        float x = std::pow(1.01f, float(i));
        tris.push_back(makeTriangle(vec3(x, 0, 0), vec3(x, 1, 0), vec3(x, 0, 1)));
    }
    std::vector<BvhNode> nodes;
    std::vector<Triangle> copy = tris;
    wf::BvhBuildStats stats = wf::buildBvh(copy, nodes);
    checkStructure(nodes, copy, stats);
    EXPECT_LE(stats.maxDepth, wf::BVH_MAX_DEPTH);
    compareWithBruteForce(tris, 2000, 16u);
}

TEST(Bvh, EmptyScene) {
    std::vector<Triangle> tris;
    std::vector<BvhNode> nodes;
    wf::BvhBuildStats stats = wf::buildBvh(tris, nodes);
    ASSERT_EQ(nodes.size(), 1u);
    EXPECT_EQ(stats.nodeCount, 1u);
    EXPECT_EQ(stats.sahCost, 0.0);
    wf::CpuBvh bvh(nodes, tris);
    wf::HitRecord hit;
    for (vec3 d : {vec3(1, 0, 0), vec3(0, 0, -1), vec3(0.3f, -0.4f, 0.5f), vec3(0.0f)}) {
        EXPECT_FALSE(bvh.traceClosest(vec3(0.0f), d, INF, hit));
        EXPECT_EQ(hit.triangle, WF_NO_TRIANGLE);
        EXPECT_FALSE(bvh.traceAny(vec3(0.0f), d, INF));
    }
}

TEST(Bvh, SingleTriangle) {
    std::vector<Triangle> tris = {makeTriangle(vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0))};
    std::vector<BvhNode> nodes;
    wf::BvhBuildStats stats = wf::buildBvh(tris, nodes);
    ASSERT_EQ(nodes.size(), 1u);
    EXPECT_EQ(nodes[0].count, 1u);
    EXPECT_EQ(stats.leafCount, 1u);
    wf::CpuBvh bvh(nodes, tris);
    wf::HitRecord hit;
    ASSERT_TRUE(bvh.traceClosest(vec3(0.25f, 0.25f, 1.0f), vec3(0, 0, -1), INF, hit));
    EXPECT_EQ(hit.t, 1.0f);
    EXPECT_EQ(hit.triangle, 0u);
    EXPECT_FALSE(bvh.traceAny(vec3(0.25f, 0.25f, 1.0f), vec3(0, 0, -1), 1.0f)); // t < tMax
    EXPECT_FALSE(bvh.traceAny(vec3(0.25f, 0.25f, 1.0f), vec3(0, 0, 1), INF));
    compareWithBruteForce(tris, 2000, 17u);
}

// A depth limit far too small forces leaves of hundreds of triangles (the root itself with
// maxDepth 0); pairing splits them into references traversal can hold, hitting all the same.
TEST(Bvh, OversizedLeavesAreSplitForTraversal) {
    for (std::uint32_t maxDepth : {0u, 2u}) {
        wf::BvhBuildOptions opts;
        opts.maxDepth = maxDepth;
        std::vector<Triangle> tris = randomSoup(1000, 5u);
        std::vector<BvhNode> nodes;
        wf::buildBvh(tris, nodes, opts);
        std::uint32_t biggest = 0;
        for (const BvhNode& n : nodes)
            biggest = std::max(biggest, n.count);
        EXPECT_GT(biggest, WF_BVH_MAX_LEAF_COUNT) << "maxDepth " << maxDepth;
        std::uint32_t referenced = 0; // each triangle in exactly one leaf reference
        for (const wf::BvhPair& pair : wf::pairBvhNodes(nodes))
            for (std::uint32_t child : {pair.child0, pair.child1})
                if (child != WF_BVH_NO_CHILD)
                    referenced += child & WF_BVH_MAX_LEAF_COUNT;
        EXPECT_EQ(referenced, tris.size()) << "maxDepth " << maxDepth;
        compareWithBruteForce(randomSoup(1000, 5u), 3000, 18u + maxDepth, false, opts);
    }
}

// The need is the depth in "both children interior" levels: a balanced tree of 2^k well-apart
// clusters of 4 triangles (one leaf each) needs k - 1 entries, and some ray reaches them all.
TEST(Bvh, StackNeedOfABalancedTree) {
    for (std::uint32_t k : {1u, 3u, 6u}) {
        std::vector<Triangle> tris;
        for (std::uint32_t c = 0; c < (1u << k); ++c) {
            vec3 base(10.0f * float(c), 0.0f, 0.0f);
            for (int i = 0; i < 4; ++i) {
                vec3 p = base + vec3(0.1f * float(i), 0.0f, 0.0f);
                tris.push_back(makeTriangle(p, p + vec3(0, 1, 0), p + vec3(0, 0, 1)));
            }
        }
        std::vector<BvhNode> nodes;
        wf::BvhBuildStats stats = wf::buildBvh(tris, nodes);
        EXPECT_EQ(stats.maxDepth, k);
        wf::CpuBvh bvh(nodes, tris);
        EXPECT_EQ(bvh.stackNeed(), k - 1);
        // A ray along the row enters every cluster's box and misses every triangle (y + z > 1):
        // the traversal fills the stack.
        EXPECT_FALSE(bvh.traceAny(vec3(-5.0f, 0.9f, 0.9f), vec3(1, 0, 0), INF));
        EXPECT_EQ(bvh.deepestStack(), k - 1);
    }
    std::vector<Triangle> one = {makeTriangle(vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0))};
    std::vector<BvhNode> nodes;
    wf::buildBvh(one, nodes);
    EXPECT_EQ(wf::bvhStackNeed(wf::pairBvhNodes(nodes)), 0u);
}

// The register stack is a stack: last in, first out, over its 8 or 16 entries; one push past
// the capacity loses the bottom entry and nothing else.
TEST(Bvh, RegisterStackIsLastInFirstOut) {
    using namespace wf::gpu_types;
    for (uint capacity : {8u, 16u}) {
        BvhRegisterStack stack = bvhRegisterStack();
        for (uint i = 0; i <= capacity; ++i)
            bvhRegisterPush(stack, 100u + i, capacity);
        for (uint i = capacity + 1; i-- > 1;) {
            EXPECT_EQ(stack.pairs0.x, 100u + i) << "capacity " << capacity;
            bvhRegisterPop(stack, capacity);
        }
        EXPECT_EQ(stack.pairs0.x, 0u) << "capacity " << capacity;
    }
}

} // namespace
