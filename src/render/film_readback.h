// Reading the film back to the host: the image (mean radiance per pixel), the film's second
// moments and the AOVs, from the path buffers' film, moment film and AOV film.
#pragma once
#include <cstdint>
#include <vector>

namespace wf {

struct PathBuffers;

// The film and its second moment, per pixel: rgb sums, sample counts and rgb sums of squares.
struct FilmMoments {
    std::vector<float> sum;     // rgb per pixel
    std::vector<float> count;   // samples per pixel
    std::vector<float> squares; // rgb per pixel
    std::vector<float> largest; // per pixel, the largest component of any one sample
    // With --error-replicates K > 1: per pixel, K - 1 entries of rgb sum and sample count of
    // replicates 1 .. K - 1 (replicate 0: the film's less these). Empty with one sequence.
    uint32_t replicates = 1;
    std::vector<float> replicateSums;
};

// Per pixel, the mean over its samples of the camera ray's first hit (zero where it found no
// surface), and the variance of the pixel's radiance estimate (of its mean, per channel).
struct AovImages {
    std::vector<float> albedo;   // rgb per pixel
    std::vector<float> normal;   // xyz per pixel, the mean of unit normals (not renormalised)
    std::vector<float> depth;    // one per pixel: distance along the camera ray
    std::vector<float> variance; // rgb per pixel
};

// The variance of the mean of n samples with these sums (0 below two samples).
double varianceOfMean(double sum, double sumOfSquares, double n);

// Linear radiance per pixel (mean of the samples), RGB, top row first.
std::vector<float> readFilmImage(const PathBuffers& buffers, uint32_t pixelCount);
// Needs the moment film (RenderSettings.aov or pixelList).
FilmMoments readFilmMoments(const PathBuffers& buffers, uint32_t pixelCount);
// Needs the AOV film (RenderSettings.aov).
AovImages readFilmAovs(const PathBuffers& buffers, uint32_t pixelCount);

} // namespace wf
