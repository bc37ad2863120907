// Instanced meshes (issue 14): which meshes the loader instances, and the two-level traversal
// the GPU runs (bvh_traverse.h), on the CPU, against brute force over the flattened copy of the
// same file: the same closest hits and the same front faces, through rotated, mirrored and
// non-uniformly scaled placements.
#include <gtest/gtest.h>

#include <random>

#include "instanced_scene.h"
#include "scene/gltf/gltf_loader.h"
#include "scene/bvh/instance_bvh.h"
#include "shaders/traversal/bvh_traverse.h"

namespace wf {
namespace {

using test::TempDir;

Scene load(const std::string& path, Instancing mode, std::vector<std::string>* warnings = nullptr) {
    GltfOptions options;
    options.instancing = mode;
    std::vector<std::string> ignored;
    return loadGltf(path, warnings ? warnings : &ignored, options);
}

TEST(Instancing, LoaderKeepsAMeshPlacedThriceOnce) {
    TempDir dir;
    const std::string path = test::writeInstancedScene(dir);
    const Scene flat = load(path, Instancing::Off);
    const Scene instanced = load(path, Instancing::On);
    ASSERT_TRUE(flat.meshes.empty());
    ASSERT_EQ(instanced.meshes.size(), 1u);
    ASSERT_EQ(instanced.placements.size(), 3u);
    const uint32_t blob = instanced.meshes[0].triangleCount;
    EXPECT_EQ(instanced.worldTriangleCount(), 4u); // the floor's and the lamp's two each
    EXPECT_EQ(instanced.triangles.size(), 4u + blob);
    EXPECT_EQ(flat.triangles.size(), 4u + 3u * blob);
    EXPECT_EQ(instanced.instancedTriangleCount(), flat.triangles.size());
    EXPECT_EQ(instanced.surface.normals.size(), instanced.triangles.size());
    // Auto instances only where the copies would be large: this blob is flattened.
    EXPECT_TRUE(load(path, Instancing::Auto).meshes.empty());
    // Placed boxes hold the placed triangles (boxes of boxes: not tight).
    const Bounds a = triangleBounds(flat), b = triangleBounds(instanced);
    for (int k = 0; k < 3; ++k) {
        EXPECT_LE(b.lo[k], a.lo[k] + 1e-5f);
        EXPECT_GE(b.hi[k], a.hi[k] - 1e-5f);
        EXPECT_LT(b.hi[k] - b.lo[k], 1.5f * (a.hi[k] - a.lo[k]));
    }
}

TEST(Instancing, EmissiveMeshesAreFlattenedAndZeroScalesSkipped) {
    TempDir dir;
    const std::string glowing = test::writeInstancedScene(
        dir, R"({"emissiveFactor":[1,0.5,0.2],"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1]}})");
    EXPECT_TRUE(load(glowing, Instancing::On).meshes.empty()); // each copy a light of its own

    test::MiniGltf g;
    g.addMesh(g.addPositions({0, 0, 0, 1, 0, 0, 0, 1, 0}));
    g.nodes = {R"({"mesh":0})", R"({"mesh":0,"scale":[1,0,1]})", R"({"mesh":0,"translation":[3,0,0]})"};
    g.scenes = R"([{"nodes":[0,1,2]}])";
    std::vector<std::string> warnings;
    const Scene scene = load(g.write(dir, "flat.gltf"), Instancing::On, &warnings);
    EXPECT_EQ(scene.placements.size(), 2u);
    bool warned = false;
    for (const std::string& line : warnings)
        warned |= line.find("zero or overflowing scale") != std::string::npos;
    EXPECT_TRUE(warned);
}

// The world-space unit normal of a hit's triangle on the side the file calls front.
glm::vec3 frontNormal(const Triangle& t, const Instance* instance) {
    glm::vec3 p[3] = {t.p0, t.p1, t.p2};
    if (instance)
        for (glm::vec3& q : p)
            q = gpu_types::affinePoint(instance->worldFromObject0, instance->worldFromObject1,
                                       instance->worldFromObject2, q);
    const glm::vec3 n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    return instance && (instance->flags & WF_INSTANCE_MIRRORED) ? -n : n;
}

TEST(Instancing, TwoLevelTraversalMatchesBruteForceOverTheFlattenedCopy) {
    TempDir dir;
    const std::string path = test::writeInstancedScene(dir);
    const Scene flat = load(path, Instancing::Off);
    Scene instanced = load(path, Instancing::On);
    TwoLevelBvh bvh = buildTwoLevelBvh(instanced.triangles, instanced.meshes, instanced.placements,
                                       instanced.materials, instanced.camera);
    ASSERT_EQ(bvh.instances.size(), 4u); // the world geometry and three placements
    gpu_types::BvhTraversal traversal;
    traversal.pairs = bvh.pairs.data();
    traversal.triangles = instanced.triangles.data();
    traversal.instances = bvh.instances.data();

    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int hits = 0, mirroredHits = 0;
    for (int r = 0; r < 4000; ++r) {
        const glm::vec3 o(5.0f * u(rng), 1.0f + 2.5f * u(rng), 5.0f * u(rng));
        const glm::vec3 target(2.5f * u(rng), 1.0f + 0.8f * u(rng), 1.0f * u(rng));
        const glm::vec3 d = glm::normalize(target - o);
        float bestT = 3.0e38f;
        int best = -1;
        for (size_t i = 0; i < flat.triangles.size(); ++i) {
            float t, b1, b2;
            const Triangle& tri = flat.triangles[i];
            if (gpu_types::intersectTriangle(o, d, tri.p0, tri.p1, tri.p2, bestT, t, b1, b2)) {
                bestT = t;
                best = int(i);
            }
        }
        gpu_types::HitRecord hit;
        uint32_t instance = 0;
        const bool found = traversal.traceClosestInstanced(o, d, 3.0e38f, hit, instance);
        ASSERT_EQ(found, best >= 0) << "ray " << r;
        ASSERT_EQ(traversal.traceAnyInstanced(o, d, 3.0e38f), best >= 0) << "ray " << r;
        if (!found)
            continue;
        ++hits;
        EXPECT_NEAR(hit.t, bestT, 1e-4f * bestT) << "ray " << r;
        const Instance& placed = bvh.instances[instance];
        mirroredHits += (placed.flags & WF_INSTANCE_MIRRORED) != 0;
        const glm::vec3 expected = frontNormal(flat.triangles[best], nullptr);
        const glm::vec3 actual = frontNormal(instanced.triangles[hit.triangle], &placed);
        // Neighbouring triangles may swap at an edge; a flipped or wrong face cannot pass.
        EXPECT_GT(glm::dot(actual, expected), 0.8f) << "ray " << r;
        // A shadow segment short of the hit is blocked exactly when brute force says so.
        const glm::vec3 segment = d * (0.999f * bestT);
        bool blocked = false;
        for (const Triangle& tri : flat.triangles) {
            float t, b1, b2;
            blocked |= gpu_types::intersectTriangle(o, segment, tri.p0, tri.p1, tri.p2, 1.0f, t,
                                                    b1, b2);
        }
        EXPECT_EQ(traversal.traceAnyInstanced(o, segment, 1.0f), blocked) << "ray " << r;
    }
    EXPECT_GT(hits, 1000);
    EXPECT_GT(mirroredHits, 50);
}

} // namespace
} // namespace wf
