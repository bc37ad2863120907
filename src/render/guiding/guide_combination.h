// Combining the images of a guided render's iterations: every iteration's image is an unbiased
// estimate on its own (each samples from a guide frozen for its duration), so a weighted mean
// of them is too, as long as the weights sum to one and do not depend on the images. They are
// the iterations' sample counts: the image is the mean of every sample the render traced.
// The course's ("Path Guiding in Production", Mueller's chapter) inverse-variance weights,
// estimated from the images themselves (one number per image), were biased: an iteration that
// caught a rare bright path reads as noisy and weighs less, so rare paths are under-counted
// (on the glass caustic, 64x64, 1024 spp, 24 seeds: its dark pixels 15% too dark, lower than
// plain averaging of the very same samples in 23 of 24 seeds; docs/guiding.md).
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
    std::vector<double> weights; // per iteration added, summing to 1: its share of the samples
    uint32_t samplesPerPixel = 0; // of all iterations
};

class ImageCombiner {
public:
    explicit ImageCombiner(uint32_t pixels) : pixels_(pixels) {}
    // One iteration's film (sums, counts, squares), `spp` samples per pixel.
    void add(const FilmMoments& moments, uint32_t spp);
    std::size_t iterations() const { return images_.size(); }
    // The combination of what was added (empty film when nothing was).
    CombinedImage combine() const;

private:
    struct Iteration {
        uint32_t spp;
        std::vector<float> mean;     // rgb per pixel
        std::vector<float> variance; // of the mean, rgb per pixel
        std::vector<float> largest;
    };
    uint32_t pixels_;
    std::vector<Iteration> images_;
};

} // namespace wf::guiding
