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

ErrorEstimate estimateFilmError(const FilmMoments& film, SamplerKind sampler) {
    const size_t pixels = film.count.size();
    if (film.sum.size() != 3 * pixels || film.squares.size() != 3 * pixels ||
        film.largest.size() != pixels)
        throw InternalError("estimateError: film moments of mismatched sizes");
    ErrorEstimate e;
    e.upperBound = sampler != SamplerKind::Independent;
    e.pixelsTotal = static_cast<uint32_t>(pixels);
    double total = 0.0, variance = 0.0, single = 0.0;
    for (size_t i = 0; i < pixels; ++i) {
        const double n = film.count[i];
        if (!(n >= 2.0))
            continue;
        ++e.pixels;
        // The largest sample's share of the pixel's sum of squares, against the channel it
        // can have come from (largest is over channels too): at most 1, 1/n for equal samples.
        const double largest = film.largest[i];
        const double squaresMost = std::max({film.squares[3 * i], film.squares[3 * i + 1],
                                             film.squares[3 * i + 2]});
        const double share =
            squaresMost > 0.0 ? std::min(1.0, double(largest) * largest / squaresMost) : 0.0;
        // The relative variance of a variance estimate: at most the share (sum x^4 <= largest^2
        // sum x^2), and at least a normal's 2 / (n - 1).
        const double uncertainty = std::sqrt(std::max(2.0 / (n - 1.0), share));
        double error = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double sum = film.sum[3 * i + c], squares = film.squares[3 * i + c];
            const double mean = sum / n;
            const double ofMean = varianceOfMean(sum, squares, n);
            // mean^2 - ofMean estimates r^2 without bias, but where a pixel's error is of its
            // own size (a firefly in few samples) it nears zero and the ratio explodes: the
            // correction stops at halving mean^2.
            const double reference2 = std::max(mean * mean - ofMean, 0.5 * mean * mean);
            error += ofMean / (reference2 + kRelMseEpsilon) / 3.0;
        }
        const double spread = error * uncertainty;
        total += error;
        variance += spread * spread;
        if (share > kDominatedShare)
            single += error;
    }
    if (e.pixels > 0) {
        e.relMse = total / e.pixels;
        e.standardError = std::sqrt(variance) / e.pixels;
        e.singleSampleShare = single / e.pixels;
    }
    judgeErrorEstimate(e);
    return e;
}

} // namespace wf
