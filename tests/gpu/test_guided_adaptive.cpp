// Guided adaptive sampling (--target-error, converge's `adaptive+guided`): the guide trains as
// the pilot with the pilot's seed (render/adaptive_sampling.h), more iterations follow while
// the training stays within the round's budget, and the rounds sample the frozen guide. On the
// glass caustic, each 8x8 region's mean over seeds agrees with an unguided reference within 5
// standard errors; the rounds really sampled the trained guide (a restart forgets it); a seed
// gives the same image twice; no sample is NaN or Inf.
#include <gtest/gtest.h>

#include "gpu_test_util.h"
#include "guided_settings.h"
#include "render/adaptive_sampling.h"
#include "render/gpu_scene/scene_buffers.h"
#include "render/guiding/path_guide.h"
#include "scene/gltf/gltf_loader.h"

namespace wf::test {
namespace {

constexpr uint32_t kMeanSpp = 96, kMaxSpp = 1024;

struct GuidedAdaptiveRun {
    AdaptiveResult result;
    guiding::SDTreeStats guideInRounds; // the renderer's guide once the rounds are done
};

GuidedAdaptiveRun renderGuidedAdaptively(const Scene& scene, uint32_t seed) {
    static ShaderCompiler compiler;
    PreparedScene prepared = prepareScene(scene);
    AdaptiveSettings adaptive;
    adaptive.meanSpp = kMeanSpp;
    adaptive.maxSpp = kMaxSpp;
    RenderSettings settings = guidedTestSettings(kMaxSpp, seed, true);
    settings.pixelList = true;
    // A fixed BSDF share of 0.5, so that the rounds sample the guide everywhere (the glass
    // caustic's leaves learn share 1 at this size, which stops training early).
    settings.guideLearnFraction = false;
    WavefrontRenderer renderer(gpuContext(), prepared, settings, compiler);
    GuidedAdaptiveRun run;
    run.result = renderAdaptive(renderer, seed, adaptive, kGuidedSize, kGuidedSize);
    run.guideInRounds = renderer.guide()->tree().stats(settings.guideBsdfFraction);
    return run;
}

TEST(GuidedAdaptive, GlassCausticUnbiasedWithTheTrainedGuide) {
    Scene scene = loadGltf(std::string(WF_TEST_SCENE_DIR) + "/glass_caustic.gltf");
    RenderSettings referenceSettings = guidedTestSettings(1024, 4242, false);
    referenceSettings.aov = true; // the variance layer: the reference's own noise
    const RenderResult reference = renderScene(scene, referenceSettings);
    std::vector<std::vector<float>> images;
    for (uint32_t seed = 1; seed <= 8; ++seed) {
        GuidedAdaptiveRun run = renderGuidedAdaptively(scene, seed);
        const AdaptiveResult& result = run.result;
        EXPECT_EQ(result.stats.nonFiniteSamples, 0u);
        // The pilot: 1 + 2 + 4 + 8 + 16 spp (pilotSppFor(1024) = 16); then 32 more before the
        // round of about 96 spp on average (31 + 32 <= 96), and no more (63 + 64 > 96).
        EXPECT_EQ(result.pilotSpp, 16u);
        ASSERT_EQ(result.stats.guideIterations.size(), 6u);
        EXPECT_EQ(result.stats.guideIterations.back().samplesPerPixel, 32u);
        // The rounds sampled the trained guide, not the one-node guide a restart leaves.
        EXPECT_GT(run.guideInRounds.samplingNodes, 1u);
        EXPECT_EQ(run.guideInRounds.samplingNodes,
                  result.stats.guideIterations.back().directionalNodes);
        images.push_back(result.rgb);
    }
    EXPECT_EQ(expectRegionsUnbiased(images, reference.rgb, reference.aov.variance, kGuidedSize,
                                    kGuidedSize, kGuidedBlock, "glass caustic, guided adaptive"),
              16);
    EXPECT_EQ(renderGuidedAdaptively(scene, 1).result.rgb, images.front());
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
