// Every sampler is progressive on the GPU: any split of a render into calls, waves or
// --spp-offset parts gives the image of one run of all the samples. Within one renderer the
// film adds samples one at a time in sample order, so splits into calls and waves are exact to
// the bit; parts rendered apart merge by their sample-weighted mean within float rounding, and
// exactly when summed in sample order. The megakernel baseline draws the same samples.
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "gpu_test_util.h"
#include "image/error_metrics.h"
#include "render/gpu_scene/scene_buffers.h"
#include "scene/gltf/gltf_loader.h"

namespace wf {
// Test names and failure messages show the sampler's name.
void PrintTo(SamplerKind kind, std::ostream* os) { *os << samplerName(kind); }
} // namespace wf

namespace wf::test {
namespace {

const uint32_t kSeed = 3;
const uint32_t kSpp = 6;

RenderSettings smallSettings(SamplerKind sampler) {
    RenderSettings settings;
    settings.width = 16;
    settings.height = 16;
    settings.samplesPerPixel = kSpp;
    settings.maxDepth = 4;
    settings.rrDepth = 1; // roulette dimensions in play
    settings.seed = kSeed;
    settings.sampler = sampler;
    settings.submitBudgetSeconds = 0.0; // fixed wave sizes, so that the test controls them
    return settings;
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

class SamplerProgressive : public ::testing::TestWithParam<SamplerKind> {
protected:
    static void SetUpTestSuite() {
        scene_ = new PreparedScene(
            prepareScene(loadGltf(std::string(WF_TEST_SCENE_DIR) + "/cornell_box.gltf")));
    }
    static void TearDownTestSuite() {
        delete scene_;
        scene_ = nullptr;
    }
    static PreparedScene* scene_;
    ShaderCompiler compiler_;
};

PreparedScene* SamplerProgressive::scene_ = nullptr;

TEST_P(SamplerProgressive, AnySplitGivesTheImageOfOneRun) {
    const SamplerKind kind = GetParam();
    WavefrontRenderer renderer(gpuContext(), *scene_, smallSettings(kind), compiler_);
    renderer.render();
    const std::vector<float> whole = renderer.readImage();
    ASSERT_EQ(renderer.samplesDone(), kSpp);

    // Several calls of renderSamples: the same bits.
    renderer.restart(kSeed, 0, 0);
    for (uint32_t part : {1u, 2u, 3u})
        renderer.renderSamples(part);
    EXPECT_TRUE(sameBits(renderer.readImage(), whole)) << samplerName(kind) << ": 1 + 2 + 3";

    // Waves of one sample over pixel ranges (100 paths per wave for 256 pixels).
    RenderSettings narrow = smallSettings(kind);
    narrow.maxPathsPerWave = 100;
    WavefrontRenderer ranged(gpuContext(), *scene_, narrow, compiler_);
    ranged.render();
    EXPECT_TRUE(sameBits(ranged.readImage(), whole)) << samplerName(kind) << ": pixel ranges";

    // The megakernel baseline draws the same samples (same sampler code and tables).
    RenderSettings mega = smallSettings(kind);
    mega.megakernel = true;
    WavefrontRenderer megakernel(gpuContext(), *scene_, mega, compiler_);
    megakernel.render();
    EXPECT_TRUE(sameBits(megakernel.readImage(), whole)) << samplerName(kind) << ": megakernel";

    // One-sample parts at every --spp-offset, summed in sample order like the film: exact.
    std::vector<float> sum(whole.size(), 0.0f);
    for (uint32_t offset = 0; offset < kSpp; ++offset) {
        renderer.restart(kSeed, offset, kSpp);
        renderer.renderSamples(1);
        const std::vector<float> part = renderer.readImage();
        for (size_t i = 0; i < sum.size(); ++i)
            sum[i] += part[i];
    }
    for (float& v : sum)
        v /= float(kSpp);
    EXPECT_TRUE(sameBits(sum, whole)) << samplerName(kind) << ": one-sample parts";

    // Parts of 2 and 4 samples merged by sample count: within float rounding.
    renderer.restart(kSeed, 0, kSpp);
    renderer.renderSamples(2);
    const std::vector<float> first = renderer.readImage();
    renderer.restart(kSeed, 2, kSpp);
    renderer.renderSamples(4);
    const std::vector<float> merged = mergeBySampleCount({first, renderer.readImage()}, {2, 4});
    for (size_t i = 0; i < whole.size(); ++i)
        ASSERT_NEAR(merged[i], whole[i], 2e-6f * std::abs(whole[i]) + 1e-7f)
            << samplerName(kind) << ": merged parts, value " << i;
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// Different seeds give different images; without randomization (except `independent`, which
// has nothing else) the seed changes nothing.
TEST_P(SamplerProgressive, SeedsMatterUnlessNotRandomized) {
    const SamplerKind kind = GetParam();
    RenderSettings settings = smallSettings(kind);
    settings.randomizeSamples = kind == SamplerKind::Independent;
    WavefrontRenderer renderer(gpuContext(), *scene_, settings, compiler_);
    renderer.render();
    const std::vector<float> a = renderer.readImage();
    renderer.restart(kSeed + 1, 0, 0);
    renderer.renderSamples(kSpp);
    EXPECT_EQ(sameBits(renderer.readImage(), a), !settings.randomizeSamples)
        << samplerName(kind);
    for (float v : a)
        ASSERT_TRUE(std::isfinite(v)) << samplerName(kind);
}

INSTANTIATE_TEST_SUITE_P(EverySampler, SamplerProgressive, ::testing::ValuesIn(allSamplers()),
                         [](const ::testing::TestParamInfo<SamplerKind>& info) {
                             return std::string(samplerName(info.param));
                         });

} // namespace
} // namespace wf::test
