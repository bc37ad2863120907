// Shading split by material kind (src/passes/shade_kinds.h): scenes of several kinds shade each
// kind in a pass of its own and render what one shade pass renders; scenes of one kind keep
// the one pass, its shaders and its buffers.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "gpu_test_util.h"
#include "render/gpu_scene/scene_buffers.h"
#include "scene/gltf/gltf_loader.h"

namespace wf::test {
namespace {

RenderSettings splitSettings(bool split, uint32_t seed) {
    RenderSettings settings;
    settings.width = 48;
    settings.height = 48;
    settings.samplesPerPixel = 16;
    settings.maxDepth = 8;
    settings.seed = seed;
    settings.shadeSplit = split ? ShadeSplit::On : ShadeSplit::Off;
    return settings;
}

// The Cornell box with a mirror (specular kind), a rough metal (general) and Lambert walls.
Scene mixedCornell() {
    Scene scene = loadGltf(WF_TEST_SCENE_DIR "/cornell_box.gltf");
    Material& red = scene.materials[1];
    red.metallic = 1.0f;
    red.roughness = 0.0f;
    Material& green = scene.materials[2];
    green.metallic = 1.0f;
    green.roughness = 0.3f;
    return scene;
}

std::string definedValue(const ShaderDefines& defines, const std::string& name) {
    for (const auto& [key, value] : defines)
        if (key == name)
            return value;
    return "";
}

struct SplitCase {
    const char* name;
    Scene scene;
    const char* bins; // WF_SHADE_BINS with the split on
};

std::vector<SplitCase> mixedScenes() {
    return {{"mirror, rough metal, Lambert", mixedCornell(), "3"},
            {"glass_caustic (glass, Lambert)", loadGltf(WF_TEST_SCENE_DIR "/glass_caustic.gltf"),
             "2"}};
}

// Paired per pixel, so the image's structure cancels: the mean difference over its standard
// error.
double pairedZ(const std::vector<float>& a, const std::vector<float>& b) {
    const size_t n = a.size();
    double sum = 0.0, sumSq = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double d = double(a[i]) - double(b[i]);
        sum += d;
        sumSq += d * d;
    }
    const double mean = sum / n;
    const double variance = std::max(0.0, sumSq / n - mean * mean) * n / (n - 1);
    return std::abs(mean) / std::max(std::sqrt(variance / n), 1e-12);
}

TEST(ShadeSplit, MixedScenesShadeByKindAndRenderTheSameImage) {
    ShaderCompiler compiler;
    for (const SplitCase& c : mixedScenes()) {
        SCOPED_TRACE(c.name);
        PreparedScene prepared = prepareScene(c.scene);
        WavefrontRenderer split(gpuContext(), prepared, splitSettings(true, 5), compiler);
        EXPECT_EQ(definedValue(split.shaderDefines(), "WF_SHADE_BINS"), c.bins);
        split.render();
        WavefrontRenderer single(gpuContext(), prepared, splitSettings(false, 5), compiler);
        EXPECT_EQ(definedValue(single.shaderDefines(), "WF_SHADE_BINS"), "");
        single.render();
        // The same estimator and samples: the same image up to float rounding.
        const std::vector<float> a = split.readImage(), b = single.readImage();
        ASSERT_EQ(a.size(), b.size());
        for (size_t i = 0; i < a.size(); ++i)
            ASSERT_NEAR(a[i], b[i], 1e-4f * std::max(1.0f, std::abs(b[i]))) << i;
        EXPECT_EQ(split.stats().extensionRays, single.stats().extensionRays);
        EXPECT_GT(split.stats().passMilliseconds.count("shade diffuse"), 0u);
        EXPECT_EQ(split.stats().passMilliseconds.count("shade"), 0u);
        // Another seed: independent noise, the same mean.
        WavefrontRenderer other(gpuContext(), prepared, splitSettings(false, 6), compiler);
        other.render();
        const double z = pairedZ(a, other.readImage());
        EXPECT_LT(z, 4.0) << "split against one pass on another seed";
        std::printf("%s: |z| = %.2f\n", c.name, z);
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// bench --compare-megakernel: the megakernel ignores the bins but shares the scene buffers
// they ride in, and traces the same image.
TEST(ShadeSplit, MegakernelSharesTheSplitScenesBuffers) {
    PreparedScene prepared = prepareScene(mixedCornell());
    ShaderCompiler compiler;
    WavefrontRenderer split(gpuContext(), prepared, splitSettings(true, 2), compiler);
    RenderSettings mega = splitSettings(true, 2);
    mega.megakernel = true;
    WavefrontRenderer megakernel(gpuContext(), prepared, mega, compiler, split.sceneBuffers());
    split.render();
    megakernel.render();
    const std::vector<float> a = split.readImage(), b = megakernel.readImage();
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i)
        ASSERT_NEAR(a[i], b[i], 1e-3f * std::max(1.0f, std::abs(b[i]))) << i;
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(ShadeSplit, SceneOfOneKindKeepsOneShadePass) {
    PreparedScene prepared = prepareScene(loadGltf(WF_TEST_SCENE_DIR "/cornell_box.gltf"));
    ShaderCompiler compiler;
    WavefrontRenderer renderer(gpuContext(), prepared, splitSettings(true, 1), compiler);
    EXPECT_EQ(definedValue(renderer.shaderDefines(), "WF_SHADE_BINS"), "");
    EXPECT_EQ(definedValue(renderer.shaderDefines(), "WF_BSDF_DIFFUSE_ONLY"), "1");
    for (const auto& [name, bytes] : renderer.memoryReport())
        EXPECT_NE(name, "shade bins");
    renderer.render();
    EXPECT_EQ(renderer.stats().passMilliseconds.count("shade"), 1u);
    EXPECT_EQ(renderer.stats().passMilliseconds.count("shade diffuse"), 0u);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
