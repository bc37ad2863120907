// The light tree on the CPU, through the traversal code the shade pass runs: its pmf sums to 1
// at any point, sampling draws each light as often as that pmf says (chi-square over lights),
// the pmf sampling returns is the one a BSDF hit replays from the light's trail, and no light
// that can reach a point is ever given probability 0 there.
#include <random>

#include <gtest/gtest.h>

#include "chi_square.h"
#include "scene/lights/light_table.h"
#include "scene/lights/light_tree.h"

namespace wf {
namespace {

using gpu_types::LightTreeTraversal;

struct TreeScene {
    std::vector<Triangle> triangles;
    std::vector<Material> materials;
    std::vector<PunctualLight> lights;
    LightTable table;
    LightTree tree;
};

// Emissive triangles of random size, orientation and power (one material in three
// double-sided), sphere, point and spot lights, and a directional light beside the tree.
TreeScene randomScene(uint32_t triangles, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    auto point = [&](float extent) {
        return glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f) * extent;
    };
    TreeScene s;
    for (int m = 0; m < 6; ++m) {
        Material material{};
        material.emission = glm::vec3(std::pow(100.0f, u(rng)));
        material.flags = m % 3 == 0 ? WF_MATERIAL_DOUBLE_SIDED : 0u;
        s.materials.push_back(material);
    }
    for (uint32_t i = 0; i < triangles; ++i) {
        const glm::vec3 c = point(10.0f), size = glm::vec3(0.05f + 0.5f * u(rng));
        s.triangles.push_back({c + point(1.0f) * size, i % 6, c + point(1.0f) * size,
                               WF_NO_EMITTER, c + point(1.0f) * size, 0});
    }
    for (uint32_t i = 0; i < 12; ++i) {
        PunctualLight light{};
        light.type = i % 3 == 0 ? WF_LIGHT_SPHERE : (i % 3 == 1 ? WF_LIGHT_POINT : WF_LIGHT_SPOT);
        light.position = point(10.0f);
        light.radius = 0.2f * u(rng);
        light.intensity = glm::vec3(1.0f + 10.0f * u(rng));
        light.direction = glm::normalize(point(1.0f) + glm::vec3(1e-3f));
        light.cosInner = 0.9f;
        light.cosOuter = 0.6f;
        s.lights.push_back(light);
    }
    PunctualLight sun{};
    sun.type = WF_LIGHT_DIRECTIONAL;
    sun.direction = glm::vec3(0, -1, 0);
    sun.intensity = glm::vec3(1.0f);
    s.lights.push_back(sun);
    SceneBounds bounds = sceneBounds(s.triangles, s.lights);
    s.table = buildLightTable(s.triangles, s.materials, s.lights, Environment{}, bounds);
    s.tree = buildLightTree(s.table, s.triangles, s.materials, s.lights);
    return s;
}

std::vector<glm::vec3> probePoints(uint32_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<glm::vec3> points;
    for (uint32_t i = 0; i < count; ++i) // inside the lights' box and out to 4x beyond it
        points.push_back(glm::vec3(u(rng), u(rng), u(rng)) * (i % 2 ? 6.0f : 20.0f));
    return points;
}

// The receiver normal at probe point i: none (light from both sides) for one in three, else a
// fixed pseudo-random direction as the shade pass stores it.
glm::vec3 probeNormal(uint32_t i) {
    if (i % 3 == 0)
        return glm::vec3(0.0f);
    const glm::vec3 d(std::sin(1.7f * i + 0.3f), std::cos(2.9f * i), std::sin(0.7f * i - 1.0f));
    return gpu_types::decodeReceiverNormal(gpu_types::encodeReceiverNormal(glm::normalize(d)));
}

TEST(LightTree, ReceiverNormalSurvivesItsEncoding) {
    for (uint32_t i = 1; i < 200; ++i) {
        if (i % 3 == 0)
            continue;
        const glm::vec3 d = glm::normalize(
            glm::vec3(std::sin(1.7f * i + 0.3f), std::cos(2.9f * i), std::sin(0.7f * i - 1.0f)));
        const float encoded = gpu_types::encodeReceiverNormal(d);
        EXPECT_EQ(encoded, std::floor(encoded));
        EXPECT_LE(encoded, 16777216.0f); // exact in a float
        EXPECT_GT(glm::dot(gpu_types::decodeReceiverNormal(encoded), d), 0.99999f);
    }
    EXPECT_EQ(gpu_types::decodeReceiverNormal(0.0f), glm::vec3(0.0f));
}

TEST(LightTree, HoldsEveryLightButTheDirectionalOnes) {
    TreeScene s = randomScene(300, 1);
    EXPECT_EQ(s.tree.lights, 312u);
    EXPECT_EQ(s.tree.nodes.size(), 2u * 312u - 1u);
    EXPECT_LE(s.tree.depth, WF_LIGHT_TREE_MAX_DEPTH);
    uint32_t inTree = 0;
    for (uint32_t e = 0; e < s.table.emitters.size(); ++e) {
        const bool member = inLightTree(s.table.emitters[e].source, s.lights);
        EXPECT_EQ(s.tree.trails[e].z, member ? 1u : 0u) << "emitter " << e;
        inTree += member ? 1u : 0u;
    }
    EXPECT_EQ(inTree, s.tree.lights);
}

TEST(LightTree, PmfSumsToOneAndSamplingReturnsTheTrailsPmf) {
    TreeScene s = randomScene(300, 2);
    LightTreeTraversal walk{&s.tree.nodes};
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const std::vector<glm::vec3> points = probePoints(40, 3);
    for (uint32_t i = 0; i < points.size(); ++i) {
        const glm::vec3 p = points[i], n = probeNormal(i);
        double sum = 0.0;
        for (uint32_t e = 0; e < s.tree.trails.size(); ++e)
            if (s.tree.trails[e].z)
                sum += walk.lightTreePmf(p, n, glm::uvec2(s.tree.trails[e]));
        EXPECT_NEAR(sum, 1.0, 1e-4) << "at " << p.x << " " << p.y << " " << p.z;
        for (int k = 0; k < 200; ++k) {
            float pmf = 0.0f;
            const uint32_t e = walk.lightTreeSample(p, n, u(rng), pmf);
            ASSERT_NE(e, WF_LIGHT_TREE_LEAF);
            ASSERT_EQ(s.tree.trails[e].z, 1u);
            EXPECT_FLOAT_EQ(pmf, walk.lightTreePmf(p, n, glm::uvec2(s.tree.trails[e])));
        }
    }
}

TEST(LightTree, SamplingMatchesPmfByChiSquare) {
    TreeScene s = randomScene(60, 4);
    LightTreeTraversal walk{&s.tree.nodes};
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const int samples = 200000;
    const std::vector<glm::vec3> points = probePoints(6, 5);
    for (uint32_t i = 0; i < points.size(); ++i) {
        const glm::vec3 p = points[i], n = probeNormal(i);
        std::vector<double> observed(s.tree.trails.size(), 0.0), expected(observed.size(), 0.0);
        for (uint32_t e = 0; e < observed.size(); ++e)
            if (s.tree.trails[e].z)
                expected[e] = samples * walk.lightTreePmf(p, n, glm::uvec2(s.tree.trails[e]));
        for (int k = 0; k < samples; ++k) {
            float pmf = 0.0f;
            observed[walk.lightTreeSample(p, n, u(rng), pmf)] += 1.0;
        }
        EXPECT_GT(test::chiSquarePValue(observed, expected), 1e-4)
            << "at " << p.x << " " << p.y << " " << p.z;
    }
}

// Unbiasedness needs every light that can send p something to have a positive pmf there:
// triangles that face p, and spots whose outer cone holds it (spheres and points always).
TEST(LightTree, NoReachableLightGetsProbabilityZero) {
    TreeScene s = randomScene(300, 6);
    LightTreeTraversal walk{&s.tree.nodes};
    int reachable = 0, unreachableWithWeight = 0;
    // Random points, and points just in front of triangles, far along their planes: there the
    // cones and the boxes' extent decide.
    std::vector<glm::vec3> points = probePoints(60, 7);
    for (uint32_t i = 0; i < 60; ++i) {
        const Triangle& t = s.triangles[i];
        const glm::vec3 n = glm::normalize(glm::cross(t.p1 - t.p0, t.p2 - t.p0));
        points.push_back((t.p0 + t.p1 + t.p2) / 3.0f + 0.01f * n + 3.0f * (t.p1 - t.p0));
    }
    for (uint32_t i = 0; i < points.size(); ++i) {
        const glm::vec3 p = points[i], n = probeNormal(i);
        // Light can reach p only from the side n faces (n = 0: either side).
        auto above = [&](glm::vec3 q) { return glm::dot(n, q - p) > 0.0f || n == glm::vec3(0); };
        for (uint32_t e = 0; e < s.table.emitters.size(); ++e) {
            if (!s.tree.trails[e].z)
                continue;
            const uint32_t source = s.table.emitters[e].source;
            const uint32_t index = source & WF_EMITTER_INDEX_MASK;
            bool reaches = true;
            if ((source & WF_EMITTER_KIND_MASK) == WF_EMITTER_TRIANGLE) {
                const Triangle& t = s.triangles[index];
                const float side = glm::dot(glm::cross(t.p1 - t.p0, t.p2 - t.p0), p - t.p0);
                reaches = (side > 0.0f ||
                           (s.materials[t.material].flags & WF_MATERIAL_DOUBLE_SIDED) != 0u) &&
                          (above(t.p0) || above(t.p1) || above(t.p2));
            } else {
                const PunctualLight& l = s.lights[index];
                const float radius = l.type == WF_LIGHT_SPHERE ? l.radius : 0.0f;
                reaches = above(l.position + radius * n); // the sphere's point nearest n's side
                if (l.type == WF_LIGHT_SPOT)
                    reaches = reaches &&
                              glm::dot(glm::normalize(p - l.position), l.direction) > l.cosOuter;
            }
            const float pmf = walk.lightTreePmf(p, n, glm::uvec2(s.tree.trails[e]));
            if (reaches) {
                ++reachable;
                EXPECT_GT(pmf, 0.0f) << "emitter " << e << " at " << p.x << " " << p.y << " "
                                     << p.z;
            } else if (pmf > 0.0f) {
                ++unreachableWithWeight;
            }
        }
    }
    EXPECT_GT(reachable, 1000);
    // The bounds are conservative, not exact: some lights that cannot reach p keep a weight,
    // but the orientation cones must cull some of them.
    EXPECT_LT(unreachableWithWeight, reachable);
}

TEST(LightTree, OneLightOrNoneMakesNoTree) {
    TreeScene s = randomScene(0, 8);
    s.lights.resize(1); // one sphere
    s.table = buildLightTable(s.triangles, s.materials, s.lights, Environment{},
                              sceneBounds(s.triangles, s.lights));
    s.tree = buildLightTree(s.table, s.triangles, s.materials, s.lights);
    EXPECT_EQ(s.tree.lights, 1u);
    EXPECT_EQ(s.tree.nodes.size(), 1u);
    LightTreeTraversal walk{&s.tree.nodes};
    float pmf = 0.0f;
    EXPECT_EQ(walk.lightTreeSample(glm::vec3(100.0f), glm::vec3(0.0f), 0.5f, pmf), 0u);
    EXPECT_EQ(pmf, 1.0f);
}

} // namespace
} // namespace wf

namespace wf {
namespace {

// Motion blur: a light's keys over the shutter (light.motion = 1 + its first key) widen its
// leaf and so the root to cover every key, so that no receiver ever gives zero importance to a
// light that reaches it at some time within the shutter.
TEST(LightTree, MovingLightsBoundsCoverEveryKey) {
    std::vector<Triangle> triangles;
    std::vector<Material> materials(1);
    std::vector<PunctualLight> lights;
    for (int i = 0; i < 4; ++i) {
        PunctualLight light{};
        light.type = WF_LIGHT_SPHERE;
        light.position = glm::vec3(float(i), 0.0f, 0.0f);
        light.radius = 0.1f;
        light.intensity = glm::vec3(1.0f);
        lights.push_back(light);
    }
    const uint32_t segments = 2;
    std::vector<glm::vec4> keys = {{3, 0, 0, 1}, {3, 5, 0, 1}, {3, 9, -4, 1}};
    const SceneBounds bounds = sceneBounds(triangles, lights);
    const LightTable table = buildLightTable(triangles, materials, lights, Environment{}, bounds);
    const LightTree still = buildLightTree(table, triangles, materials, lights);
    lights[3].motion = 1; // keys 0 .. 2
    const LightTree moving = buildLightTree(table, triangles, materials, lights, keys, segments);
    ASSERT_FALSE(moving.nodes.empty());
    EXPECT_LT(still.nodes[0].hi.y, 1.0f);
    for (const glm::vec4& key : keys) {
        EXPECT_LE(moving.nodes[0].lo.x, key.x - 0.1f);
        EXPECT_GE(moving.nodes[0].hi.y, key.y + 0.1f - 1e-4f);
        EXPECT_LE(moving.nodes[0].lo.z, key.z - 0.1f + 1e-4f);
    }
}

} // namespace
} // namespace wf
