#include "render/sample_allocation.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>

#include "errors.h"
#include "image/error_metrics.h"

namespace wf {

uint32_t pilotSppFor(uint32_t maxSpp) {
    return std::min(maxSpp, std::clamp(maxSpp / 16u, 4u, 16u));
}

uint32_t minSppFor(uint32_t pilotSpp) { return std::max(1u, pilotSpp / 2u); }

std::vector<double> relativeSampleVariance(const FilmMoments& pilot) {
    std::vector<double> v(pilot.count.size(), 0.0);
    for (size_t i = 0; i < v.size(); ++i) {
        const double n = pilot.count[i];
        if (!(n > 1.0))
            continue;
        double sum = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double mean = pilot.sum[3 * i + c] / n;
            const double variance =
                varianceOfMean(pilot.sum[3 * i + c], pilot.squares[3 * i + c], n) * n;
            sum += variance / (mean * mean + kRelMseEpsilon);
        }
        v[i] = sum / 3.0;
    }
    return v;
}

std::vector<double> relativeErrorOfMean(const FilmMoments& film) {
    std::vector<double> error = relativeSampleVariance(film);
    for (size_t i = 0; i < error.size(); ++i)
        if (film.count[i] > 0.0f)
            error[i] /= film.count[i];
    return error;
}

double meanOf(const std::vector<double>& values) {
    return values.empty() ? 0.0
                          : std::accumulate(values.begin(), values.end(), 0.0) / values.size();
}

std::vector<double> dilate3x3(const std::vector<double>& values, uint32_t width,
                              uint32_t height) {
    if (values.size() != size_t(width) * height)
        throw InternalError("dilate3x3: size mismatch");
    std::vector<double> out(values.size());
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            double most = 0.0;
            for (uint32_t yy = y > 0 ? y - 1 : 0; yy <= std::min(y + 1, height - 1); ++yy)
                for (uint32_t xx = x > 0 ? x - 1 : 0; xx <= std::min(x + 1, width - 1); ++xx)
                    most = std::max(most, values[size_t(yy) * width + xx]);
            out[size_t(y) * width + x] = most;
        }
    return out;
}

std::vector<double> defensiveShape(const std::vector<double>& relVariance, uint32_t width,
                                   uint32_t height) {
    std::vector<double> shape = dilate3x3(relVariance, width, height);
    const double floor = kDefensiveShare * meanOf(shape);
    for (double& s : shape)
        s = std::max(s, floor);
    return shape;
}

std::vector<uint32_t> sampleLevels(uint32_t minSpp, uint32_t maxSpp, bool powersOfTwo) {
    if (minSpp == 0 || minSpp > maxSpp)
        throw InternalError("sampleLevels: need 1 <= minSpp <= maxSpp");
    std::vector<uint32_t> levels{minSpp};
    while (levels.back() < maxSpp) {
        const uint32_t next =
            powersOfTwo ? std::bit_floor(levels.back()) * 2
                        : std::max(levels.back() + 1,
                                   static_cast<uint32_t>(std::lround(levels.back() * 1.25)));
        levels.push_back(std::min(next, maxSpp));
    }
    return levels;
}

namespace {

struct Plan {
    std::vector<uint32_t> spp;
    double predicted = 0.0;
    double mean = 0.0;
};

// The counts for scale c: each pixel's c sqrt(shape) snapped to the nearest level in ratio.
Plan planFor(double c, const std::vector<double>& relVariance, const std::vector<double>& shape,
             const std::vector<uint32_t>& levels) {
    Plan plan;
    plan.spp.resize(shape.size());
    double predicted = 0.0, total = 0.0;
    for (size_t i = 0; i < shape.size(); ++i) {
        const double wanted = c * std::sqrt(shape[i]);
        auto above = std::lower_bound(levels.begin(), levels.end(), wanted,
                                      [](uint32_t level, double w) { return level < w; });
        uint32_t n;
        if (above == levels.begin())
            n = levels.front();
        else if (above == levels.end())
            n = levels.back();
        else
            n = wanted * wanted < double(*above) * double(*(above - 1)) ? *(above - 1) : *above;
        plan.spp[i] = n;
        predicted += relVariance[i] / n;
        total += n;
    }
    plan.predicted = predicted / shape.size();
    plan.mean = total / shape.size();
    return plan;
}

} // namespace

SampleAllocation allocateSamples(const std::vector<double>& relVariance,
                                 const std::vector<double>& shape,
                                 const AdaptiveSettings& settings) {
    if (relVariance.size() != shape.size() || shape.empty())
        throw InternalError("allocateSamples: size mismatch");
    const uint32_t pilot = settings.pilotSpp ? settings.pilotSpp : pilotSppFor(settings.maxSpp);
    SampleAllocation allocation;
    allocation.levels = sampleLevels(minSppFor(pilot), settings.maxSpp, settings.powerOfTwoLevels);
    // Both the predicted error (falling) and the mean count (rising) are monotone in c, so a
    // bisection on log c finds the scale; 1e-12 .. 1e12 spans every count from min to max.
    const bool budget = settings.targetError <= 0.0;
    auto good = [&](const Plan& plan) {
        return budget ? plan.mean <= settings.meanSpp : plan.predicted <= settings.targetError;
    };
    double lo = std::log(1e-12), hi = std::log(1e12);
    Plan best = planFor(std::exp(budget ? lo : hi), relVariance, shape, allocation.levels);
    allocation.targetMet = budget || good(best);
    if (good(best)) {
        for (int step = 0; step < 60; ++step) {
            const double mid = 0.5 * (lo + hi);
            Plan plan = planFor(std::exp(mid), relVariance, shape, allocation.levels);
            // Target: the smallest c that meets it; budget: the largest within it.
            const bool ok = good(plan);
            if (ok)
                best = std::move(plan);
            if (ok == budget)
                lo = mid;
            else
                hi = mid;
        }
    }
    allocation.spp = std::move(best.spp);
    allocation.predictedRelMse = best.predicted;
    allocation.meanSpp = best.mean;
    return allocation;
}

} // namespace wf
