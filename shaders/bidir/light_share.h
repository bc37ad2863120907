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
#include "sampling/sampler_common.h"

#ifdef __cplusplus
namespace wf::gpu_types {
#endif

// The light subpath (its pixel-index slot, below lightPaths) that `pixel` connects to. Pixels
// are dealt out by a fixed permutation of the image (the samplers' permuteIndex), then modulo
// the subpath count: every subpath serves the same number of pixels give or take one,
// scattered over the image rather than on a lattice of correlated pixels, and a pixel keeps
// its subpath index across its samples, which the sampler stratifies.
WF_INLINE uint lightSubpathOfPixel(uint pixel, uint pixelCount, uint lightPaths) {
    if (lightPaths >= pixelCount) {
        return pixel;
    }
    return permuteIndex(pixel, pixelCount, 0x68bc21ebu) % lightPaths;
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
