#include "render/film_readback.h"

#include <algorithm>

#include "errors.h"
#include "render/path_buffers.h"

namespace wf {

double varianceOfMean(double sum, double sumOfSquares, double n) {
    // (sum x^2 - (sum x)^2 / n) / (n (n - 1)): the sample variance over n.
    return n > 1.0 ? std::max(0.0, sumOfSquares - sum * sum / n) / (n * (n - 1.0)) : 0.0;
}

std::vector<float> readFilmImage(const PathBuffers& buffers, uint32_t pixelCount) {
    std::vector<float> film = buffers.film.download<float>();
    std::vector<float> rgb(size_t(pixelCount) * 3);
    for (size_t i = 0; i < pixelCount; ++i) {
        float count = film[4 * i + 3];
        for (int c = 0; c < 3; ++c)
            rgb[3 * i + c] = count > 0.0f ? film[4 * i + c] / count : 0.0f;
    }
    return rgb;
}

FilmMoments readFilmMoments(const PathBuffers& buffers, uint32_t pixelCount) {
    if (!buffers.momentFilm)
        throw InternalError("readMoments: the renderer keeps no second moment");
    const std::vector<float> film = buffers.film.download<float>();
    const std::vector<float> squares = buffers.momentFilm.download<float>();
    FilmMoments moments;
    moments.sum.resize(size_t(pixelCount) * 3);
    moments.count.resize(pixelCount);
    moments.squares.resize(size_t(pixelCount) * 3);
    moments.largest.resize(pixelCount);
    for (size_t i = 0; i < pixelCount; ++i) {
        for (int c = 0; c < 3; ++c) {
            moments.sum[3 * i + c] = film[4 * i + c];
            moments.squares[3 * i + c] = squares[4 * i + c];
        }
        moments.count[i] = film[4 * i + 3];
        moments.largest[i] = squares[4 * i + 3];
    }
    if (buffers.replicateFilm) {
        moments.replicates = buffers.replicates;
        moments.replicateSums = buffers.replicateFilm.download<float>();
    }
    return moments;
}

AovImages readFilmAovs(const PathBuffers& buffers, uint32_t pixelCount) {
    if (!buffers.aovFilm)
        throw InternalError("readAovs: the renderer was made without RenderSettings.aov");
    const FilmMoments moments = readFilmMoments(buffers, pixelCount);
    const std::vector<float> aov = buffers.aovFilm.download<float>();
    AovImages images;
    images.albedo.resize(size_t(pixelCount) * 3);
    images.normal.resize(size_t(pixelCount) * 3);
    images.depth.resize(pixelCount);
    images.variance.resize(size_t(pixelCount) * 3);
    for (size_t i = 0; i < pixelCount; ++i) {
        const double n = moments.count[i];
        if (!(n > 0.0))
            continue;
        const float* sums = &aov[8 * i];
        for (int c = 0; c < 3; ++c) {
            images.albedo[3 * i + c] = float(sums[c] / n);
            images.normal[3 * i + c] = float(sums[4 + c] / n);
            images.variance[3 * i + c] = float(
                varianceOfMean(moments.sum[3 * i + c], moments.squares[3 * i + c], n));
        }
        images.depth[i] = float(sums[3] / n);
    }
    return images;
}

} // namespace wf
