#include "render/film_error.h"

#include <algorithm>
#include <cmath>

#include "errors.h"
#include "image/error_metrics.h"

namespace wf {
namespace {

// Where one sample holds more than this share of a pixel's sum of squares, the pixel's
// variance rests on that one sample.
constexpr double kDominatedShare = 0.5;

} // namespace

bool replicateVarianceOfMean(const FilmMoments& film, size_t pixel, std::array<double, 3>& out) {
    const uint32_t k = film.replicates;
    const double n = film.count[pixel];
    std::array<double, 3> first{film.sum[3 * pixel], film.sum[3 * pixel + 1],
                                film.sum[3 * pixel + 2]};
    double firstCount = n;
    const float* others = film.replicateSums.data() + size_t(pixel) * (k - 1) * 4;
    for (uint32_t r = 0; r + 1 < k; ++r) {
        for (int c = 0; c < 3; ++c)
            first[c] -= others[4 * r + c];
        firstCount -= others[4 * r + 3];
    }
    if (!(firstCount >= 1.0))
        return false;
    out = {0.0, 0.0, 0.0};
    for (uint32_t r = 0; r < k; ++r) {
        const double count = r == 0 ? firstCount : others[4 * (r - 1) + 3];
        if (!(count >= 1.0))
            return false;
        const double weight = count / n;
        for (int c = 0; c < 3; ++c) {
            const double sum = r == 0 ? first[c] : others[4 * (r - 1) + c];
            const double apart = sum / count - film.sum[3 * pixel + c] / n;
            out[c] += weight * weight * apart * apart;
        }
    }
    for (double& v : out)
        v *= double(k) / double(k - 1);
    return true;
}

namespace {

// `replicates` > 1 reads the film's replicate sums; 1 takes the samples' variance alone.
ErrorEstimate estimate(const FilmMoments& film, SamplerKind sampler, uint32_t replicates) {
    const size_t pixels = film.count.size();
    if (film.sum.size() != 3 * pixels || film.squares.size() != 3 * pixels ||
        film.largest.size() != pixels ||
        film.replicateSums.size() != (std::max(film.replicates, 1u) - 1) * 4 * pixels)
        throw InternalError("estimateError: film moments of mismatched sizes");
    ErrorEstimate e;
    e.replicates = replicates;
    e.upperBound = sampler != SamplerKind::Independent && replicates == 1;
    e.pixelsTotal = static_cast<uint32_t>(pixels);
    // The relative variance of a replicate variance from K - 1 degrees of freedom, from the
    // estimate itself: a chi-square's 2 / (K - 1) V^2, over E[v^2] = (K + 1) / (K - 1) V^2.
    const double replicateSpread = 2.0 / (replicates + 1.0);
    double total = 0.0, variance = 0.0, single = 0.0, errorSquares = 0.0;
    for (size_t i = 0; i < pixels; ++i) {
        const double n = film.count[i];
        if (!(n >= 2.0))
            continue;
        std::array<double, 3> ofMeans{};
        if (replicates > 1 && !replicateVarianceOfMean(film, i, ofMeans))
            continue; // fewer samples than replicates
        ++e.pixels;
        // The largest sample's share of the pixel's sum of squares, against the channel it
        // can have come from (largest is over channels too): at most 1, 1/n for equal samples.
        const double largest = film.largest[i];
        const double squaresMost = std::max({film.squares[3 * i], film.squares[3 * i + 1],
                                             film.squares[3 * i + 2]});
        const double share =
            squaresMost > 0.0 ? std::min(1.0, double(largest) * largest / squaresMost) : 0.0;
        // The relative variance of a variance estimate: at most the share (sum x^4 <= largest^2
        // sum x^2), and at least a normal's 2 / (n - 1), or the replicates' spread.
        const double uncertainty = std::sqrt(
            std::max(replicates > 1 ? replicateSpread : 2.0 / (n - 1.0), share));
        double error = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double sum = film.sum[3 * i + c], squares = film.squares[3 * i + c];
            const double mean = sum / n;
            // The samples' own variance (many degrees of freedom) corrects r^2: mean^2 - ofMean
            // estimates it without bias for independent samples, but where a pixel's error is
            // of its own size (a firefly in few samples) it nears zero and the ratio explodes:
            // the correction stops at halving mean^2.
            const double independent = varianceOfMean(sum, squares, n);
            const double reference2 = std::max(mean * mean - independent, 0.5 * mean * mean);
            const double ofMean = replicates > 1 ? ofMeans[c] : independent;
            error += ofMean / (reference2 + kRelMseEpsilon) / 3.0;
        }
        const double spread = error * uncertainty;
        total += error;
        errorSquares += error * error;
        variance += spread * spread;
        if (share > kDominatedShare)
            single += error;
    }
    if (e.pixels > 0) {
        e.relMse = total / e.pixels;
        e.standardError = std::sqrt(variance) / e.pixels;
        e.singleSampleShare = single / e.pixels;
        e.effectivePixels = errorSquares > 0.0 ? total * total / errorSquares : 0.0;
    }
    judgeErrorEstimate(e);
    return e;
}

} // namespace

ErrorEstimate estimateFilmError(const FilmMoments& film, SamplerKind sampler) {
    return estimate(film, sampler, std::max(film.replicates, 1u));
}

ErrorEstimate estimateIndependentFilmError(const FilmMoments& film) {
    return estimate(film, SamplerKind::Independent, 1);
}

} // namespace wf
