#include "image/error_metrics.h"

#include <cmath>
#include <string>

#include "errors.h"

namespace wf {

ImageError imageError(const std::vector<float>& image, const std::vector<float>& reference) {
    if (image.size() != reference.size() || image.empty())
        throw InternalError("image error: sizes differ (" + std::to_string(image.size()) +
                            " and " + std::to_string(reference.size()) + " values) or are zero");
    ImageError error;
    for (size_t i = 0; i < image.size(); ++i) {
        const double r = reference[i];
        double d = double(image[i]) - r;
        if (!std::isfinite(d))
            d = 1e30;
        error.relMse += d * d / (r * r + kRelMseEpsilon);
        error.mse += d * d;
        error.bias += d;
    }
    const double n = double(image.size());
    error.relMse /= n;
    error.mse /= n;
    error.bias /= n;
    return error;
}

double referenceNoiseRelMse(const std::vector<float>& a, double samplesA,
                            const std::vector<float>& b, double samplesB,
                            const std::vector<float>& reference) {
    if (a.size() != reference.size() || b.size() != reference.size() || reference.empty() ||
        !(samplesA > 0.0) || !(samplesB > 0.0))
        throw InternalError("reference noise: two halves of the reference's size and samples "
                            "needed");
    // E[(a - b)^2] = s^2 (1 / nA + 1 / nB) for per-sample variance s^2; the mean's is
    // s^2 / (nA + nB).
    const double scale = samplesA * samplesB / ((samplesA + samplesB) * (samplesA + samplesB));
    double sum = 0.0;
    for (size_t i = 0; i < reference.size(); ++i) {
        const double r = reference[i];
        const double d = double(a[i]) - double(b[i]);
        if (std::isfinite(d))
            sum += d * d * scale / (r * r + kRelMseEpsilon);
    }
    return sum / double(reference.size());
}

std::vector<float> mergeBySampleCount(const std::vector<std::vector<float>>& images,
                                      const std::vector<double>& samplesPerPixel) {
    if (images.empty() || images.size() != samplesPerPixel.size())
        throw InternalError("merge: one sample count per image needed");
    double total = 0.0;
    for (double spp : samplesPerPixel)
        total += spp;
    std::vector<double> sum(images.front().size(), 0.0);
    for (size_t k = 0; k < images.size(); ++k) {
        if (images[k].size() != sum.size())
            throw InternalError("merge: images of different sizes");
        for (size_t i = 0; i < sum.size(); ++i)
            sum[i] += samplesPerPixel[k] * double(images[k][i]);
    }
    std::vector<float> merged(sum.size());
    for (size_t i = 0; i < sum.size(); ++i)
        merged[i] = float(sum[i] / total);
    return merged;
}

} // namespace wf
