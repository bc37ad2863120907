// What `wavefront converge` reports from its measurements: per checkpoint the median and
// interquartile range across seeds, per method the fitted convergence slopes and the time to
// reach a target relMSE, and the ranking by that time.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "render/convergence.h"

namespace wf {

struct CheckpointSummary {
    uint32_t spp = 0;
    double gpuSeconds = 0.0;  // medians across seeds
    double wallSeconds = 0.0;
    double relMse = 0.0;      // median, and the quartiles around it
    double relMseLow = 0.0;
    double relMseHigh = 0.0;
    double mse = 0.0;
    double bias = 0.0;        // median of the signed mean error
    double estimatedRelMse = 0.0; // median of the renders' own estimates
    double estimateReliable = 0.0; // share of the seeds whose estimate says it is reliable
};

struct MethodSummary {
    std::string name;
    std::vector<CheckpointSummary> points;
    double slopeSpp = 0.0;  // d log relMSE / d log spp (Monte Carlo: -1)
    double slopeTime = 0.0; // d log relMSE / d log GPU time
    double timeToTarget = 0.0; // GPU seconds to reach the target relMSE
    bool extrapolated = false; // the target lies beyond the measurements
};

// Quantile by linear interpolation between order statistics (q in [0, 1]).
double quantile(std::vector<double> values, double q);
// Least-squares slope of log y against log x over points with positive x and y.
double logLogSlope(const std::vector<double>& x, const std::vector<double>& y);

// Summary without the target-dependent fields; slopes fit checkpoints of 4 spp and more
// (fewer than 3 such: all of them), past the first samples' pre-asymptotic wobble.
MethodSummary summarize(const MethodRun& run);
// When the median relMSE first reaches `target`: interpolated in log-log between checkpoints,
// or extrapolated along the fitted time slope past the last one (or before the first; a
// method below the target from the start but not improving gets its first checkpoint's time).
// Infinite when the target lies ahead and the error does not fall.
void setTimeToTarget(MethodSummary& summary, double target);
// The default target: the median over methods of their final median relMSE, so that about
// half the methods reach it within their budget.
double defaultTarget(const std::vector<MethodSummary>& summaries);
// Indices of `summaries`, fastest to the target first.
std::vector<size_t> rankByTimeToTarget(const std::vector<MethodSummary>& summaries);

} // namespace wf
