// Adaptive sampling (--target-error, converge's `adaptive`) by two-stage allocation: a pilot
// render with its own seed measures each pixel's relative variance; from it alone every pixel
// gets a sample count, n_i proportional to the square root of that variance (the allocation
// that minimises the image's relMSE for its total), scaled so that the predicted image relMSE
// meets the target (or the mean meets a budget); then the image is rendered afresh with those
// counts and the pilot thrown away. The counts depend only on the pilot, whose samples are
// independent of the image's, so each pixel's mean stays unbiased; a rule that stops a pixel
// on its own samples would not be (it stops early where its samples happen to agree, which
// is where a rare bright path has not been found yet).
// With a target, the image's own error estimate (image/error_estimate.h) then decides whether
// it is done: the target is met only when that estimate is at most the target and reliable.
// Otherwise the image becomes the pilot of another round, rendered afresh with at least twice
// the samples, until the target is met, --spp caps every pixel, or the time limit comes. Only
// the last round's samples make the image (each round's counts come from earlier rounds only,
// so it stays unbiased); the earlier rounds' cost is in the timings. docs/architecture.md says
// more.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "image/error_estimate.h"
#include "render/sample_allocation.h"
#include "render/wavefront_renderer.h"

namespace wf {

// The error replicates (--error-replicates) a --target-error render takes unless told: two
// interleaved, independently scrambled halves of each pixel's samples, whose spread calibrates
// the error estimate for every sampler. Two cost Sobol's image about nothing at 1,024 spp and
// up to 10% of its relMSE at 64 (more replicates cost more: docs/architecture.md).
inline constexpr uint32_t kTargetErrorReplicates = 2;

// A target is claimed met only when the estimate stays under it by this many of its own
// standard errors: one render's error scatters around the estimate by about 1.4 of them (the
// estimate's own spread and the render's), so a claim then holds to within one standard error
// beyond the target but for chances below 1e-4.
inline constexpr double kClaimStandardErrors = 4.0;

struct AdaptiveProgress {
    std::string stage;      // "pilot", "training" (a guided pilot's iterations) or "render"
    uint32_t imageRound = 1; // with a target, the image round this stage belongs to
    uint32_t round = 0;     // 1-based within the stage
    uint32_t rounds = 0;
    uint32_t activePixels = 0;
    uint32_t level = 0;     // spp the round's pixels reach
    double seconds = 0.0;   // wall time so far, both stages
    double predictedRelMse = 0.0; // 0 until the allocation is made
};

struct AdaptiveResult {
    std::vector<float> rgb;          // the image: each pixel's mean over its samples
    std::vector<float> sampleCounts; // per pixel
    SampleAllocation allocation;
    uint32_t pilotSpp = 0;
    ErrorEstimate estimate;          // the image's own (image/error_estimate.h)
    // A target: the estimate reliable and, kClaimStandardErrors of its standard errors added,
    // at most it.
    bool targetMet = false;
    // Why the rounds stopped: "target" (met), "spp" (every pixel at --spp, or no round could
    // add samples), "time-limit", "rounds" (maxRounds), "budget" (meanSpp mode: one round).
    std::string stoppedBy;
    uint32_t imageRounds = 0;        // images rendered; all but the last were pilots
    // Each round's plan: the calibrated estimate of the evidence over the independent-sample
    // one, which scales the predicted error of an allocation (1 without replicates).
    double plannedGain = 1.0;
    // How fast the pilot's calibrated error fell with its samples: relMSE ~ n^-errorSlope
    // (1 for independent samples; 1 where the pilot could not tell).
    double errorSlope = 1.0;
    // Whether the first image's estimate was reliable: where it was not, the rounds after it
    // doubled their samples for evidence, not for the target.
    bool firstImageReliable = false;
    double meanSpp = 0.0;            // of the image
    RenderStats stats;               // every round and the pilot: paths, rays and seconds
};

// Renders with `renderer` (made with RenderSettings.pixelList and samplesPerPixel >= maxSpp):
// the pilot with a seed derived from `seed`, then the image with `seed` itself. A guided
// renderer's pilot trains the guide (iterations of 1, 2, 4, ... spp, the last one the pilot)
// and every round samples the guide frozen after it.
AdaptiveResult renderAdaptive(WavefrontRenderer& renderer, uint32_t seed,
                              const AdaptiveSettings& settings, uint32_t width, uint32_t height,
                              const std::function<void(const AdaptiveProgress&)>& onRound = {});

// The pilot's seed: another stream than `seed` and than the small seeds converge and the
// tests use.
uint32_t pilotSeedFor(uint32_t seed);

} // namespace wf
