// Every render's own error estimate (image/error_estimate.h) and --target-error's promise, on
// the laboratory's scenes, each against a 16,384-spp reference of the same 32x32 image:
// - calibration: at 64 and 1,024 spp over four seeds, with two error replicates (the
//   independent sampler needs none), the estimate lies within 0.7-1.4 of the measured relMSE
//   for sobol, halton, bluenoise and independent samples, unless it says it is unreliable; one
//   sequence of sobol keeps its upper bound;
// - targets: at two targets per scene over 5 seeds, no render says targetMet with a measured
//   error above the target by more than the estimate's stated standard error, and where the
//   first and final estimates were reliable the median delivered error is at least half the
//   target
//   (a target costs what it needs, not several times that);
// - the adaptive rounds stay unbiased: each 8x8 region's mean over the ten target renders
//   agrees with the reference within 5 standard errors.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gpu_test_util.h"
#include "image/error_metrics.h"
#include "render/adaptive_sampling.h"
#include "render/gpu_scene/scene_buffers.h"
#include "scene/gltf/gltf_loader.h"

namespace wf::test {
namespace {

constexpr uint32_t kSize = 32, kBlock = 8, kReferenceSpp = 16384, kMaxSpp = 1024;

struct SceneCase {
    const char* name;
    double targets[2]; // relMSE: one most seeds reach, one harder
};

void PrintTo(const SceneCase& test, std::ostream* out) { *out << test.name; }

RenderSettings settingsFor(uint32_t spp, uint32_t seed, SamplerKind sampler) {
    RenderSettings settings;
    settings.width = kSize;
    settings.height = kSize;
    settings.samplesPerPixel = spp;
    settings.maxDepth = 8;
    settings.seed = seed;
    settings.sampler = sampler;
    return settings;
}

class ErrorTargets : public ::testing::TestWithParam<SceneCase> {};

TEST_P(ErrorTargets, EstimateCalibratedAndTargetsHonest) {
    const SceneCase& test = GetParam();
    const Scene scene = loadGltf(std::string(WF_TEST_SCENE_DIR) + "/" + test.name + ".gltf");
    RenderSettings referenceSettings = settingsFor(kReferenceSpp, 4242, SamplerKind::Sobol);
    referenceSettings.aov = true; // its variance layer: the reference's own noise per region
    const RenderResult reference = renderScene(scene, referenceSettings);

    auto measure = [&](SamplerKind sampler, uint32_t spp, uint32_t seed, uint32_t replicates) {
        RenderSettings settings = settingsFor(spp, seed, sampler);
        settings.errorReplicates = replicates;
        const RenderResult result = renderScene(scene, settings);
        const double measured = imageError(result.rgb, reference.rgb).relMse;
        const ErrorEstimate& e = result.estimate;
        std::printf("%s %s %u spp seed %u, %u replicates: measured %.4g, estimate %s%s "
                    "(ratio %.2f, %.0f effective pixels)\n",
                    test.name, samplerName(sampler), spp, seed, e.replicates, measured,
                    describeErrorEstimate(e).c_str(), e.reliable ? "" : (": " + e.reason).c_str(),
                    e.relMse / measured, e.effectivePixels);
        return std::pair{e, e.relMse / measured};
    };
    for (SamplerKind sampler : {SamplerKind::Independent, SamplerKind::Sobol, SamplerKind::Halton,
                                SamplerKind::BlueNoise})
        for (uint32_t spp : {64u, 1024u})
            for (uint32_t seed = 1; seed <= 4; ++seed) {
                const auto [e, ratio] = measure(sampler, spp, seed, kTargetErrorReplicates);
                EXPECT_FALSE(e.upperBound);
                EXPECT_EQ(e.replicates, sampler == SamplerKind::Independent ? 1u : 2u);
                if (!e.reliable)
                    continue;
                EXPECT_GE(ratio, 0.7) << test.name << " " << samplerName(sampler) << " " << spp;
                EXPECT_LE(ratio, 1.4) << test.name << " " << samplerName(sampler) << " " << spp;
            }
    // One sequence of a correlated sampler: the variance of independent samples, a bound.
    const auto [bound, boundRatio] = measure(SamplerKind::Sobol, 64, 1, 1);
    EXPECT_TRUE(bound.upperBound);
    if (bound.reliable)
        EXPECT_GE(boundRatio, 0.7) << test.name << ": sobol's bound";

    static ShaderCompiler compiler;
    PreparedScene prepared = prepareScene(scene);
    RenderSettings adaptiveSettings = settingsFor(kMaxSpp, 0, SamplerKind::Sobol);
    adaptiveSettings.pixelList = true;
    adaptiveSettings.errorReplicates = kTargetErrorReplicates;
    WavefrontRenderer renderer(gpuContext(), prepared, adaptiveSettings, compiler);
    std::vector<std::vector<float>> images;
    for (double target : test.targets) {
        std::vector<double> delivered; // where the final estimate was reliable
        for (uint32_t seed = 31; seed < 36; ++seed) {
            AdaptiveSettings adaptive;
            adaptive.targetError = target;
            adaptive.maxSpp = kMaxSpp;
            AdaptiveResult result = renderAdaptive(renderer, seed, adaptive, kSize, kSize);
            const double error = imageError(result.rgb, reference.rgb).relMse;
            std::printf("%s target %g seed %u: measured %.4g (%.2f of it), estimate %s, "
                        "targetMet %d (%s), %u image rounds, %.1f image spp, %.1f spp traced, "
                        "gain %.2f, slope %.2f, %.2f s\n",
                        test.name, target, seed, error, error / target,
                        describeErrorEstimate(result.estimate).c_str(), result.targetMet,
                        result.stoppedBy.c_str(), result.imageRounds, result.meanSpp,
                        double(result.stats.paths) / (kSize * kSize), result.plannedGain, result.errorSlope,
                        result.stats.seconds);
            EXPECT_EQ(result.stats.nonFiniteSamples, 0u);
            EXPECT_FALSE(result.estimate.upperBound);
            if (result.targetMet)
                EXPECT_LE(error, target + result.estimate.standardError)
                    << test.name << " says it met " << target;
            // Where every pixel has the fewest samples a round gives, no plan could spend less.
            const bool floor = std::all_of(
                result.sampleCounts.begin(), result.sampleCounts.end(),
                [&](float n) { return n <= float(result.allocation.levels.front()); });
            // The plan is judged where it planned from reliable evidence: after an unreliable
            // first image, rounds double for evidence (many lamps at 32x32: 0.25-0.46x).
            if (result.estimate.reliable && result.firstImageReliable && !floor)
                delivered.push_back(error);
            images.push_back(std::move(result.rgb));
        }
        std::sort(delivered.begin(), delivered.end());
        if (delivered.size() >= 3)
            EXPECT_GE(delivered[delivered.size() / 2], 0.5 * target)
                << test.name << ": median delivered error, target " << target;
    }

    // Unbiased: each region's mean over the target renders against the reference's.
    expectRegionsUnbiased(images, reference.rgb, reference.aov.variance, kSize, kSize, kBlock,
                          test.name);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Laboratory, ErrorTargets,
    ::testing::Values(SceneCase{"cornell_box", {3e-3, 3e-4}},
                      SceneCase{"tiny_light", {1e-5, 1e-6}},
                      SceneCase{"veach_mis", {1e-2, 2e-3}},
                      SceneCase{"glass_caustic", {5e-2, 1e-2}},
                      SceneCase{"many_lamps", {5e-2, 1e-2}},
                      SceneCase{"sphere_near_floor", {1e-2, 1e-3}}),
    [](const ::testing::TestParamInfo<SceneCase>& info) { return std::string(info.param.name); });

} // namespace
} // namespace wf::test
