// --traversal rt against the project's BVH, on the device's ray-tracing pipelines (skipped
// where it has none, as Mesa 22.3's lavapipe): the same closest hits on a set of rays made on
// the CPU, and the same images within noise on scenes of each kind the acceleration
// structures must model (one-level triangles, sphere lights as boxes with the project's own
// intersection, mirrored instances, alpha cut-outs and stochastic alpha through the any-hit
// shader, textures and normal maps), validation layer on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include "errors.h"
#include "gpu_test_util.h"
#include "instanced_scene.h"
#include "render/gpu_scene/scene_buffers.h"
#include "scene/gltf/gltf_loader.h"
#include "scene/gltf/gltf_materials.h"
#include "shaders/traversal/geometry.h"

namespace wf::test {
namespace {

constexpr uint32_t kSize = 32;  // 16 regions of 8 x 8
constexpr uint32_t kBlock = 8;

Scene loadScene(const std::string& path, Instancing mode = Instancing::Auto) {
    GltfOptions options;
    options.instancing = mode;
    std::vector<std::string> warnings;
    return loadGltf(path, &warnings, options);
}

std::string sceneFile(const char* name) { return std::string(WF_TEST_SCENE_DIR) + "/" + name; }

// A floor lit by a quad light through two occluders: one cut out by a checker texture (alpha
// MASK), one of alpha 0.5 (BLEND, stochastic transparency), seen from above at a slant, so
// camera, continuation and shadow rays all meet the alpha test.
Scene alphaScene() {
    Scene scene;
    Material floor = gltf::defaultMaterial();
    floor.flags = WF_MATERIAL_DOUBLE_SIDED;
    Material light = gltf::defaultMaterial();
    light.baseColor = glm::vec4(0, 0, 0, 1);
    light.emission = glm::vec3(6.0f);
    light.flags = WF_MATERIAL_DOUBLE_SIDED;
    Material mask = gltf::defaultMaterial();
    mask.flags = WF_MATERIAL_ALPHA_MASK | WF_MATERIAL_DOUBLE_SIDED;
    mask.alphaCutoff = 0.5f;
    mask.baseColor = glm::vec4(0.9f, 0.3f, 0.2f, 1.0f);
    mask.baseColorTexture = 0;
    Material blend = gltf::defaultMaterial();
    blend.flags = WF_MATERIAL_ALPHA_BLEND | WF_MATERIAL_DOUBLE_SIDED;
    blend.baseColor = glm::vec4(0.2f, 0.4f, 0.9f, 0.5f);
    scene.materials = {floor, light, mask, blend};
    auto quadY = [&](float y, glm::vec2 lo, glm::vec2 hi, uint32_t material, float uvScale) {
        const glm::vec3 a(lo.x, y, lo.y), b(hi.x, y, lo.y), c(hi.x, y, hi.y), d(lo.x, y, hi.y);
        scene.triangles.push_back({a, material, b, WF_NO_EMITTER, c, 0});
        scene.triangles.push_back({a, material, c, WF_NO_EMITTER, d, 0});
        const float s = uvScale;
        scene.surface.uv0.push_back({{0, 0}, {s, 0}, {s, s}});
        scene.surface.uv0.push_back({{0, 0}, {s, s}, {0, s}});
    };
    quadY(0.0f, {-4, -4}, {4, 4}, 0, 1.0f);
    quadY(3.0f, {-1, -1}, {1, 1}, 1, 1.0f);
    quadY(1.2f, {-1.6f, -1.2f}, {0.0f, 1.2f}, 2, 4.0f); // 4 x 4 checker of holes
    quadY(1.6f, {0.1f, -1.2f}, {1.6f, 1.2f}, 3, 1.0f);
    TextureImage checker;
    checker.width = checker.height = 2;
    checker.rgba = {0xffffffffu, 0x00ffffffu, 0x00ffffffu, 0xffffffffu};
    scene.surface.images.push_back(checker);
    TextureRef ref{};
    ref.uRow = glm::vec3(1, 0, 0);
    ref.vRow = glm::vec3(0, 1, 0);
    ref.flags = WF_TEXTURE_NEAREST | WF_WRAP_REPEAT;
    scene.surface.textureRefs.push_back(ref);
    scene.surface.refImage.push_back(0);
    scene.camera.position = glm::vec3(0.0f, 4.5f, 3.5f);
    scene.camera.forward = glm::normalize(glm::vec3(0.0f, -4.5f, -3.5f));
    scene.camera.up = glm::normalize(glm::cross(glm::cross(scene.camera.forward,
                                                           glm::vec3(0, 1, 0)),
                                                scene.camera.forward));
    scene.camera.yfov = 1.0f;
    scene.hasCamera = true;
    return scene;
}

// A floor under a tiny sphere light: the shadow segments end on the sphere's near side,
// offset off it by its own small size, less than the error of a ray-sphere t computed from
// metres away, so the light must not be tested against its own segments (issue 13: 20-30%
// of the samples went dark). The rt shadow pass leaves it out in its intersection shader.
Scene tinySphereLight() {
    Scene scene;
    Material floor = gltf::defaultMaterial();
    floor.flags = WF_MATERIAL_DOUBLE_SIDED;
    scene.materials = {floor};
    const glm::vec3 a(-4, 0, -4), b(4, 0, -4), c(4, 0, 4), d(-4, 0, 4);
    scene.triangles.push_back({a, 0, b, WF_NO_EMITTER, c, 0});
    scene.triangles.push_back({a, 0, c, WF_NO_EMITTER, d, 0});
    PunctualLight sphere{};
    sphere.type = WF_LIGHT_SPHERE;
    sphere.position = glm::vec3(0.5f, 3.0f, 0.2f);
    sphere.direction = glm::vec3(0, -1, 0);
    sphere.radius = 0.002f;
    sphere.intensity = glm::vec3(9.0f);
    sphere.emitter = WF_NO_EMITTER;
    scene.lights.push_back(sphere);
    scene.camera.position = glm::vec3(0.0f, 2.0f, 0.0f);
    scene.camera.forward = glm::vec3(0, -1, 0);
    scene.camera.up = glm::vec3(0, 0, 1);
    scene.camera.yfov = 1.2f;
    scene.hasCamera = true;
    return scene;
}

RenderSettings smallRender(uint32_t spp, uint32_t seed, Traversal traversal) {
    RenderSettings s;
    s.width = s.height = kSize;
    s.samplesPerPixel = spp;
    s.maxDepth = 5;
    s.seed = seed;
    s.traversal = traversal;
    return s;
}

// rt renders over four seeds against a BVH reference of another seed, per 8 x 8 region.
void expectSameImage(const Scene& scene, const std::string& what,
                     Integrator integrator = Integrator::Path) {
    Context* context = rayTracingContext();
    if (!context)
        GTEST_SKIP() << "the device has no ray-tracing pipelines";
    RenderSettings reference = smallRender(256, 1000, Traversal::Bvh);
    reference.aov = true; // the reference's per-pixel variance
    reference.integrator = integrator;
    const RenderResult bvh = renderScene(scene, reference, *context);
    std::vector<std::vector<float>> images;
    for (uint32_t seed = 1; seed <= 4; ++seed) {
        RenderSettings settings = smallRender(64, seed, Traversal::RayTracing);
        settings.integrator = integrator;
        RenderResult rt = renderScene(scene, settings, *context);
        EXPECT_EQ(rt.stats.nonFiniteSamples, 0u) << what;
        EXPECT_GT(rt.stats.extensionRays, 0u) << what;
        images.push_back(std::move(rt.rgb));
    }
    EXPECT_EQ(expectRegionsUnbiased(images, bvh.rgb, bvh.aov.variance, kSize, kSize, kBlock,
                                    what + " (rt against bvh)"),
              16);
    EXPECT_EQ(context->validationMessageCount(), 0u);
}

TEST(TraversalRt, CornellBoxImageMatchesBvh) {
    expectSameImage(loadScene(sceneFile("cornell_box.gltf")), "cornell box");
}

TEST(TraversalRt, SphereLightsImageMatchesBvh) {
    expectSameImage(loadScene(sceneFile("veach_mis.gltf")), "veach mis (sphere lights)");
}

// Lambert, mirror and glass: hits binned by material kind, appended by the ray-generation
// shader (one atomic per ray) rather than by subgroup ballots.
TEST(TraversalRt, ShadeBinsImageMatchesBvh) {
    expectSameImage(loadScene(sceneFile("glass_caustic.gltf")), "glass caustic (shade bins)");
}

TEST(TraversalRt, MirroredInstancesImageMatchesBvh) {
    TempDir dir;
    expectSameImage(loadScene(writeInstancedScene(dir), Instancing::On),
                    "instances (rotated, mirrored, scaled)");
}

TEST(TraversalRt, NormalMappedInstancesImageMatchesBvh) {
    TempDir dir;
    expectSameImage(loadScene(writeNormalMappedInstancedScene(dir), Instancing::On),
                    "normal-mapped textured instances");
}

TEST(TraversalRt, TinySphereLightImageMatchesBvh) {
    expectSameImage(tinySphereLight(), "tiny sphere light");
}

TEST(TraversalRt, AlphaMaskAndStochasticAlphaImageMatchesBvh) {
    expectSameImage(alphaScene(), "alpha mask and stochastic alpha");
}

// Light subpaths extend through the same ray-traced intersect pass (their splats' and
// connections' shadow rays walk the BVH in light_splat): light tracing, bdpt and vcm each
// give the BVH's image, on the glass caustic and through alpha cut-outs.
TEST(TraversalRt, LightSubpathsImageMatchesBvh) {
    for (Integrator integrator : {Integrator::Light, Integrator::Bdpt, Integrator::Vcm}) {
        const std::string name = integratorName(integrator);
        expectSameImage(loadScene(sceneFile("glass_caustic.gltf")), "glass caustic, " + name,
                        integrator);
        expectSameImage(alphaScene(), "alpha, " + name, integrator);
    }
}

// The same rays through both traversals: rays from random points of the scene's box (and the
// camera) in random directions. The triangle, instance and barycentrics must agree wherever
// the ray meets a triangle away from its edges; the driver's intersector (watertight, its own
// rounding) may pick the other triangle of an edge that a ray grazes, or a different t by an
// ulp or so, which the share printed here shows.
void expectSameHits(const Scene& scene, const std::string& what) {
    Context* context = rayTracingContext();
    if (!context)
        GTEST_SKIP() << "the device has no ray-tracing pipelines";
    static ShaderCompiler compiler;
    const PreparedScene prepared = prepareScene(scene);
    RenderSettings settings = smallRender(1, 0, Traversal::Bvh);
    settings.width = settings.height = 64; // room for 4096 rays
    WavefrontRenderer bvh(*context, prepared, settings, compiler);
    settings.traversal = Traversal::RayTracing;
    WavefrontRenderer rt(*context, prepared, settings, compiler);

    const Bounds box = triangleBounds(scene);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::normal_distribution<float> gauss;
    std::vector<glm::vec4> origins, directions;
    for (int i = 0; i < 4096; ++i) {
        glm::vec3 o = i % 4 == 0 ? scene.camera.position
                                 : box.lo + (box.hi - box.lo) *
                                                glm::vec3(unit(rng), unit(rng), unit(rng));
        glm::vec3 d;
        do
            d = glm::vec3(gauss(rng), gauss(rng), gauss(rng));
        while (glm::length(d) < 1e-3f);
        origins.emplace_back(o, 0.0f);
        directions.emplace_back(glm::normalize(d), 0.0f);
    }
    const std::vector<glm::uvec4> a = bvh.intersectRays(origins, directions);
    const std::vector<glm::uvec4> b = rt.intersectRays(origins, directions);
    size_t hits = 0, differ = 0, nearEdge = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        hits += a[i].w != 0xffffffffu;
        const float b1 = glm::uintBitsToFloat(a[i].y), b2 = glm::uintBitsToFloat(a[i].z);
        const bool same = a[i].w == b[i].w &&
                          (a[i].w == 0xffffffffu ||
                           (std::abs(b1 - glm::uintBitsToFloat(b[i].y)) < 1e-4f &&
                            std::abs(b2 - glm::uintBitsToFloat(b[i].z)) < 1e-4f &&
                            (prepared.instances.empty()
                                 // t's rounding follows the coordinates' size, not t's: a
                                 // ray from a point 1e-4 off a wall differs in t's 4th digit
                                 ? std::abs(glm::uintBitsToFloat(a[i].x) -
                                            glm::uintBitsToFloat(b[i].x)) <=
                                       1e-5f * (glm::length(glm::vec3(origins[i])) +
                                                glm::uintBitsToFloat(a[i].x))
                                 : a[i].x == b[i].x)));
        if (!same) {
            if (differ < 3)
                std::printf("  ray %zu: bvh (%08x, %g, %g, %u), rt (%08x, %g, %g, %u)\n", i,
                            a[i].x, b1, b2, a[i].w, b[i].x, glm::uintBitsToFloat(b[i].y),
                            glm::uintBitsToFloat(b[i].z), b[i].w);
            ++differ;
            nearEdge += std::min({b1, b2, 1.0f - b1 - b2}) < 1e-3f;
        }
    }
    std::printf("%s: %zu rays, %zu hits, %zu differ (%.3f%%), %zu of them within 1e-3 of an "
                "edge in barycentrics\n",
                what.c_str(), a.size(), hits, differ, 100.0 * differ / a.size(), nearEdge);
    EXPECT_GT(hits, a.size() / 4) << what;
    EXPECT_LE(differ, a.size() / 200) << what << ": over 0.5% of the rays hit differently";
    EXPECT_EQ(context->validationMessageCount(), 0u);
}

TEST(TraversalRt, SameClosestHitsCornellBox) {
    expectSameHits(loadScene(sceneFile("cornell_box.gltf")), "cornell box");
}

TEST(TraversalRt, SameClosestHitsSphereLights) {
    expectSameHits(loadScene(sceneFile("veach_mis.gltf")), "veach mis (sphere lights)");
}

TEST(TraversalRt, SameClosestHitsMirroredInstances) {
    TempDir dir;
    expectSameHits(loadScene(writeInstancedScene(dir), Instancing::On), "mirrored instances");
}

TEST(TraversalRt, SameClosestHitsAlpha) { expectSameHits(alphaScene(), "alpha"); }

// Spawned rays stay off the surface they leave when the driver intersects: triangles from
// 1e-3 to 1e3 across, up to 1e3 from the origin, a third long and skinny, each the start of
// one ray from a random point of it, offset as shade offsets it (the point from barycentrics,
// triangleSpawnError, offsetRayOrigin), to either side. No ray may meet its own triangle
// again, by either traversal. The control, the raw point, does meet it: the test can fail.
TEST(TraversalRt, SpawnedRaysNeverRehitTheirTriangle) {
    Context* context = rayTracingContext();
    if (!context)
        GTEST_SKIP() << "the device has no ray-tracing pipelines";
    using namespace gpu_types;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::normal_distribution<double> gauss;
    auto randomDir = [&] {
        return glm::normalize(glm::dvec3(gauss(rng), gauss(rng), gauss(rng)));
    };
    Scene scene;
    Material material = gltf::defaultMaterial();
    material.flags = WF_MATERIAL_DOUBLE_SIDED;
    scene.materials = {material};
    for (int i = 0; i < 4096; ++i) {
        const double size = std::pow(10.0, -3.0 + 6.0 * uniform(rng));
        const glm::dvec3 t = std::pow(10.0, -3.0 + 6.0 * uniform(rng)) * randomDir();
        const glm::dvec3 q0 = t + size * randomDir();
        glm::dvec3 q1 = t + size * randomDir(), q2 = t + size * randomDir();
        if (i % 3 == 0) { // long and skinny: 1e-4 .. 1e-1 as wide as long
            const glm::dvec3 axis = randomDir();
            const glm::dvec3 side = glm::normalize(glm::cross(axis, randomDir()));
            q1 = q0 + size * axis;
            q2 = q0 + size * (uniform(rng) * axis + std::pow(10.0, -4.0 + 3.0 * uniform(rng)) * side);
        }
        scene.triangles.push_back(
            {glm::vec3(q0), 0, glm::vec3(q1), WF_NO_EMITTER, glm::vec3(q2), 0});
    }
    scene.hasCamera = true;
    static ShaderCompiler compiler;
    const PreparedScene prepared = prepareScene(scene); // degenerate triangles dropped
    RenderSettings settings = smallRender(1, 0, Traversal::Bvh);
    settings.width = settings.height = 64;
    WavefrontRenderer bvh(*context, prepared, settings, compiler);
    settings.traversal = Traversal::RayTracing;
    WavefrontRenderer rt(*context, prepared, settings, compiler);
    std::vector<glm::vec4> offset, raw, directions;
    for (const Triangle& tri : prepared.triangles) {
        float b1 = float(uniform(rng)), b2 = float(uniform(rng));
        if (b1 + b2 > 1.0f) {
            b1 = 1.0f - b1;
            b2 = 1.0f - b2;
        }
        const vec3 p = triangleHitPoint(tri.p0, tri.p1, tri.p2, b1, b2);
        const vec3 n = glm::normalize(glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0));
        vec3 w = vec3(randomDir());
        if (std::abs(glm::dot(w, n)) < 1e-3f)
            w = n;
        const vec3 error = triangleSpawnError(tri.p0, tri.p1, tri.p2, b1, b2);
        offset.emplace_back(offsetRayOrigin(p, error, n, w), 0.0f);
        raw.emplace_back(p, 0.0f);
        directions.emplace_back(w, 0.0f);
    }
    const auto selfHits = [&](WavefrontRenderer& renderer, const std::vector<glm::vec4>& from) {
        const std::vector<glm::uvec4> hits = renderer.intersectRays(from, directions);
        size_t count = 0;
        for (size_t i = 0; i < hits.size(); ++i)
            count += hits[i].w == i;
        return count;
    };
    const size_t rays = directions.size();
    const size_t rtRaw = selfHits(rt, raw), bvhRaw = selfHits(bvh, raw);
    std::printf("%zu rays; self-hits from the raw point: rt %zu, bvh %zu\n", rays, rtRaw,
                bvhRaw);
    EXPECT_GT(rays, 4000u);
    EXPECT_GT(rtRaw, rays / 100) << "the control: raw points should re-hit";
    EXPECT_EQ(selfHits(rt, offset), 0u);
    EXPECT_EQ(selfHits(bvh, offset), 0u);
    EXPECT_EQ(context->validationMessageCount(), 0u);
}

// The ray-tracing variant models no more than the scene needs: the BVH variant's shaders do
// not change, and a context asked for no ray tracing refuses an rt render.
TEST(TraversalRt, BvhVariantUnchangedAndRtNeedsTheContext) {
    Context* context = rayTracingContext();
    if (!context)
        GTEST_SKIP() << "the device has no ray-tracing pipelines";
    static ShaderCompiler compiler;
    const PreparedScene prepared = prepareScene(loadScene(sceneFile("cornell_box.gltf")));
    RenderSettings settings = smallRender(1, 0, Traversal::Bvh);
    WavefrontRenderer bvh(*context, prepared, settings, compiler);
    for (const auto& [name, value] : bvh.shaderDefines())
        EXPECT_NE(name, "WF_RAY_TRACING");
    EXPECT_EQ(bvh.sceneBuffers()->acceleration(), nullptr);
    settings.traversal = Traversal::RayTracing;
    WavefrontRenderer rt(*context, prepared, settings, compiler);
    ASSERT_NE(rt.sceneBuffers()->acceleration(), nullptr);
    EXPECT_GT(rt.sceneBuffers()->acceleration()->bytes(), 0u);
    EXPECT_FALSE(gpuContext().rayTracingEnabled());
    EXPECT_THROW(std::make_unique<WavefrontRenderer>(gpuContext(), prepared, settings, compiler),
                 UsageError);
}

} // namespace
} // namespace wf::test
