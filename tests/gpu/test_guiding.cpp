// Path guiding (render/guiding/, WF_GUIDING): guided renders agree with unguided ones per 8x8
// region within 5 standard errors over seeds (on the Cornell box, the glass caustic scene and
// with a deliberately wrong frozen guide or parallax: unbiased, only noisier), whether the image combines
// every iteration by its samples (the default) or keeps the last one, training stops where
// the learnt shares leave the guide unused, a guide set aside is not looked up (the image is
// unguided MIS's), a seed gives the same image twice, and no sample is NaN or Inf.
#include <gtest/gtest.h>

#include "gpu_test_util.h"
#include "guided_settings.h"
#include "guiding/guide_tree.h"
#include "render/gpu_scene/scene_buffers.h"
#include "render/guiding/path_guide.h"
#include "scene/gltf/gltf_loader.h"

namespace wf::test {
namespace {

constexpr uint32_t kSize = kGuidedSize, kBlock = kGuidedBlock;

RenderSettings settingsFor(uint32_t spp, uint32_t seed, bool guiding, bool combine = true) {
    return guidedTestSettings(spp, seed, guiding, combine);
}

struct Reference {
    std::vector<float> rgb, variance;
};

Reference unguidedReference(const Scene& scene) {
    RenderSettings settings = settingsFor(1024, 4242, false);
    settings.aov = true; // the variance layer: the reference's own noise
    RenderResult result = renderScene(scene, settings);
    return {result.rgb, result.aov.variance};
}

Scene loadScene(const std::string& name) {
    return loadGltf(std::string(WF_TEST_SCENE_DIR) + "/" + name + ".gltf");
}

// allVertices: guide every vertex, not only the camera's (RenderSettings.guideMaxDepth).
void expectGuidedUnbiased(const std::string& name, bool combine = true, bool allVertices = false) {
    Scene scene = loadScene(name);
    Reference reference = unguidedReference(scene);
    std::vector<std::vector<float>> images;
    for (uint32_t seed = 1; seed <= 8; ++seed) {
        RenderSettings settings = settingsFor(64, seed, true, combine);
        if (allVertices) { // and a fixed share of 0.5, so that every vertex samples the guide
            settings.guideMaxDepth = settings.maxDepth;
            settings.guideLearnFraction = false;
        }
        RenderResult result = renderScene(scene, settings);
        EXPECT_EQ(result.stats.nonFiniteSamples, 0u);
        // 1+2+4+8+16, then 33 spp: at 32x32 guiding::UnusedGuideStop may stop training only
        // after iteration 4 (28 spp of 1024 pixels), the schedule's own end.
        const auto& iterations = result.stats.guideIterations;
        const bool stopped = result.stats.guideStoppedUnused;
        ASSERT_EQ(iterations.size(), 5u);
        std::vector<uint32_t> spp;
        uint32_t trained = 0;
        for (const auto& it : iterations) {
            spp.push_back(it.samplesPerPixel);
            trained += it.samplesPerPixel;
        }
        if (stopped)
            EXPECT_EQ(iterations.back().payingLeaves + iterations.end()[-2].payingLeaves, 0u);
        const uint32_t imageSpp = 64 - trained;
        spp.push_back(imageSpp);
        if (combine) {
            // Every iteration weighs by its samples: the image is the mean of all 64.
            EXPECT_EQ(result.stats.guideFinalSamples, 64u);
            const std::vector<double>& w = result.stats.guideWeights;
            ASSERT_EQ(w.size(), spp.size());
            for (size_t k = 0; k < w.size(); ++k)
                EXPECT_NEAR(w[k], spp[k] / 64.0, 1e-12) << "iteration " << k;
        } else {
            EXPECT_EQ(result.stats.guideFinalSamples, imageSpp);
            EXPECT_TRUE(result.stats.guideWeights.empty());
        }
        images.push_back(std::move(result.rgb));
    }
    EXPECT_EQ(expectRegionsUnbiased(images, reference.rgb, reference.variance, kSize, kSize,
                                    kBlock, name + (combine ? " guided" : " guided, last only")),
              16);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(Guiding, CornellBoxUnbiased) { expectGuidedUnbiased("cornell_box"); }

// The glass caustic's fireflies are where weights estimated from the images' own samples
// biased the combination (an iteration that caught one weighed less); these 8 seeds did not
// show it (tests/unit/test_guide_combination.cpp does).
TEST(Guiding, GlassCausticUnbiased) { expectGuidedUnbiased("glass_caustic"); }

TEST(Guiding, LastIterationAloneUnbiased) { expectGuidedUnbiased("cornell_box", false); }

TEST(Guiding, EveryVertexGuidedUnbiased) { expectGuidedUnbiased("glass_caustic", true, true); }

// The learnt shares end training where the guide does not pay (guiding::UnusedGuideStop):
// the Cornell box's leaves learn BSDF share 1 from the start (at 32x32 training stops after
// iteration 4, 31 spp), the narrow gap's a share below 1 in some of its iterations.
TEST(Guiding, TrainingStopsWhereEveryLeafLearnsBsdfShareOne) {
    const Scene box = loadScene("cornell_box"), gap = loadScene("narrow_gap");
    for (uint32_t seed = 1; seed <= 4; ++seed) {
        RenderResult result = renderScene(box, settingsFor(256, seed, true));
        EXPECT_TRUE(result.stats.guideStoppedUnused) << seed;
        EXPECT_EQ(result.stats.guideIterations.size(), 5u) << seed;
        EXPECT_EQ(result.stats.guideFinalSamples, 256u) << seed;
        result = renderScene(gap, settingsFor(256, seed, true));
        EXPECT_FALSE(result.stats.guideStoppedUnused) << seed;
        EXPECT_EQ(result.stats.guideIterations.size(), 7u) << seed; // 1 + ... + 64, then 129
        uint64_t guided = 0; // at this size some iterations' leaves fall back to share 1
        for (const auto& it : result.stats.guideIterations)
            guided += it.guidedLeaves;
        EXPECT_GT(guided, 0u) << seed;
    }
}

TEST(Guiding, SameSeedSameImage) {
    Scene scene = loadScene("glass_caustic");
    RenderResult a = renderScene(scene, settingsFor(16, 7, true));
    RenderResult b = renderScene(scene, settingsFor(16, 7, true));
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_GT(a.stats.guideIterations.size(), 0u);
}

// Where no vertex looks the guide up (GuideParams.maxDepth 0: what a render whose training
// stopped uploads, PathGuide::sampleBsdfAlone), not even one reached through the glass, a
// guided render traces unguided MIS's paths: the same samples give the same image, whatever
// the guide and its share (here a uniform one at 0.5, which would change every guided path).
TEST(Guiding, NoVertexLooksTheGuideUpAtMaxDepthZero) {
    static ShaderCompiler compiler;
    Scene scene = loadScene("glass_caustic");
    PreparedScene prepared = prepareScene(scene);
    const std::vector<float> unguided = renderScene(scene, settingsFor(8, 11, false)).rgb;
    RenderSettings settings = settingsFor(8, 11, true);
    settings.guideMaxIterations = 0;
    settings.guideLearnFraction = false;
    settings.guideMaxDepth = 0;
    const std::vector<float> none = renderScene(scene, settings).rgb;
    settings.guideMaxDepth = settings.maxDepth; // every vertex, until the guide is set aside
    WavefrontRenderer renderer(gpuContext(), prepared, settings, compiler);
    renderer.guide()->sampleBsdfAlone();
    renderer.render();
    const std::vector<float> setAside = renderer.readImage();
    renderer.reset(); // and looked up again after a reset: the uniform guide's paths differ
    renderer.guide()->reset();
    renderer.render();
    const std::vector<float> guided = renderer.readImage();
    ASSERT_EQ(none.size(), unguided.size());
    ASSERT_EQ(setAside.size(), unguided.size());
    size_t noneApart = 0, setAsideApart = 0;
    double guidedDifference = 0.0;
    for (size_t i = 0; i < unguided.size(); ++i) {
        const float tolerance = 1e-5f * std::max(1.0f, std::abs(unguided[i]));
        noneApart += std::abs(none[i] - unguided[i]) > tolerance ? 1 : 0;
        setAsideApart += std::abs(setAside[i] - unguided[i]) > tolerance ? 1 : 0;
        guidedDifference += std::abs(double(guided[i]) - unguided[i]);
    }
    EXPECT_EQ(noneApart, 0u);
    EXPECT_EQ(setAsideApart, 0u);
    EXPECT_GT(guidedDifference, 1e-2 * double(unguided.size()) / 3.0);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// The megakernel baseline guides with the same GLSL functions: the same training, the same
// guide, the same samples as the wavefront.
TEST(Guiding, MegakernelTracesTheSameGuidedImage) {
    Scene scene = loadScene("glass_caustic");
    RenderSettings settings = settingsFor(16, 5, true);
    RenderResult wavefront = renderScene(scene, settings);
    settings.megakernel = true;
    RenderResult megakernel = renderScene(scene, settings);
    MeanAndError a = imageMean(wavefront.rgb), b = imageMean(megakernel.rgb);
    EXPECT_NEAR(a.mean, b.mean, 1e-4 * a.mean);
    EXPECT_EQ(megakernel.stats.nonFiniteSamples, 0u);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// A frozen guide that sends all of its share straight down (-y, the Cornell box's floor),
// whatever the light: the BSDF's share still covers every direction the BSDF does. parallax:
// a guide over every direction (most towards +x) reprojected through a wrong centre (the
// box's corner) at a wrong distance, so the Jacobians vary over the scene and the
// directions; the mixture's pdf is still the one sampled.
void expectWrongGuideUnbiased(bool parallax) {
    static ShaderCompiler compiler;
    Scene scene = loadScene("cornell_box");
    Reference reference = unguidedReference(scene);
    PreparedScene prepared = prepareScene(scene);
    std::vector<std::vector<float>> images;
    for (uint32_t seed = 1; seed <= 8; ++seed) {
        RenderSettings settings = settingsFor(32, seed, true);
        settings.guideMaxIterations = 0;
        settings.guideMaxDepth = settings.maxDepth; // the wrong guide at every vertex
        WavefrontRenderer renderer(gpuContext(), prepared, settings, compiler);
        const guiding::SDTree& current = renderer.guide()->tree();
        guiding::SDTree wrong(current.boxLo(), current.boxLo() + current.boxSize());
        for (int iteration = 0; iteration < 3; ++iteration) { // a deep, peaked frozen quadtree
            for (int i = 0; i < 64 && !parallax; ++i)
                wrong.record(current.boxLo() + 0.5f * current.boxSize(),
                             glm::vec3(0.0f, -1.0f, 0.0f), 1.0);
            // With parallax: mass over every direction, most towards +x, so that the
            // Jacobians weigh wherever the BSDF samples.
            for (int i = 0; i < 4096 && parallax; ++i) {
                glm::vec3 w = gpu_types::guideSquareToDir(
                    glm::vec2((float(i % 64) + 0.5f) / 64.0f, (float(i / 64) + 0.5f) / 64.0f));
                float x = std::max(0.0f, w.x);
                wrong.record(current.boxLo() + 0.5f * current.boxSize(), w,
                             1.0 + 30.0 * x * x * x * x);
            }
            wrong.endIteration(1e30, 0.01, 12);
        }
        EXPECT_GT(wrong.stats().maxDirDepth, 3u);
        if (parallax) {
            wrong.leaf(0).samplingCentre = current.boxLo();
            wrong.leaf(0).radianceDistance = 0.05f * current.boxSize().x;
        }
        renderer.guide()->setTree(std::move(wrong));
        renderer.render();
        EXPECT_EQ(renderer.stats().nonFiniteSamples, 0u);
        images.push_back(renderer.readImage());
    }
    EXPECT_EQ(expectRegionsUnbiased(images, reference.rgb, reference.variance, kSize, kSize,
                                    kBlock, parallax ? "cornell_box wrong parallax" : "cornell_box wrong guide"),
              16);
}

TEST(Guiding, WrongFrozenGuideStaysUnbiased) { expectWrongGuideUnbiased(false); }

TEST(Guiding, WrongParallaxStaysUnbiased) { expectWrongGuideUnbiased(true); }

} // namespace
} // namespace wf::test
