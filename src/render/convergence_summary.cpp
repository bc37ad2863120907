#include "render/convergence_summary.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "errors.h"

namespace wf {

double quantile(std::vector<double> values, double q) {
    if (values.empty())
        throw InternalError("quantile of nothing");
    std::sort(values.begin(), values.end());
    const double at = std::clamp(q, 0.0, 1.0) * double(values.size() - 1);
    const size_t below = static_cast<size_t>(std::floor(at));
    const size_t above = std::min(below + 1, values.size() - 1);
    return values[below] + (at - double(below)) * (values[above] - values[below]);
}

double logLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
        if (!(x[i] > 0.0) || !(y[i] > 0.0))
            continue;
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        n += 1, sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
    }
    const double denominator = n * sxx - sx * sx;
    return n >= 2 && denominator > 0.0 ? (n * sxy - sx * sy) / denominator : 0.0;
}

MethodSummary summarize(const MethodRun& run) {
    MethodSummary summary;
    summary.name = run.method.name;
    for (size_t c = 0; c < run.checkpoints.size(); ++c) {
        std::vector<double> gpu, wall, rel, mse, bias, estimated;
        double reliable = 0.0;
        for (const auto& seed : run.perSeed) {
            gpu.push_back(seed[c].gpuSeconds);
            wall.push_back(seed[c].wallSeconds);
            rel.push_back(seed[c].error.relMse);
            mse.push_back(seed[c].error.mse);
            bias.push_back(seed[c].error.bias);
            estimated.push_back(seed[c].estimate.relMse);
            reliable += seed[c].estimate.reliable ? 1.0 / run.perSeed.size() : 0.0;
        }
        CheckpointSummary point;
        point.spp = run.checkpoints[c];
        point.gpuSeconds = quantile(gpu, 0.5);
        point.wallSeconds = quantile(wall, 0.5);
        point.relMse = quantile(rel, 0.5);
        point.relMseLow = quantile(rel, 0.25);
        point.relMseHigh = quantile(rel, 0.75);
        point.mse = quantile(mse, 0.5);
        point.bias = quantile(bias, 0.5);
        point.estimatedRelMse = quantile(estimated, 0.5);
        point.estimateReliable = reliable;
        summary.points.push_back(point);
    }
    std::vector<double> spp, time, error;
    const size_t asymptotic = std::count_if(summary.points.begin(), summary.points.end(),
                                            [](const CheckpointSummary& p) { return p.spp >= 4; });
    for (const CheckpointSummary& p : summary.points) {
        if (asymptotic >= 3 && p.spp < 4)
            continue;
        spp.push_back(p.spp);
        time.push_back(p.gpuSeconds);
        error.push_back(p.relMse);
    }
    summary.slopeSpp = logLogSlope(spp, error);
    summary.slopeTime = logLogSlope(time, error);
    return summary;
}

void setTimeToTarget(MethodSummary& summary, double target) {
    const auto& p = summary.points;
    summary.extrapolated = true;
    summary.timeToTarget = INFINITY;
    if (p.empty() || !(target > 0.0))
        return;
    for (size_t i = 0; i < p.size(); ++i) {
        if (p[i].relMse > target)
            continue;
        if (i == 0)
            break; // reached before the first checkpoint: extrapolate backwards below
        // Log-log interpolation between the checkpoints on either side of the target.
        const double t0 = std::log(std::max(p[i - 1].gpuSeconds, 1e-9));
        const double t1 = std::log(std::max(p[i].gpuSeconds, 1e-9));
        const double e0 = std::log(p[i - 1].relMse), e1 = std::log(p[i].relMse);
        const double f = e1 != e0 ? (std::log(target) - e0) / (e1 - e0) : 1.0;
        summary.timeToTarget = std::exp(t0 + f * (t1 - t0));
        summary.extrapolated = false;
        return;
    }
    // Along the fitted power law from the nearest end, if the error falls. Reached at the
    // first checkpoint already but not falling: that checkpoint's time, an upper bound.
    const bool early = p.front().relMse <= target;
    const CheckpointSummary& from = early ? p.front() : p.back();
    if (summary.slopeTime < 0.0 && from.relMse > 0.0)
        summary.timeToTarget =
            from.gpuSeconds * std::pow(target / from.relMse, 1.0 / summary.slopeTime);
    else if (early)
        summary.timeToTarget = from.gpuSeconds;
}

double defaultTarget(const std::vector<MethodSummary>& summaries) {
    std::vector<double> finals;
    for (const MethodSummary& s : summaries)
        if (!s.points.empty())
            finals.push_back(s.points.back().relMse);
    return finals.empty() ? 0.0 : quantile(finals, 0.5);
}

std::vector<size_t> rankByTimeToTarget(const std::vector<MethodSummary>& summaries) {
    std::vector<size_t> order(summaries.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return summaries[a].timeToTarget < summaries[b].timeToTarget;
    });
    return order;
}

} // namespace wf
