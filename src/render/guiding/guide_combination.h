// Combining the images of a guided render's iterations (the "Path Guiding in Production"
// course, Mueller's chapter): every iteration's image is an unbiased estimate on its own (each
// samples from a guide frozen for its duration), so a weighted mean of them with weights that
// sum to one is too. Inverse-variance weights minimise the combination's variance; each
// iteration's variance is one number for the whole image, the mean over pixels and channels of
// its pixels' variance of the mean relative to (m^2 + 0.01), m the spp-weighted mean of all
// iterations (the denominator of converge's relMSE, shared by every iteration so that the
// weights compare like with like). One number per image keeps the weights nearly independent
// of any one pixel's samples: a weight estimated per pixel from its own samples would bias it.
// Iterations of one sample per pixel have no variance estimate and are left out.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/film_readback.h"

namespace wf::guiding {

struct CombinedImage {
    std::vector<float> film;    // per pixel rgb sum and count (count = samples combined)
    std::vector<float> moments; // per pixel rgb "sum of squares" and largest sample, chosen
                                // so that the film's variance of the mean is the combination's
    std::vector<double> weights; // per iteration added, summing to 1 (0: left out)
    uint32_t samplesPerPixel = 0; // of the iterations with a weight
};

class ImageCombiner {
public:
    explicit ImageCombiner(uint32_t pixels) : pixels_(pixels) {}
    // One iteration's film (sums, counts, squares), `spp` samples per pixel.
    void add(const FilmMoments& moments, uint32_t spp);
    std::size_t iterations() const { return images_.size(); }
    // The inverse-variance combination of what was added; empty film when nothing had a
    // variance estimate.
    CombinedImage combine() const;
    // The relative variance of each iteration's image (0 where it has none), as combine()
    // weighs them: for --verbose, the JSON and the tests.
    std::vector<double> relativeVariances() const;

private:
    struct Iteration {
        uint32_t spp;
        std::vector<float> mean;     // rgb per pixel
        std::vector<float> variance; // of the mean, rgb per pixel
        std::vector<float> largest;
    };
    std::vector<double> denominators() const; // (m^2 + 0.01) per pixel and channel

    uint32_t pixels_;
    std::vector<Iteration> images_;
};

} // namespace wf::guiding
