// White furnace: inside a closed box whose walls emit E and reflect albedo a, every path sees
// L = E + a L, so L = E / (1 - a) exactly, at every pixel. Emission is counted both by NEE and
// by BSDF-sampled hits, so counting it twice (or missing an MIS weight) shows up at once.
#include <cmath>

#include <glm/gtc/packing.hpp>
#include <gtest/gtest.h>

#include "gpu_test_util.h"

namespace wf::test {
namespace {

class Furnace : public ::testing::TestWithParam<float> {};

TEST_P(Furnace, RadianceIsEmissionOverOneMinusAlbedo) {
    const float albedo = GetParam();
    const float emission = 0.5f;
    RenderSettings settings;
    settings.width = 64;
    settings.height = 64;
    settings.samplesPerPixel = 64;
    settings.maxDepth = 200; // a^200 is far below the tolerance for every albedo tested
    settings.seed = 7;
    RenderResult result = renderScene(furnaceBox(albedo, emission), settings);

    const double expected = emission / (1.0 - albedo);
    MeanAndError measured = imageMean(result.rgb);
    EXPECT_EQ(result.stats.nonFiniteSamples, 0u);
    EXPECT_NEAR(measured.mean, expected, 0.005 * expected)
        << "standard error " << measured.standardError;
    // The spread must also be consistent: the mean sits within 4 standard errors.
    EXPECT_NEAR(measured.mean, expected, 4.0 * measured.standardError + 1e-6 * expected);
    for (float v : result.rgb)
        ASSERT_TRUE(std::isfinite(v));
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Albedos, Furnace, ::testing::Values(0.3f, 0.5f, 0.8f));

TEST(FurnaceDepth, MaxDepthTruncatesTheSeriesExactly) {
    // With D segments the path collects emission from D vertices: E (1 - a^D) / (1 - a).
    const float albedo = 0.5f, emission = 1.0f;
    for (uint32_t depth : {1u, 2u, 3u}) {
        RenderSettings settings;
        settings.width = 48;
        settings.height = 48;
        settings.samplesPerPixel = 32;
        settings.maxDepth = depth;
        RenderResult result = renderScene(furnaceBox(albedo, emission), settings);
        const double expected = emission * (1.0 - std::pow(albedo, depth)) / (1.0 - albedo);
        MeanAndError measured = imageMean(result.rgb);
        EXPECT_NEAR(measured.mean, expected, 0.005 * expected) << "max depth " << depth;
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// COLOR_0 multiplies the base colour: walls of albedo a painted with vertex colour c reflect
// a c, so L = E / (1 - a c); a colour that varies over a triangle averages to its mean at the
// centre of the box, which is what the per-channel colours here test (each channel its own c).
TEST(FurnaceVertexColors, ColourMultipliesTheAlbedo) {
    const float albedo = 0.8f, emission = 0.5f;
    Scene scene = furnaceBox(albedo, emission);
    const glm::vec4 colour(0.25f, 0.5f, 1.0f, 1.0f);
    const uint32_t packed = glm::packUnorm4x8(colour);
    scene.surface.colors.assign(scene.triangles.size(), {packed, packed, packed, 0u});
    RenderSettings settings;
    settings.width = settings.height = 32;
    settings.samplesPerPixel = 64;
    settings.maxDepth = 200;
    RenderResult result = renderScene(scene, settings);
    const glm::vec4 stored = glm::unpackUnorm4x8(packed); // 8-bit: 0.251, 0.502, 1
    for (int c = 0; c < 3; ++c) {
        std::vector<float> channel;
        for (size_t i = c; i < result.rgb.size(); i += 3)
            channel.insert(channel.end(), 3, result.rgb[i]);
        const double expected = emission / (1.0 - albedo * stored[c]);
        MeanAndError measured = imageMean(channel);
        EXPECT_NEAR(measured.mean, expected, 0.005 * expected + 4.0 * measured.standardError)
            << "channel " << c;
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
