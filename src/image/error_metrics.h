// Error of an image against a reference, as `wavefront converge` and the tests measure it.
// All metrics average over pixels and the three channels of linear RGB radiance.
#pragma once
#include <vector>

namespace wf {

// relMSE's epsilon: keeps near-black reference pixels from dominating (a common choice; the
// failure-scene tests use the same).
constexpr double kRelMseEpsilon = 1e-2;

struct ImageError {
    double relMse = 0.0; // mean of (x - r)^2 / (r^2 + epsilon)
    double mse = 0.0;    // mean of (x - r)^2
    double bias = 0.0;   // mean of x - r: the image's mean minus the reference's (signed)
};

// Non-finite pixels count as errors of 1e30 so that they cannot hide. Throws InternalError if
// the sizes differ or are zero.
ImageError imageError(const std::vector<float>& image, const std::vector<float>& reference);

// What a reference's own noise adds to the relMSE of any image independent of it, estimated
// without bias from two independent renders a and b of nA and nB samples per pixel whose
// sample-weighted mean is the reference: per value (a - b)^2 nA nB / (nA + nB)^2 (the variance
// of that mean), over reference^2 + epsilon as relMse weighs it. An image's relMSE against the
// truth is its relMSE against the reference less this. Throws InternalError on mismatched sizes.
double referenceNoiseRelMse(const std::vector<float>& a, double samplesA,
                            const std::vector<float>& b, double samplesB,
                            const std::vector<float>& reference);

// The sample-weighted mean of partial renders (--spp-offset parts): sum of spp_i * image_i over
// the sum of spp_i. How partial renders merge into the image of one run of all their samples.
std::vector<float> mergeBySampleCount(const std::vector<std::vector<float>>& images,
                                      const std::vector<double>& samplesPerPixel);

} // namespace wf
