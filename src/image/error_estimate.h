// Every render's estimate of its own error (made from the film's moments by
// render/film_error.h), as EXR headers, JSON and progress lines carry it: made from the film's moments (the sums, the sums of
// squares and the largest sample of each pixel), on the scale `wavefront converge` measures
// against a reference: relMSE = mean over pixels and channels of (x - r)^2 / (r^2 + epsilon).
//
// Per pixel and channel, the expected squared error of the mean is the variance of one sample
// over n, estimated from the same samples; r^2 is estimated by mean^2 - that variance (an
// unbiased estimate of r^2, where mean^2 alone is too large by exactly it), but at least
// mean^2 / 2. The image's estimate is their mean.
//
// How far to trust it: a variance estimate is only as good as the samples that show the
// variance. Where one bright sample carries most of a pixel's sum of squares (a caustic path
// found once, a tiny light hit once), the pixel's variance is known only to within its own
// size, and where no sample has found such a path yet, not at all. The estimate carries its
// own standard error, from a bound on each pixel's fourth moment (sum x^4 <= largest^2 sum x^2,
// so the relative variance of the variance estimate is at most largest^2 / sum x^2 and at
// least the 2 / (n - 1) of a normal): a few fireflies, each carrying its pixel, make it large.
// It is `reliable` when that is small and when at most half of the estimate rests on pixels
// whose largest sample holds over half their sum of squares: where a bright path turns up in
// about one sample per pixel, the pixels that have not found it yet look quiet, and the
// estimate misses their error (measured: half of it where half the pixels found one). docs/architecture.md ("Error estimates") has the
// measured calibration.
#pragma once
#include <cstdint>
#include <string>
#include <vector>


namespace wf {

struct ErrorEstimate {
    double relMse = 0.0;            // the image's estimated relMSE
    double standardError = 0.0;     // of relMse itself
    double singleSampleShare = 0.0; // of relMse, in pixels one sample dominates
    // (sum e_i)^2 / sum e_i^2 over the pixels' estimates e_i: how many pixels carry it. One
    // render's error scatters around its expectation by about sqrt(2 / effectivePixels).
    double effectivePixels = 0.0;
    uint32_t pixels = 0;            // pixels with at least two samples (the estimate's base)
    uint32_t pixelsTotal = 0;
    bool reliable = false;
    std::string reason; // why not reliable (empty when it is)
    // The variance of a pixel's mean is that of independent samples. With every sampler but
    // `independent` the samples are correlated by design (stratified, low-discrepancy) and
    // their mean's error is lower: with one sequence the estimate is then an upper bound, 1.5x
    // to over 80x above the measured error on the laboratory's scenes (docs/architecture.md);
    // with error replicates it is not (see `replicates`).
    bool upperBound = false;
    // How it was made: 1 from the samples' variance, K > 1 from the spread of K independently
    // randomized replicates (--error-replicates), which measures correlated samplers' error
    // without bias: then no upper bound.
    uint32_t replicates = 1;
};

// The thresholds of `reliable`: the estimate's relative standard error (about 25 fireflies
// seen, where they carry it), and its share in pixels one sample dominates (which a few
// samples of any distribution do: exponential samples reach a third at 16 spp). On the
// laboratory's scenes (tests/gpu/test_error_targets) the reliable estimates lay within a
// factor of 2 of the measured relMSE (docs/architecture.md).
inline constexpr double kReliableRelativeError = 0.2;
inline constexpr double kReliableSingleSampleShare = 0.5;
// And the pixels that carry it: where fewer do, one render's error scatters around its
// expectation by more than sqrt(2 / 50) = 0.2 of it (Veach's plates and the sphere near the
// floor at 32x32 rest on 2-40 pixels; docs/architecture.md).
inline constexpr double kReliableEffectivePixels = 50.0;

// Sets `reliable` and `reason` from the other fields and the thresholds above.
void judgeErrorEstimate(ErrorEstimate& estimate);

// The estimate of a sample-weighted merge of renders (checkpoint + rest, merge's parts):
// sum of (n_k / N)^2 relMse_k, with N the total. Not reliable where any part is not. The parts
// of one render are sample ranges of one sequence: `correlated` (every sampler but
// independent) says their errors may partly cancel, so the sum bounds the merge's from above.
ErrorEstimate mergeErrorEstimates(const std::vector<ErrorEstimate>& parts,
                                  const std::vector<double>& samplesPerPixel,
                                  bool correlated);

// "0.0123 (+-0.0011)", "<= 0.0123 (+-0.0011)" (an upper bound) or "0.0123 (unreliable)", for
// progress lines and warnings.
std::string describeErrorEstimate(const ErrorEstimate& estimate);

} // namespace wf
