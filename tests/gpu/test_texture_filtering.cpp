// Ray-cone texture filtering on the GPU: a checker of one-texel squares far away (16 texels a
// pixel) on a white-sky-lit Lambert quad, where each sample is exactly the albedo it looked up.
// Point sampling aliases: its pixels scatter around the true pixel average. The cone's mip
// level averages the footprint: at equal spp the error against a high-spp point-sampled
// reference (the converged, pixel-filtered image) is far lower, and the mean is kept. The
// megakernel filters alike, and cones keep their width through a mirror.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gpu_test_util.h"
#include "scene/gltf/gltf_materials.h"

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

// The checker seen in a mirror: the cone's width grows over both segments and a Dirac bounce
// adds no spread, so at the checker (10 + 10 units away, about 2.8 texels a pixel: level 1.5,
// uniform grey from level 1 on) every lookup is the same grey and two seeds give the same
// image. A cone restarted at the mirror would ask for level 0.5 there and let half of point
// sampling's aliasing noise through. (Against a reference the grey is no better than point
// sampling here: a pixel covering under three texels has a true average that beats visibly
// around 0.5; that is the blur filtering trades for noise.)
TEST(TextureFiltering, ConeWidthCarriesThroughAMirror) {
    Scene scene = farChecker(100);
    scene.camera.yfov = 2.0f * std::atan(0.1f);
    const float d = 10.0f, h = 2.2f; // mirror distance, checker half size
    Material mirror = gltf::defaultMaterial();
    mirror.baseColor = glm::vec4(1.0f);
    mirror.metallic = 1.0f;
    mirror.roughness = 0.0f;
    scene.materials.push_back(mirror);
    // Mirror through (0, 0, -d) facing (1, 0, 1): camera rays along -z turn to +x.
    const glm::vec3 o(0, 0, -d), s = glm::vec3(1, 0, -1) / std::sqrt(2.0f), t(0, 1, 0);
    const float m = 3.0f;
    scene.triangles = {
        {o - m * s - m * t, 1, o + m * s - m * t, WF_NO_EMITTER, o + m * s + m * t, 0},
        {o - m * s - m * t, 1, o + m * s + m * t, WF_NO_EMITTER, o - m * s + m * t, 0}};
    // The checker at x = d, facing -x, centred on the reflected view.
    const glm::vec3 a(d, -h, -d - h), b(d, -h, -d + h), c(d, h, -d + h), e(d, h, -d - h);
    scene.triangles.push_back({a, 0, b, WF_NO_EMITTER, c, 0});
    scene.triangles.push_back({a, 0, c, WF_NO_EMITTER, e, 0});
    scene.surface.uv0 = {{{0, 0}, {0, 0}, {0, 0}}, {{0, 0}, {0, 0}, {0, 0}}, // the mirror's, unread
                         {{0, 1}, {1, 1}, {1, 0}}, {{0, 1}, {1, 0}, {0, 0}}};
    auto noise = [&](bool filtered) { // rms difference of two seeds' images
        RenderSettings one = settings(4, 7, filtered), two = settings(4, 8, filtered);
        // The checker sees the mirror, which shows it the sky: enough segments and no roulette
        // for every path to end in the sky, so each sample is the albedo it looked up.
        one.maxDepth = two.maxDepth = 6;
        one.rrDepth = two.rrDepth = 16;
        return rmse(renderScene(scene, one).rgb, renderScene(scene, two).rgb);
    };
    const double filteredNoise = noise(true), pointNoise = noise(false);
    std::printf("seed-to-seed rms at 4 spp through the mirror: filtered %.5f, point %.4f\n",
                filteredNoise, pointNoise);
    EXPECT_GT(pointNoise, 0.02); // so the check can fail
    EXPECT_LT(filteredNoise, 0.1 * pointNoise);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
