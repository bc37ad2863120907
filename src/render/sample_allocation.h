// Where an adaptive render puts its samples (render/adaptive_sampling.h runs the rounds): each
// pixel's relative variance from a pilot, the shape that spreads samples by it, the levels
// counts come in, and the allocation that meets a target or spends a budget.
#pragma once
#include <cstdint>
#include <vector>

#include "render/film_readback.h"

namespace wf {

struct AdaptiveSettings {
    double targetError = 0.0; // the image relMSE to reach; 0: spend meanSpp instead
    double meanSpp = 0.0;     // the budget, samples per pixel on average (targetError 0)
    uint32_t maxSpp = 64;     // no pixel gets more (--spp)
    uint32_t pilotSpp = 0;    // 0: pilotSppFor(maxSpp)
    double timeLimitSeconds = 0.0; // --time-limit with a target: no round starts past it (0: none)
    uint32_t maxRounds = 8;   // image rounds at most (with a target)
    bool powerOfTwoLevels = false; // sampleLevels' powersOfTwo (renderAdaptive: base-2 samplers)
};

uint32_t pilotSppFor(uint32_t maxSpp); // maxSpp / 16, within 4 .. 16 (and at most maxSpp)
uint32_t minSppFor(uint32_t pilotSpp); // the fewest samples a pixel gets: half the pilot's

// Per pixel, the relMSE of one sample as converge measures error: the mean over channels of
// variance / (mean^2 + kRelMseEpsilon), from the pilot's sums (0 for fewer than 2 samples).
std::vector<double> relativeSampleVariance(const FilmMoments& pilot);
// Per pixel, the estimated relMSE of its mean: the above over its sample count.
std::vector<double> relativeErrorOfMean(const FilmMoments& film);
double meanOf(const std::vector<double>& values);

// Each pixel's largest value over its 3x3 neighbourhood: a pilot that found a rare bright path
// at one pixel is likely to have missed it at the next.
std::vector<double> dilate3x3(const std::vector<double>& values, uint32_t width,
                              uint32_t height);

// Where samples go: the dilated variance, but at least kDefensiveShare of its image mean, so
// that a pixel the pilot saw as quiet still gets sqrt(kDefensiveShare) of the typical count
// (the pilot misses rare bright paths; a quiet pixel with few samples that meets one is a
// firefly): the defensive mixture of defensive importance sampling.
inline constexpr double kDefensiveShare = 0.1;
std::vector<double> defensiveShape(const std::vector<double>& relVariance, uint32_t width,
                                   uint32_t height);

// Sample counts come in levels, so that the image renders in few rounds (each round traces
// the pixels whose count reaches its level): minSpp, then about 1.25x each, ending at maxSpp.
// With `powersOfTwo`, minSpp then the powers of two above it, ending at maxSpp: a base-2
// (0, 2)-sequence's prefix is a net only at a power of two, and Sobol's error at counts between
// them is measured far above its trend (the tiny light: 12 spp gave 3x the relMSE of 16).
std::vector<uint32_t> sampleLevels(uint32_t minSpp, uint32_t maxSpp, bool powersOfTwo = false);

struct SampleAllocation {
    std::vector<uint32_t> spp;    // per pixel, one of `levels`
    std::vector<uint32_t> levels; // increasing
    double predictedRelMse = 0.0; // mean over pixels of relVariance / spp
    double meanSpp = 0.0;
    bool targetMet = true;        // false when even maxSpp everywhere predicts above target
};

// n_i = the level nearest (in ratio) to c sqrt(shape_i), within [minSpp, maxSpp], with c the
// smallest that predicts the target, or the largest within the budget. `shape` decides where
// samples go (the dilated variance), `relVariance` predicts the error they give.
SampleAllocation allocateSamples(const std::vector<double>& relVariance,
                                 const std::vector<double>& shape,
                                 const AdaptiveSettings& settings);

} // namespace wf
