#include "render/guiding/guiding_schedule.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "errors.h"
#include "passes/shade_kinds.h"
#include "render/gpu_scene/scene_buffers.h"

namespace wf::guiding {

GuideSchedule::GuideSchedule(uint32_t budgetSpp, double timeLimitSeconds, uint32_t maxIterations)
    : budget_(budgetSpp), limit_(timeLimitSeconds), maxIterations_(maxIterations) {}

uint32_t GuideSchedule::nextTrainingSpp(uint32_t samplesDone, double seconds) {
    if (iterations_ >= maxIterations_ || nextSpp_ == 0 || unused_.stopped())
        return 0;
    const uint32_t spp = nextSpp_;
    // The image keeps at least half of the samples...
    if (2ull * (uint64_t(samplesDone) + spp) > budget_)
        return 0;
    // ...and of the time: the pace so far (every sample so far trained) says how long this
    // iteration takes. The first iteration has no pace and always runs.
    if (limit_ > 0.0 && samplesDone > 0) {
        const double pace = seconds / samplesDone;
        if (seconds + pace * spp > 0.5 * limit_)
            return 0;
    }
    ++iterations_;
    nextSpp_ = spp >= (1u << 30) ? 0 : 2 * spp;
    return spp;
}

void UnusedGuideStop::endIteration(bool guidePays, uint64_t pixelSamples) {
    ++iterations_;
    pixelSamples_ += pixelSamples;
    unusedStreak_ = guidePays ? 0 : unusedStreak_ + 1;
    // The iteration that just ended has index iterations_ - 1.
    if (unusedStreak_ >= kUnusedIterationsToStop && iterations_ >= kFirstUnusedStop + 1 &&
        pixelSamples_ >= kMinStopPixelSamples)
        stopped_ = true;
}

uint32_t GuideSchedule::nextImageSpp(uint32_t samplesDone, double seconds) {
    if (samplesDone >= budget_)
        return 0;
    const uint32_t left = budget_ - samplesDone;
    if (!imageStarted_) {
        imageStarted_ = true;
        imageFirstSample_ = samplesDone;
        imageFirstSecond_ = seconds;
        if (limit_ <= 0.0)
            return left;
        // The training pace (records, splats and rebuilds included: slower than the image's)
        // bounds the first pass; it runs even past the limit, so the image has a sample.
        if (samplesDone == 0)
            return 1;
        const double fit = (limit_ - seconds) / (seconds / samplesDone);
        return static_cast<uint32_t>(std::clamp(std::floor(fit), 1.0, double(left)));
    }
    if (limit_ <= 0.0)
        return left;
    const uint32_t imageSamples = samplesDone - imageFirstSample_;
    const double imageSeconds = seconds - imageFirstSecond_;
    if (imageSamples == 0)
        return 1;
    // Whole passes only, as many as the image phase's pace says still fit (render()'s rule).
    const double fit = (limit_ - seconds) / (imageSeconds / imageSamples);
    if (fit < 1.0)
        return 0;
    return static_cast<uint32_t>(std::min(std::floor(fit), double(left)));
}

uint32_t progressiveTrainingEnd(uint32_t iteration, uint32_t maxIterations) {
    if (iteration >= maxIterations || iteration >= 31)
        return 0;
    return 1u << iteration;
}

GuidingMode parseGuidingMode(const std::string& word) {
    if (word == "off")
        return GuidingMode::Off;
    if (word == "on")
        return GuidingMode::On;
    if (word == "auto")
        return GuidingMode::Auto;
    throw UsageError("--guiding: expected off, on or auto, got '" + word + "'");
}

GuideSceneTraits guideSceneTraits(const PreparedScene& scene) {
    GuideSceneTraits traits;
    const uint32_t kinds = shadeKindsPresent(scene.materials);
    traits.nonDelta = (kinds & ((1u << uint32_t(ShadeKind::Diffuse)) |
                                (1u << uint32_t(ShadeKind::General)))) != 0;
    traits.delta = (kinds & (1u << uint32_t(ShadeKind::Specular))) != 0;
    traits.emits = !scene.lights.emitters.empty() ||
                   scene.lights.environmentEmitter != WF_NO_EMITTER || scene.environment.present();
    return traits;
}

namespace {

// Measured on lavapipe (Mesa 25.0.7, 2 cores), docs/guiding.md "auto" and "Current figures":
// guided over unguided MIS efficiency at equal time (training included), the least over the
// image sizes and budgets measured, as auto must not lose. Caustic scenes (the glass
// caustic): 0.94-1.00x at 64x64 over 0.75-8 s (converge, 5 seeds), 0.98x at the gallery's
// 128x128 and 256 spp (training stops there: no leaf's share pays). Diffuse and glossy ones:
// the dark narrow gap 2.2-2.8x over 0.5-8 s, but the Cornell box 0.98-1.00x over 0.25-1.5 s
// (64x64) and 0.94x in the gallery, whose other scenes read 0.96-1.04x (training stopped).
// Every gain but the narrow gap's is the cost of 7 spp of training, the guide then unused.
constexpr double kCausticEqualTimeGain = 0.94;
constexpr double kDiffuseEqualTimeGain = 0.94;

} // namespace

GuidingDecision decideGuiding(GuidingMode mode, const GuideSceneTraits& traits,
                              uint32_t budgetSpp) {
    GuidingDecision decision;
    if (mode != GuidingMode::Auto) {
        decision.on = mode == GuidingMode::On;
        decision.reason = decision.on ? "on (asked)" : "off (asked)";
        return decision;
    }
    if (!traits.nonDelta || !traits.emits) {
        decision.reason = !traits.emits ? "auto: off (nothing emits)"
                                        : "auto: off (no non-delta surface to guide at)";
        return decision;
    }
    // Training takes samples from the image: fewer than 4 spp leave it nothing to learn from.
    if (budgetSpp < 4) {
        decision.reason = "auto: off (under 4 spp: too few samples to train a guide on)";
        return decision;
    }
    char line[240];
    decision.predictedGain = traits.delta ? kCausticEqualTimeGain : kDiffuseEqualTimeGain;
    decision.on = decision.predictedGain >= kAutoMinGain;
    std::snprintf(line, sizeof line,
                  "auto: %s (predicted efficiency %.2fx: measured at equal time on %s scenes; "
                  "on needs %.2fx)",
                  decision.on ? "on" : "off", decision.predictedGain,
                  traits.delta ? "caustic" : "diffuse/glossy", kAutoMinGain);
    decision.reason = line;
    return decision;
}

} // namespace wf::guiding
