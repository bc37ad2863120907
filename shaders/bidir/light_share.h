// Light subpaths shared by pixels (--light-share, issue 46): each sample index traces
// lightPaths light subpaths, one per --light-share pixels, in the path slots of that sample
// whose pixel index is below lightPaths; every pixel's camera subpath of the sample connects to
// one of them. Unbiased for any assignment (each camera subpath meets a light subpath of the
// right distribution); fewer light subpaths cost less and give the light tracer's splats
// (t = 1), which no pixel's sampler stratifies, less weight in the MIS. Shared with the CPU
// tests (tests/unit/test_light_share.cpp).
#ifndef WF_LIGHT_SHARE_H
#define WF_LIGHT_SHARE_H

#include "types/glsl_cpp.h"

#ifdef __cplusplus
namespace wf::gpu_types {
#endif

// The light subpath (its pixel-index slot, below lightPaths) that `pixel` connects to. Pixels
// are dealt out by a fixed permutation of the image (odd multiplies and xorshifts on the
// next power of two, cycle-walked back into the image), then modulo the subpath count: every
// subpath serves the same number of pixels give or take one, scattered over the image rather
// than on a lattice of correlated pixels, and a pixel keeps its subpath index across its
// samples, which the sampler stratifies.
WF_INLINE uint lightSubpathOfPixel(uint pixel, uint pixelCount, uint lightPaths) {
    if (lightPaths >= pixelCount) {
        return pixel;
    }
    uint mask = pixelCount - 1u;
    mask |= mask >> 1u;
    mask |= mask >> 2u;
    mask |= mask >> 4u;
    mask |= mask >> 8u;
    mask |= mask >> 16u;
    uint x = pixel;
    do {
        x = (x * 0x2c1b3c6du + 0x297a2d39u) & mask;
        x ^= x >> 7u;
        x = (x * 0x9e3779b1u) & mask;
        x ^= x >> 13u;
    } while (x >= pixelCount);
    return x % lightPaths;
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
