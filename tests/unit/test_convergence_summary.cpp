// The arithmetic of `wavefront converge`: error metrics, merging partial renders, quantiles,
// fitted slopes, time to a target relMSE, and the method list syntax.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>

#include "errors.h"
#include "image/error_metrics.h"
#include "render/convergence_summary.h"

namespace wf {
namespace {

TEST(ErrorMetrics, RelMseMseAndBias) {
    const std::vector<float> reference = {1.0f, 0.0f, 2.0f};
    const ImageError e = imageError({1.5f, 0.1f, 2.0f}, reference);
    EXPECT_NEAR(e.mse, (0.25 + 0.01) / 3.0, 1e-7);
    EXPECT_NEAR(e.relMse, (0.25 / (1.0 + kRelMseEpsilon) + 0.01 / kRelMseEpsilon) / 3.0, 1e-6);
    EXPECT_NEAR(e.bias, 0.6 / 3.0, 1e-7);
    EXPECT_GT(imageError({NAN, 0.0f, 2.0f}, reference).mse, 1e50); // NaN cannot hide
    EXPECT_THROW(imageError({1.0f}, reference), InternalError);
}

TEST(ErrorMetrics, PartsMergeBySampleCount) {
    const std::vector<float> merged = mergeBySampleCount({{1.0f, 4.0f}, {4.0f, 1.0f}}, {1, 2});
    EXPECT_FLOAT_EQ(merged[0], 3.0f);
    EXPECT_FLOAT_EQ(merged[1], 2.0f);
}

// Synthetic renders of a known truth: each value's sample mean has variance sd^2 / spp. The
// reference's noise term must make an independent image's relMSE against the reference that
// against the truth, for halves of equal and of unequal sample counts.
TEST(ErrorMetrics, ReferenceNoiseIsWhatTheReferenceAddsToRelMse) {
    std::mt19937 rng(11);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::uniform_real_distribution<double> value(0.05, 2.0);
    const size_t n = 200000;
    std::vector<double> truth(n);
    for (double& t : truth)
        t = value(rng);
    auto render = [&](double spp) {
        std::vector<float> image(n);
        for (size_t i = 0; i < n; ++i)
            image[i] = float(truth[i] + 0.5 * truth[i] / std::sqrt(spp) * normal(rng));
        return image;
    };
    for (const auto [sppA, sppB] : {std::pair{64.0, 64.0}, std::pair{32.0, 96.0}}) {
        const std::vector<float> a = render(sppA), b = render(sppB);
        const std::vector<float> reference =
            mergeBySampleCount({a, b}, {sppA, sppB});
        const std::vector<float> image = render(32.0); // a quarter of the reference's samples
        double againstTruth = 0.0;
        for (size_t i = 0; i < n; ++i) {
            const double d = double(image[i]) - truth[i];
            againstTruth += d * d / (double(reference[i]) * reference[i] + kRelMseEpsilon);
        }
        againstTruth /= double(n);
        const double raw = imageError(image, reference).relMse;
        const double noise = referenceNoiseRelMse(a, sppA, b, sppB, reference);
        EXPECT_GT(raw - againstTruth, 0.15 * againstTruth) << "the reference's noise shows";
        EXPECT_NEAR(raw - noise, againstTruth, 0.02 * againstTruth) << sppA << " + " << sppB;
    }
    EXPECT_THROW(referenceNoiseRelMse({1.0f}, 1.0, {1.0f, 2.0f}, 1.0, {1.0f}), InternalError);
}

TEST(ConvergenceSummary, QuantilesAndSlopes) {
    EXPECT_DOUBLE_EQ(quantile({5, 1, 3}, 0.5), 3.0);
    EXPECT_DOUBLE_EQ(quantile({1, 2, 3, 4, 5}, 0.25), 2.0);
    EXPECT_DOUBLE_EQ(quantile({1, 2}, 0.5), 1.5);
    std::vector<double> x, y;
    for (double n : {1.0, 4.0, 16.0, 64.0}) {
        x.push_back(n);
        y.push_back(3.0 * std::pow(n, -1.5));
    }
    EXPECT_NEAR(logLogSlope(x, y), -1.5, 1e-12);
}

MethodRun syntheticRun(const std::string& name, double scale, double slope) {
    MethodRun run;
    run.method.name = name;
    for (uint32_t spp : {1u, 2u, 4u, 8u, 16u, 32u}) {
        run.checkpoints.push_back(spp);
        for (size_t seed = 0; seed < 3; ++seed) {
            if (run.perSeed.size() <= seed)
                run.perSeed.emplace_back();
            Checkpoint c;
            c.spp = spp;
            c.gpuSeconds = 0.1 * spp;
            c.wallSeconds = 0.12 * spp;
            c.error.relMse = scale * std::pow(double(spp), slope) * (1.0 + 0.1 * double(seed));
            run.perSeed[seed].push_back(c);
        }
    }
    return run;
}

TEST(ConvergenceSummary, TimeToTargetInterpolatesAndExtrapolates) {
    MethodSummary fast = summarize(syntheticRun("fast", 1.0, -2.0));
    MethodSummary slow = summarize(syntheticRun("slow", 1.0, -1.0));
    EXPECT_NEAR(fast.slopeSpp, -2.0, 1e-9);
    EXPECT_NEAR(slow.slopeTime, -1.0, 1e-9);
    EXPECT_NEAR(fast.points[2].relMseLow, 1.05 / 16.0, 1e-9); // quartile of 1, 1.1, 1.2
    // The medians are 1.1 * spp^slope: relMSE 1.1/64 at 8 spp (fast) and 64 spp (slow).
    const double target = 1.1 / 64.0;
    setTimeToTarget(fast, target);
    setTimeToTarget(slow, target);
    EXPECT_NEAR(fast.timeToTarget, 0.8, 1e-9);
    EXPECT_FALSE(fast.extrapolated);
    EXPECT_NEAR(slow.timeToTarget, 6.4, 1e-9); // past the last checkpoint, along slope -1
    EXPECT_TRUE(slow.extrapolated);
    // Below the target from the first checkpoint on: backwards along the slope, or, when
    // the error does not fall, the first checkpoint's time as a bound; never when above.
    MethodSummary early = summarize(syntheticRun("early", 1e-3, -1.0));
    setTimeToTarget(early, 2.2e-3);
    EXPECT_NEAR(early.timeToTarget, 0.05, 1e-9);
    EXPECT_TRUE(early.extrapolated);
    MethodSummary flat = summarize(syntheticRun("flat", 1e-3, 0.1));
    setTimeToTarget(flat, 1.0);
    EXPECT_NEAR(flat.timeToTarget, 0.1, 1e-12);
    setTimeToTarget(flat, 1e-6);
    EXPECT_FALSE(std::isfinite(flat.timeToTarget));
    std::vector<MethodSummary> both = {slow, fast};
    EXPECT_EQ(rankByTimeToTarget(both).front(), 1u);
    EXPECT_NEAR(defaultTarget(both), 0.5 * (1.1 / 32.0 + 1.1 / 1024.0), 1e-12);
}

TEST(ConvergenceMethods, ParseWordsInAnyOrder) {
    EXPECT_EQ(parseMethod("sobol").name, "sobol+mis");
    EXPECT_EQ(parseMethod("nee+halton+no-randomize").name, "halton+nee+no-randomize");
    ConvergenceMethod m = parseMethod("independent+bsdf+sphere-area+triangle-area");
    EXPECT_EQ(m.sampler, SamplerKind::Independent);
    EXPECT_EQ(m.lightSampling, LightSampling::Bsdf);
    EXPECT_FALSE(m.sphereSolidAngle);
    EXPECT_FALSE(m.triangleSolidAngle);
    EXPECT_EQ(parseMethod("tree+nee").name, "sobol+nee+tree");
    EXPECT_EQ(parseMethod("uniform").lightSelection, LightSelection::Uniform);
    EXPECT_EQ(parseMethod("sobol").lightSelection, LightSelection::Auto);
    EXPECT_THROW(parseMethod("tree+power"), UsageError);
    EXPECT_EQ(parseMethods("sobol,halton+nee").size(), 2u);
    EXPECT_EQ(defaultMethods().size(), allSamplers().size() + 2);
    EXPECT_THROW(parseMethod("sobol+fast"), UsageError);
    EXPECT_THROW(parseMethod("sobol+halton"), UsageError);
    EXPECT_THROW(parseMethod("nee+mis"), UsageError);
    EXPECT_THROW(parseMethod("independent+no-randomize"), UsageError);
    EXPECT_THROW(parseMethods("sobol,sobol+mis"), UsageError);
    EXPECT_THROW(parseMethods(","), UsageError);
    EXPECT_EQ(parseMethod("adaptive+sobol").name, "sobol+mis+adaptive");
    EXPECT_TRUE(parseMethod("sobol+adaptive").adaptive);
    EXPECT_THROW(parseMethod("stratified+adaptive"), UsageError);
    EXPECT_EQ(parseMethod("guided+halton").name, "halton+mis+guided");
    EXPECT_TRUE(parseMethod("sobol+bsdf+guided").guided);
    EXPECT_FALSE(parseMethod("sobol").guided);
    EXPECT_EQ(parseMethod("sobol+guided+adaptive").name, "sobol+mis+adaptive+guided");
    EXPECT_THROW(parseMethod("guided+guided"), UsageError);
}

} // namespace
} // namespace wf
