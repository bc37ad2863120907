// What `wavefront bench` relies on: the workload is deterministic (same inputs, same ray counts
// per depth, whatever the wave sizes), the per-depth counters conserve rays, the submit budget
// splits waves without changing a bit of the image, and the megakernel baseline traces the same
// paths as the wavefront. No timing is asserted: speed goes in bench output only.
#include <cmath>
#include <cstring>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "gpu_test_util.h"
#include "scene/gltf/gltf_loader.h"
#include "shaders/types/render_types.h"

namespace wf::test {
namespace {

RenderSettings benchSettings() {
    RenderSettings settings;
    settings.width = 40;
    settings.height = 32;
    settings.samplesPerPixel = 6;
    settings.maxDepth = 7;
    settings.seed = 17;
    return settings;
}

const Scene& scene(const std::string& name) {
    static std::map<std::string, Scene> scenes;
    auto it = scenes.find(name);
    if (it == scenes.end())
        it = scenes.emplace(name, loadGltf(WF_TEST_SCENE_DIR "/" + name)).first;
    return it->second;
}

void expectSameWorkload(const RenderStats& a, const RenderStats& b) {
    EXPECT_EQ(a.paths, b.paths);
    EXPECT_EQ(a.cameraRays, b.cameraRays);
    EXPECT_EQ(a.extensionRays, b.extensionRays);
    EXPECT_EQ(a.shadowRays, b.shadowRays);
    EXPECT_EQ(a.depthRays, b.depthRays);
    EXPECT_EQ(a.depthShadowRays, b.depthShadowRays);
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(BenchWorkload, SameInputsSameRayCountsWhateverTheWaves) {
    RenderSettings oneWave = benchSettings();
    oneWave.submitBudgetSeconds = 0.0; // all six samples in one wave
    RenderSettings pixelRanges = benchSettings();
    pixelRanges.maxPathsPerWave = 1024;     // under one sample of the 1280 pixels
    pixelRanges.submitBudgetSeconds = 1e-9; // and kept at the smallest wave
    RenderResult a = renderScene(scene("cornell_box.gltf"), oneWave);
    RenderResult b = renderScene(scene("cornell_box.gltf"), oneWave);
    RenderResult c = renderScene(scene("cornell_box.gltf"), pixelRanges);
    EXPECT_EQ(a.stats.waves, 1u);
    EXPECT_GE(c.stats.waves, 12u); // two pixel ranges per sample
    expectSameWorkload(a.stats, b.stats);
    expectSameWorkload(a.stats, c.stats);
    // Each pixel adds its samples in order, so the film does not depend on the wave shapes.
    EXPECT_TRUE(sameBits(a.rgb, b.rgb));
    EXPECT_TRUE(sameBits(a.rgb, c.rgb));
    EXPECT_GT(c.stats.longestSubmitSeconds, 0.0);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(BenchWorkload, OccupancyPerDepthConservesRays) {
    RenderResult r = renderScene(scene("cornell_box.gltf"), benchSettings());
    ASSERT_EQ(r.stats.depthRays.size(), size_t(WF_TRACKED_DEPTHS));
    EXPECT_EQ(r.stats.depthRays[0], r.stats.paths);
    uint64_t extension = 0, shadow = 0;
    for (size_t d = 0; d < r.stats.depthRays.size(); ++d) {
        if (d > 0) {
            extension += r.stats.depthRays[d];
            EXPECT_LE(r.stats.depthRays[d], r.stats.depthRays[d - 1]) << "depth " << d;
        }
        shadow += r.stats.depthShadowRays[d];
        if (d >= benchSettings().maxDepth)
            EXPECT_EQ(r.stats.depthRays[d], 0u) << "depth " << d;
    }
    EXPECT_EQ(extension, r.stats.extensionRays);
    EXPECT_EQ(shadow, r.stats.shadowRays);
    // The last segment neither extends nor connects.
    EXPECT_EQ(r.stats.depthShadowRays[benchSettings().maxDepth - 1], 0u);
}

TEST(BenchWorkload, DeepPathsFoldIntoTheLastDepthEntry) {
    RenderSettings settings = benchSettings();
    settings.maxDepth = WF_TRACKED_DEPTHS + 8;
    settings.rrDepth = 100; // no roulette: many paths go the whole way in the closed box
    RenderResult r = renderScene(furnaceBox(0.8f, 0.5f), settings);
    uint64_t extension = 0;
    for (size_t d = 1; d < r.stats.depthRays.size(); ++d)
        extension += r.stats.depthRays[d];
    EXPECT_EQ(extension, r.stats.extensionRays);
    EXPECT_GT(r.stats.depthRays[WF_TRACKED_DEPTHS - 1], r.stats.depthRays[WF_TRACKED_DEPTHS - 2]);
}

// The megakernel calls the same functions on the same samples: the same rays, and images that
// differ by float rounding at most (the compiler may contract the two programs differently).
void expectMegakernelAgrees(const std::string& name) {
    RenderSettings settings = benchSettings();
    RenderResult wave = renderScene(scene(name), settings);
    settings.megakernel = true;
    RenderResult mega = renderScene(scene(name), settings);
    expectSameWorkload(wave.stats, mega.stats);
    ASSERT_EQ(wave.rgb.size(), mega.rgb.size());
    size_t differing = 0;
    for (size_t i = 0; i < wave.rgb.size(); ++i)
        if (std::abs(wave.rgb[i] - mega.rgb[i]) > 1e-4f * (1.0f + std::abs(wave.rgb[i])))
            ++differing;
    EXPECT_EQ(differing, 0u) << name;
    MeanAndError a = imageMean(wave.rgb), b = imageMean(mega.rgb);
    EXPECT_NEAR(a.mean, b.mean, 0.5 * a.standardError) << name;
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(BenchWorkload, MegakernelAgreesWithWavefrontCornell) {
    expectMegakernelAgrees("cornell_box.gltf");
}

TEST(BenchWorkload, MegakernelAgreesWithWavefrontGlass) {
    expectMegakernelAgrees("glass_caustic.gltf");
}

TEST(BenchWorkload, MegakernelAgreesWithWavefrontSphereLight) {
    expectMegakernelAgrees("sphere_near_floor.gltf");
}

// The light tree by default, and the receiver normal carried from vertex to vertex for MIS.
TEST(BenchWorkload, MegakernelAgreesWithWavefrontLightTree) {
    expectMegakernelAgrees("many_lamps.gltf");
}

} // namespace
} // namespace wf::test
