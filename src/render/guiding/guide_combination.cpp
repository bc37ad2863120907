#include "render/guiding/guide_combination.h"

#include <algorithm>

#include "errors.h"

namespace wf::guiding {

void ImageCombiner::add(const FilmMoments& moments, uint32_t spp) {
    if (moments.count.size() != pixels_)
        throw InternalError("guide combination: film of another size");
    Iteration it;
    it.spp = spp;
    it.mean.resize(size_t(pixels_) * 3);
    it.variance.resize(size_t(pixels_) * 3);
    it.largest = moments.largest;
    for (size_t p = 0; p < pixels_; ++p) {
        const double n = moments.count[p];
        for (int c = 0; c < 3; ++c) {
            const size_t i = 3 * p + size_t(c);
            it.mean[i] = n > 0.0 ? float(moments.sum[i] / n) : 0.0f;
            it.variance[i] = float(varianceOfMean(moments.sum[i], moments.squares[i], n));
        }
    }
    images_.push_back(std::move(it));
}

CombinedImage ImageCombiner::combine() const {
    CombinedImage out;
    double weightSum = 0.0;
    for (const Iteration& it : images_) {
        out.weights.push_back(it.spp);
        weightSum += it.spp;
    }
    if (!(weightSum > 0.0))
        return out;
    for (double& w : out.weights)
        w /= weightSum;
    for (size_t k = 0; k < images_.size(); ++k)
        if (out.weights[k] > 0.0)
            out.samplesPerPixel += images_[k].spp;
    const double n = out.samplesPerPixel;
    out.film.assign(size_t(pixels_) * 4, 0.0f);
    out.moments.assign(size_t(pixels_) * 4, 0.0f);
    for (size_t p = 0; p < pixels_; ++p) {
        for (int c = 0; c < 3; ++c) {
            const size_t i = 3 * p + size_t(c);
            double mean = 0.0, variance = 0.0;
            for (size_t k = 0; k < images_.size(); ++k) {
                const double w = out.weights[k];
                mean += w * images_[k].mean[i];
                variance += w * w * images_[k].variance[i];
            }
            const double sum = mean * n;
            out.film[4 * p + size_t(c)] = float(sum);
            // varianceOfMean(sum, squares, n) == variance, for the render's error estimate.
            out.moments[4 * p + size_t(c)] = float(variance * n * (n - 1.0) + sum * sum / n);
        }
        out.film[4 * p + 3] = float(n);
        float largest = 0.0f;
        for (size_t k = 0; k < images_.size(); ++k)
            if (out.weights[k] > 0.0 && p < images_[k].largest.size())
                largest = std::max(largest, images_[k].largest[p]);
        out.moments[4 * p + 3] = largest;
    }
    return out;
}

} // namespace wf::guiding
