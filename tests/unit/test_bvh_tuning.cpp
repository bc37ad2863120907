// The per-scene choice of the SAH traversal cost (bvh_tuning.h): its sample is deterministic,
// it keeps the candidate its model scores cheapest, the tree it keeps still answers every ray
// exactly, and large scenes keep the default without the extra builds.
#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <vector>

#include "scene/bvh/bvh_cpu.h"
#include "scene/bvh/bvh_tuning.h"
#include "scene/gltf/gltf_loader.h"
#include "shaders/traversal/geometry.h"

namespace {

using glm::vec3;
using wf::BvhNode;
using wf::Triangle;

std::vector<Triangle> soup(int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-5.0f, 5.0f), edge(-0.3f, 0.3f);
    std::vector<Triangle> tris;
    for (int i = 0; i < count; ++i) {
        Triangle t{};
        t.p0 = vec3(pos(rng), pos(rng), pos(rng));
        t.p1 = t.p0 + vec3(edge(rng), edge(rng), edge(rng));
        t.p2 = t.p0 + vec3(edge(rng), edge(rng), edge(rng));
        tris.push_back(t);
    }
    return tris;
}

wf::Camera cameraAt(vec3 position, vec3 target) {
    wf::Camera camera;
    camera.position = position;
    camera.forward = glm::normalize(target - position);
    camera.up = glm::normalize(glm::cross(glm::cross(camera.forward, vec3(0, 1, 0)),
                                          camera.forward));
    return camera;
}

// The cost simdTraversalWork gives the tree buildBvh makes with this traversal cost.
double candidateCost(std::vector<Triangle> tris, const std::vector<wf::Material>& materials,
                     const wf::Camera& camera, float traversalCost) {
    wf::BvhBuildOptions options;
    options.traversalCost = traversalCost;
    options.fewerBinsForSmallNodes = false; // as buildTunedBvh builds its candidates
    std::vector<BvhNode> nodes;
    wf::buildBvh(tris, nodes, options);
    return wf::simdTraversalWork(nodes, tris, materials, camera).cost();
}

void expectCheapestAndExact(const std::vector<Triangle>& input,
                            const std::vector<wf::Material>& materials,
                            const wf::Camera& camera) {
    std::vector<Triangle> tris = input;
    std::vector<BvhNode> nodes;
    const wf::BvhBuildStats stats = wf::buildTunedBvh(tris, nodes, materials, camera);
    double best = std::numeric_limits<double>::infinity();
    float bestCost = 0.0f;
    for (float cost : wf::kTunedTraversalCosts) {
        const double c = candidateCost(input, materials, camera, cost);
        if (c < best)
            best = c, bestCost = cost;
    }
    EXPECT_EQ(stats.traversalCost, bestCost);
    EXPECT_EQ(wf::simdTraversalWork(nodes, tris, materials, camera).cost(), best);
    EXPECT_EQ(stats.nodeCount, nodes.size());

    // The kept tree answers rays as brute force does.
    const wf::CpuBvh bvh(nodes, tris);
    std::mt19937 rng(3u);
    std::normal_distribution<float> gauss;
    for (int r = 0; r < 2000; ++r) {
        const vec3 o = camera.position + vec3(gauss(rng), gauss(rng), gauss(rng));
        const vec3 d(gauss(rng), gauss(rng), gauss(rng));
        float closest = std::numeric_limits<float>::infinity();
        for (const Triangle& t : tris) {
            float tHit, b1, b2;
            if (wf::gpu_types::intersectTriangle(o, d, t.p0, t.p1, t.p2, closest, tHit, b1, b2))
                closest = tHit;
        }
        wf::HitRecord hit;
        const bool found = bvh.traceClosest(o, d, std::numeric_limits<float>::infinity(), hit);
        ASSERT_EQ(found, closest < std::numeric_limits<float>::infinity()) << "ray " << r;
        if (found)
            ASSERT_EQ(hit.t, closest) << "ray " << r;
    }
}

TEST(BvhTuning, TheSampleIsDeterministic) {
    std::vector<Triangle> tris = soup(500, 1u);
    std::vector<BvhNode> nodes;
    wf::buildBvh(tris, nodes);
    const wf::Camera camera = cameraAt(vec3(0, 0, 12), vec3(0));
    const wf::SimdTraversalWork a = wf::simdTraversalWork(nodes, tris, {}, camera);
    const wf::SimdTraversalWork b = wf::simdTraversalWork(nodes, tris, {}, camera);
    EXPECT_GT(a.steps, 0.0);
    EXPECT_GE(a.triangleIterations, a.steps); // the triangle loop runs at least once a step
    EXPECT_EQ(a.steps, b.steps);
    EXPECT_EQ(a.triangleIterations, b.triangleIterations);
    const wf::SimdTraversalWork other = wf::simdTraversalWork(nodes, tris, {}, camera, 32, 2u);
    EXPECT_NE(a.steps + a.triangleIterations, other.steps + other.triangleIterations);
    EXPECT_EQ(wf::simdTraversalWork({}, {}, {}, camera).cost(), 0.0);
}

TEST(BvhTuning, KeepsTheCheapestCandidateOnTheCornellBox) {
    const wf::Scene scene = wf::loadGltf(WF_TEST_SCENE_DIR "/cornell_box.gltf");
    expectCheapestAndExact(scene.triangles, scene.materials, scene.camera);
}

TEST(BvhTuning, KeepsTheCheapestCandidateOnASoup) {
    expectCheapestAndExact(soup(3000, 2u), {}, cameraAt(vec3(0, 0, 12), vec3(0)));
}

TEST(BvhTuning, LargeScenesKeepTheDefault) {
    std::vector<Triangle> tris = soup(int(wf::kMaxTunedTriangles) + 1, 4u);
    std::vector<BvhNode> nodes;
    const wf::BvhBuildStats stats =
        wf::buildTunedBvh(tris, nodes, {}, cameraAt(vec3(0, 0, 12), vec3(0)));
    EXPECT_EQ(stats.traversalCost, wf::kTunedTraversalCosts[0]);
}

} // namespace
