// --aov on a scene whose first hits are known: a Lambertian floor seen through a narrow camera
// (every pixel sees a point within 1e-3 of the origin): albedo, normal and distance exact; the
// variance of each pixel's estimate agrees with the spread of pixel values over seeds; and the
// image itself does not change when the layers are on.
#include <cmath>

#include <gtest/gtest.h>

#include "analytic_scenes.h"
#include "gpu_test_util.h"

namespace wf::test {
namespace {

RenderSettings aovSettings(uint32_t seed) {
    RenderSettings settings;
    settings.width = settings.height = 16;
    settings.samplesPerPixel = 16;
    settings.maxDepth = 2;
    settings.seed = seed;
    settings.aov = true;
    return settings;
}

Scene litFloor() {
    Scene scene = floorScene(0.7f);
    scene.lights.push_back(sphereLight({0.4f, 1.5f, 0.2f}, 0.3f, glm::vec3(4.0f)));
    return scene;
}

TEST(Aov, FirstHitAlbedoNormalAndDistance) {
    RenderResult r = renderScene(litFloor(), aovSettings(1));
    const double distance = std::sqrt(8.0); // camera at (0, 2, 2), looking at the origin
    for (size_t i = 0; i < r.aov.depth.size(); ++i) {
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(r.aov.albedo[3 * i + c], 0.7f, 1e-6f) << "pixel " << i;
        EXPECT_NEAR(r.aov.normal[3 * i + 0], 0.0f, 1e-6f);
        EXPECT_NEAR(r.aov.normal[3 * i + 1], 1.0f, 1e-6f);
        EXPECT_NEAR(r.aov.normal[3 * i + 2], 0.0f, 1e-6f);
        EXPECT_NEAR(r.aov.depth[i], distance, 2e-3) << "pixel " << i;
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(Aov, LayersLeaveTheImageAsItWas) {
    RenderSettings settings = aovSettings(2);
    RenderResult with = renderScene(litFloor(), settings);
    settings.aov = false;
    RenderResult without = renderScene(litFloor(), settings);
    EXPECT_EQ(with.rgb, without.rgb);
}

// Every pixel estimates the same value here, so the spread of the pixels' values is a second
// estimate of one pixel's variance: the mean of the variance layer must agree with it.
TEST(Aov, VarianceMatchesTheSpreadOfPixels) {
    RenderSettings settings = aovSettings(3);
    settings.sampler = SamplerKind::Independent; // QMC pixels would not be independent draws
    RenderResult r = renderScene(litFloor(), settings);
    const size_t n = r.aov.depth.size();
    double mean = 0.0, meanVariance = 0.0;
    for (size_t i = 0; i < n; ++i) {
        mean += r.rgb[3 * i] / n;
        meanVariance += r.aov.variance[3 * i] / n;
    }
    double spread = 0.0;
    for (size_t i = 0; i < n; ++i)
        spread += (r.rgb[3 * i] - mean) * (r.rgb[3 * i] - mean) / (n - 1);
    ASSERT_GT(spread, 0.0);
    EXPECT_NEAR(meanVariance / spread, 1.0, 0.25) << "layer " << meanVariance << ", spread "
                                                   << spread;
}

} // namespace
} // namespace wf::test
