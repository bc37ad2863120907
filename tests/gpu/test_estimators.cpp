// Every estimator combination against closed forms: the white furnace, a Lambertian floor
// under an environment, under a sphere light, a point light and a directional light. Each
// combination must agree with the analytic value within a confidence interval, for several
// independent seeds.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "analytic_scenes.h"
#include "gpu_test_util.h"

namespace wf::test {
namespace {

struct Estimator {
    LightSampling lightSampling;
    bool triangleSolidAngle;
    bool sphereSolidAngle;
};

std::string describe(const Estimator& e) {
    return std::string(lightSamplingName(e.lightSampling)) +
           (e.triangleSolidAngle ? " triangle:solid-angle" : " triangle:area") +
           (e.sphereSolidAngle ? " sphere:solid-angle" : " sphere:area");
}

const Estimator kEstimators[] = {
    {LightSampling::Bsdf, false, false}, {LightSampling::Nee, false, false},
    {LightSampling::Nee, true, true},    {LightSampling::Mis, false, false},
    {LightSampling::Mis, true, true},
};

// Renders with `seeds` independent seeds; every seed's image mean and the pooled mean must lie
// within 4 standard errors (plus a relative floor for float rounding) of `expected`.
void expectUnbiased(const Scene& scene, const Estimator& estimator, double expected,
                    uint32_t spp, uint32_t maxDepth, int seeds = 3) {
    double pooled = 0.0, pooledVariance = 0.0;
    for (int seed = 0; seed < seeds; ++seed) {
        RenderSettings settings;
        settings.width = 24;
        settings.height = 24;
        settings.samplesPerPixel = spp;
        settings.maxDepth = maxDepth;
        settings.seed = 1000u + seed;
        settings.lightSampling = estimator.lightSampling;
        settings.triangleSolidAngle = estimator.triangleSolidAngle;
        settings.sphereSolidAngle = estimator.sphereSolidAngle;
        RenderResult result = renderScene(scene, settings);
        MeanAndError m = imageMean(result.rgb);
        EXPECT_EQ(result.stats.nonFiniteSamples, 0u) << describe(estimator);
        EXPECT_NEAR(m.mean, expected, 4.0 * m.standardError + 1e-4 * expected)
            << describe(estimator) << ", seed " << settings.seed;
        pooled += m.mean / seeds;
        pooledVariance += m.standardError * m.standardError / (seeds * seeds);
    }
    EXPECT_NEAR(pooled, expected, 4.0 * std::sqrt(pooledVariance) + 1e-4 * expected)
        << describe(estimator) << " pooled over seeds";
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(Estimators, FurnaceForEveryEstimator) {
    const float albedo = 0.5f, emission = 0.5f;
    for (const Estimator& e : kEstimators)
        expectUnbiased(furnaceBox(albedo, emission), e, emission / (1.0 - albedo), 16, 100, 2);
}

float skyRow(uint32_t row) { return 0.25f + 0.5f * float(row); } // brighter towards the horizon

TEST(Estimators, FloorUnderEnvironment) {
    const float albedo = 0.6f;
    Scene scene = floorScene(albedo);
    scene.environment = rowEnvironment(8, 8, skyRow);
    const double expected = lambertRadiance(albedo, rowEnvironmentIrradiance(8, skyRow));
    for (const Estimator& e : kEstimators)
        expectUnbiased(scene, e, expected, 32, 2);
}

TEST(Estimators, FloorUnderSphereLight) {
    // A sphere of radiance L and radius R whose centre is h above the point: E = pi L R^2/h^2,
    // exact while the whole sphere is above the horizon.
    const float albedo = 0.7f, radius = 0.5f, height = 1.5f;
    const glm::vec3 intensity(4.0f);
    Scene scene = floorScene(albedo);
    scene.lights.push_back(sphereLight({0.0f, height, 0.0f}, radius, intensity));
    const double radiance = intensity.x / (M_PI * radius * radius);
    const double expected =
        lambertRadiance(albedo, M_PI * radiance * radius * radius / (height * height));
    for (const Estimator& e : kEstimators)
        expectUnbiased(scene, e, expected, 32, 2);
}

TEST(Estimators, FloorUnderDiracLights) {
    const float albedo = 0.5f;
    Scene scene = floorScene(albedo);
    const double irradiance = addDiracLights(scene);
    const double expected = lambertRadiance(albedo, irradiance);
    for (const Estimator& e : kEstimators) {
        if (e.lightSampling == LightSampling::Bsdf)
            continue; // a Dirac light cannot be hit: documented, and the image is black
        expectUnbiased(scene, e, expected, 8, 2);
    }
}

} // namespace
} // namespace wf::test
