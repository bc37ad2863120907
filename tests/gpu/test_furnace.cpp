// White furnace: inside a closed box whose walls emit E and reflect albedo a, every path sees
// L = E + a L, so L = E / (1 - a) exactly, at every pixel. Emission is counted both by NEE and
// by BSDF-sampled hits, so counting it twice (or missing an MIS weight) shows up at once.
#include <cmath>

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

} // namespace
} // namespace wf::test
