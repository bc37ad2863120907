// The Cornell box end to end on the GPU: finite everywhere, bit-for-bit reproducible with the
// same seed, independent seeds agreeing within noise, and waves of any size giving one image.
#include <cmath>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "errors.h"
#include "gpu_test_util.h"
#include "render/gpu_scene/scene_buffers.h"
#include "scene/gltf/gltf_loader.h"

namespace wf::test {
namespace {

RenderSettings smallSettings(uint32_t seed) {
    RenderSettings settings;
    settings.width = 48;
    settings.height = 48;
    settings.samplesPerPixel = 16;
    settings.maxDepth = 8;
    settings.seed = seed;
    return settings;
}

const Scene& cornell() {
    static Scene scene = loadGltf(WF_TEST_SCENE_DIR "/cornell_box.gltf");
    return scene;
}

double meanRadiance(const std::vector<float>& rgb) {
    double sum = 0.0;
    for (float v : rgb)
        sum += v;
    return sum / rgb.size();
}

TEST(Cornell, FiniteAndReproducibleBitForBit) {
    RenderResult first = renderScene(cornell(), smallSettings(3));
    RenderResult second = renderScene(cornell(), smallSettings(3));
    ASSERT_EQ(first.rgb.size(), second.rgb.size());
    EXPECT_EQ(std::memcmp(first.rgb.data(), second.rgb.data(), first.rgb.size() * sizeof(float)),
              0);
    for (float v : first.rgb)
        ASSERT_TRUE(std::isfinite(v) && v >= 0.0f);
    EXPECT_EQ(first.stats.nonFiniteSamples, 0u);
    EXPECT_GT(meanRadiance(first.rgb), 0.0);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(Cornell, DifferentSeedsGiveDifferentNoiseSameMean) {
    std::vector<double> means;
    for (uint32_t seed = 10; seed < 14; ++seed)
        means.push_back(meanRadiance(renderScene(cornell(), smallSettings(seed)).rgb));
    EXPECT_NE(means[0], means[1]);
    double lo = means[0], hi = means[0];
    for (double m : means) {
        lo = std::min(lo, m);
        hi = std::max(hi, m);
    }
    // Image means of 37k paths each: seeds disagree by a few percent at most.
    EXPECT_LT(hi - lo, 0.05 * hi);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(Cornell, WaveSizeDoesNotChangeTheImage) {
    RenderSettings oneWave = smallSettings(5);
    RenderSettings manyWaves = oneWave;
    manyWaves.maxPathsPerWave = 48 * 48 * 3; // 3 samples per wave: waves of 3, 3, ..., 1
    RenderResult a = renderScene(cornell(), oneWave);
    RenderResult b = renderScene(cornell(), manyWaves);
    EXPECT_GT(b.stats.waves, 1u);
    ASSERT_EQ(a.rgb.size(), b.rgb.size());
    // Sums are taken in another grouping, so allow float rounding, nothing more.
    for (size_t i = 0; i < a.rgb.size(); ++i)
        ASSERT_NEAR(a.rgb[i], b.rgb[i], 1e-4f * (1.0f + a.rgb[i])) << "at " << i;
}

// A renderer reading another's scene tables (the viewer's preview, the bench's megakernel)
// renders what it would with its own; one of another variant is refused.
TEST(Cornell, SharedSceneBuffersGiveTheSameImage) {
    static ShaderCompiler compiler;
    PreparedScene prepared = prepareScene(cornell());
    RenderSettings settings = smallSettings(7);
    WavefrontRenderer owner(gpuContext(), prepared, settings, compiler);
    owner.render();
    RenderSettings smaller = settings;
    smaller.width = 24;
    smaller.height = 24;
    WavefrontRenderer sharing(gpuContext(), prepared, smaller, compiler, owner.sceneBuffers());
    WavefrontRenderer alone(gpuContext(), prepared, smaller, compiler);
    EXPECT_EQ(sharing.sceneBuffers(), owner.sceneBuffers());
    EXPECT_NE(alone.sceneBuffers(), owner.sceneBuffers());
    sharing.render();
    alone.render();
    std::vector<float> a = sharing.readImage(), b = alone.readImage();
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);
    RenderSettings otherVariant = smaller;
    otherVariant.lightSampling = LightSampling::Bsdf; // no emitter table, no shadow rays
    EXPECT_THROW(WavefrontRenderer(gpuContext(), prepared, otherVariant, compiler,
                                   owner.sceneBuffers()),
                 InternalError);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// The packed 64-bit stores (WF_PACKED_STORES) and the plain vec4 stores of devices without
// shaderInt64 write the same bytes: the images agree bit for bit, megakernel included.
TEST(Cornell, PackedStoresGiveTheSameImage) {
    if (!gpuContext().shaderInt64())
        GTEST_SKIP() << "the device has no shaderInt64: only the vec4 stores exist";
    for (bool megakernel : {false, true}) {
        RenderSettings settings = smallSettings(3);
        settings.megakernel = megakernel;
        RenderResult packed = renderScene(cornell(), settings);
        settings.packedStores = false;
        RenderResult plain = renderScene(cornell(), settings);
        ASSERT_EQ(packed.rgb.size(), plain.rgb.size());
        EXPECT_EQ(std::memcmp(packed.rgb.data(), plain.rgb.data(),
                              packed.rgb.size() * sizeof(float)),
                  0)
            << (megakernel ? "megakernel" : "wavefront");
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// The Cornell box with `count` small random triangles floating in the room: a deeper tree.
Scene cornellWithSoup(int count) {
    Scene scene = cornell();
    std::mt19937 rng(7u);
    std::uniform_real_distribution<float> inside(1.0f, 4.5f), edge(-0.15f, 0.15f);
    for (int i = 0; i < count; ++i) {
        glm::vec3 p(inside(rng), inside(rng), inside(rng));
        Triangle tri = scene.triangles[0]; // its material, emitter tag and all
        tri.p0 = p;
        tri.p1 = p + glm::vec3(edge(rng), edge(rng), edge(rng));
        tri.p2 = p + glm::vec3(edge(rng), edge(rng), edge(rng));
        scene.triangles.push_back(tri);
    }
    return scene;
}

// The register stack (WF_BVH_REGISTER_STACK) holds exactly what the private array holds: on
// trees whose stack need is the whole of its 8 entries (closest hits and shadow rays on it) and
// close to its 16 (shadow rays only), the images are the same bit for bit; past 16 the renderer
// keeps the array.
TEST(Cornell, RegisterStackGivesTheSameImage) {
    int need8 = -1, need16 = -1, over = -1;
    for (int count = 10; count <= 200000 && over < 0; count += 10 + count / 8) {
        const uint32_t need = prepareScene(cornellWithSoup(count)).bvhStats.stackNeed;
        if (need == 8 && need8 < 0)
            need8 = count;
        if (need >= 15 && need <= 16 && need16 < 0)
            need16 = count;
        if (need > 16)
            over = count;
    }
    ASSERT_GT(need8, 0) << "no soup size gave a stack need of exactly 8";
    ASSERT_GT(need16, 0) << "no soup size gave a stack need of 15 or 16";
    ASSERT_GT(over, 0);
    static ShaderCompiler compiler;
    for (auto [count, capacity] : {std::pair{need8, 8u}, std::pair{need16, 16u}}) {
        for (bool megakernel : {false, true}) {
            RenderSettings settings = smallSettings(5);
            settings.samplesPerPixel = 4;
            settings.megakernel = megakernel;
            const PreparedScene prepared = prepareScene(cornellWithSoup(count));
            WavefrontRenderer registers(gpuContext(), prepared, settings, compiler);
            settings.registerStack = false;
            WavefrontRenderer array(gpuContext(), prepared, settings, compiler);
            ASSERT_EQ(registers.variant().registerStack, capacity);
            ASSERT_EQ(array.variant().registerStack, 0u);
            registers.render();
            array.render();
            std::vector<float> a = registers.readImage(), b = array.readImage();
            ASSERT_EQ(a.size(), b.size());
            EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0)
                << (megakernel ? "megakernel" : "wavefront") << ", capacity " << capacity;
        }
    }
    const PreparedScene deeper = prepareScene(cornellWithSoup(over));
    EXPECT_EQ(chooseVariant(deeper, smallSettings(5)).registerStack, 0u);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(Cornell, QueuesConserveRays) {
    RenderResult result = renderScene(cornell(), smallSettings(1));
    const uint64_t paths = 48ull * 48 * 16;
    EXPECT_EQ(result.stats.paths, paths);
    EXPECT_EQ(result.stats.cameraRays, paths);
    // Every path extends at most maxDepth - 1 times and connects at most maxDepth - 1 times.
    EXPECT_GT(result.stats.extensionRays, 0u);
    EXPECT_LE(result.stats.extensionRays, paths * 7);
    EXPECT_GT(result.stats.shadowRays, 0u);
    EXPECT_LE(result.stats.shadowRays, paths * 7);
}

} // namespace
} // namespace wf::test

namespace wf::test {
namespace {

TEST(Cornell, PartialSamplesGiveTheSameImage) {
    // The viewer traces part of a sample per frame; once the samples are complete the film
    // must equal whole-sample rendering bit for bit.
    PreparedScene prepared = prepareScene(cornell());
    RenderSettings settings = smallSettings(21);
    ShaderCompiler compiler;
    WavefrontRenderer whole(gpuContext(), prepared, settings, compiler);
    whole.renderSamples(3);
    WavefrontRenderer parts(gpuContext(), prepared, settings, compiler);
    while (parts.samplesDone() < 3)
        parts.renderPixels(700); // does not divide the 2304 pixels: ranges straddle rows
    EXPECT_EQ(parts.pixelsOfNextSample(), 0u);
    std::vector<float> a = whole.readImage(), b = parts.readImage();
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
