// Ray-cone texture filtering on the GPU: a checker of one-texel squares far away (16 texels a
// pixel) on a white-sky-lit Lambert quad, where each sample is exactly the albedo it looked up.
// Point sampling aliases: its pixels scatter around the true pixel average. The cone's mip
// level averages the footprint: at equal spp the error against a high-spp point-sampled
// reference (the converged, pixel-filtered image) is far lower, and the mean is kept. The
// megakernel filters alike.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu_test_util.h"
#include "scene/gltf_materials.h"

namespace wf::test {
namespace {

constexpr uint32_t kSize = 32;

Scene farChecker(uint32_t texels) {
    Scene scene;
    scene.camera.position = glm::vec3(0.0f);
    scene.camera.forward = glm::vec3(0, 0, -1);
    scene.camera.up = glm::vec3(0, 1, 0);
    const float distance = 50.0f, half = 5.0f;
    scene.camera.yfov = 2.0f * std::atan(0.9f * half / distance); // the quad fills the image
    scene.hasCamera = true;
    Material m = gltf::defaultMaterial(); // exact Lambert
    m.baseColor = glm::vec4(1.0f);
    m.baseColorTexture = 0;
    scene.materials.push_back(m);
    const glm::vec3 a(-half, -half, -distance), b(half, -half, -distance),
        c(half, half, -distance), d(-half, half, -distance);
    scene.triangles.push_back({a, 0, b, WF_NO_EMITTER, c, 0});
    scene.triangles.push_back({a, 0, c, WF_NO_EMITTER, d, 0});
    scene.surface.uv0.push_back({{0, 1}, {1, 1}, {1, 0}});
    scene.surface.uv0.push_back({{0, 1}, {1, 0}, {0, 0}});
    TextureImage image;
    image.width = image.height = texels;
    for (uint32_t y = 0; y < texels; ++y)
        for (uint32_t x = 0; x < texels; ++x)
            image.rgba.push_back((x + y) % 2 ? 0xffffffffu : 0xff000000u);
    scene.surface.images.push_back(image);
    TextureRef ref{};
    ref.uRow = glm::vec3(1, 0, 0);
    ref.vRow = glm::vec3(0, 1, 0);
    ref.flags = WF_TEXTURE_SRGB;
    scene.surface.textureRefs.push_back(ref);
    scene.surface.refImage.push_back(0);
    scene.environment.width = scene.environment.height = 1;
    scene.environment.rgb = {1.0f, 1.0f, 1.0f};
    return scene;
}

RenderSettings settings(uint32_t spp, uint32_t seed, bool filtered) {
    RenderSettings s;
    s.width = s.height = kSize;
    s.samplesPerPixel = spp;
    s.maxDepth = 2; // camera ray and one bounce to the sky: each sample is the albedo
    s.lightSampling = LightSampling::Bsdf;
    s.seed = seed;
    s.textureLod = filtered;
    return s;
}

double rmse(const std::vector<float>& a, const std::vector<float>& b) {
    double sum = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
        sum += double(a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(sum / a.size());
}

TEST(TextureFiltering, FarCheckerConvergesFasterThanPointSampling) {
    const Scene scene = farChecker(512);
    const RenderResult reference = renderScene(scene, settings(1024, 1, false));
    const RenderResult filtered = renderScene(scene, settings(4, 2, true));
    const RenderResult point = renderScene(scene, settings(4, 2, false));
    const double filteredError = rmse(filtered.rgb, reference.rgb);
    const double pointError = rmse(point.rgb, reference.rgb);
    std::printf("rmse at 4 spp: filtered %.4f, point sampled %.4f\n", filteredError, pointError);
    EXPECT_LT(filteredError, 0.25 * pointError);
    // The chain keeps the mean (box filters in linear light): no bias beyond the noise of the
    // reference and the 8-bit rounding of the grey level.
    const MeanAndError ref = imageMean(reference.rgb), mean = imageMean(filtered.rgb);
    EXPECT_NEAR(mean.mean, ref.mean, 0.01);
    EXPECT_NEAR(mean.mean, 0.5, 0.02);
    EXPECT_EQ(filtered.stats.nonFiniteSamples, 0u);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(TextureFiltering, MegakernelFiltersLikeTheWavefront) {
    const Scene scene = farChecker(512);
    RenderSettings mega = settings(4, 3, true);
    mega.megakernel = true;
    const RenderResult wave = renderScene(scene, settings(4, 3, true));
    const RenderResult kernel = renderScene(scene, mega);
    mega.textureLod = false;
    const RenderResult unfiltered = renderScene(scene, mega);
    double worst = 0.0;
    for (size_t i = 0; i < wave.rgb.size(); ++i)
        worst = std::max(worst, double(std::abs(wave.rgb[i] - kernel.rgb[i])));
    EXPECT_LT(worst, 1e-4);
    EXPECT_GT(rmse(kernel.rgb, unfiltered.rgb), 0.05); // so the check above can fail
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
