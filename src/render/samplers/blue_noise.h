// A blue-noise rank mask made by void-and-cluster (Ulichney, "The void-and-cluster method for
// dither array generation", 1993): every threshold of the mask (the pixels of rank below k) is a
// pattern without low frequencies. The `bluenoise` sampler reads it (sampler_blue_noise.h).
#pragma once
#include <cstdint>
#include <vector>

namespace wf {

// Ranks 0 .. size^2 - 1, one per pixel of a size x size tile, row-major; tiles seamlessly (the
// filter wraps around). Gaussian filter of standard deviation `sigma` pixels (1.5 is
// Ulichney's choice). Deterministic: energies are integers, ties go to the lowest index, and
// the initial pattern comes from a fixed hash of `seed`.
std::vector<uint32_t> voidAndClusterMask(uint32_t size, double sigma, uint32_t seed);

} // namespace wf
