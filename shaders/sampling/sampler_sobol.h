// `sobol`: Owen-scrambled Sobol points, padded (Burley 2020, "Practical Hash-based Owen
// Scrambling"; pbrt-v4's PaddedSobolSampler). Every sample1D/sample2D call is its own 1D or 2D
// pattern: the first one or two Sobol dimensions, which form a (0, 2)-sequence in base 2, with
//   - the sample index shuffled per (pixel, dimension, seed) by a nested uniform scramble, so
//     each call site sees its own ordering of the points (no correlation between the pixel
//     jitter and the BSDF direction, between one bounce and the next) while every power-of-two
//     prefix of a pixel's samples is still a (0, m, 2)-net, and
//   - each coordinate Owen scrambled with its own key: a uniformly distributed point set, so
//     the estimate is unbiased, and errors across pixels are independent.
// Without randomization (--no-randomize) the keys depend on the dimension only: every pixel and
// every seed sees the same points.
#ifndef WF_SAMPLER_SOBOL_H
#define WF_SAMPLER_SOBOL_H

#include "sampling/sampler_common.h"

#ifdef __cplusplus
namespace wf::gpu_types {
#endif

// Sobol dimension 0 as a 32-bit fraction: the van der Corput sequence, a bit reversal.
WF_INLINE uint sobolDimension0(uint index) { return reverseBits32(index); }

// Sobol dimension 1 (primitive polynomial x + 1, all direction numbers 1). Its generator
// matrix is Pascal's triangle mod 2: read the index's bits as a polynomial i(t) over GF(2), the
// result is i(t + 1), bit-reversed. Since (t + 1)^(2^s) = t^(2^s) + 1 over GF(2), the
// substitution splits into halves recursively, five xor-shift steps instead of a loop over 32
// columns (tests/unit/test_samplers.cpp checks it against the column loop).
WF_INLINE uint sobolDimension1(uint index) {
    index ^= (index >> 1u) & 0x55555555u;
    index ^= (index >> 2u) & 0x33333333u;
    index ^= (index >> 4u) & 0x0f0f0f0fu;
    index ^= (index >> 8u) & 0x00ff00ffu;
    index ^= (index >> 16u) & 0x0000ffffu;
    return reverseBits32(index);
}

WF_INLINE uvec4 sobolKeys(uint pixel, uint dimension, uint seed, bool randomize) {
    return randomize ? samplerKeys(pixel, dimension, seed) : samplerKeys(0u, dimension, 0u);
}

WF_INLINE float sobolSample1D(uint pixel, uint sampleIndex, uint dimension, uint seed,
                              bool randomize) {
    uvec4 key = sobolKeys(pixel, dimension, seed, randomize);
    uint index = owenScramble(sampleIndex, key.x);
    return uintToUnitFloat(owenScramble(sobolDimension0(index), key.y));
}

WF_INLINE vec2 sobolSample2D(uint pixel, uint sampleIndex, uint dimension, uint seed,
                             bool randomize) {
    uvec4 key = sobolKeys(pixel, dimension, seed, randomize);
    uint index = owenScramble(sampleIndex, key.x);
    return vec2(uintToUnitFloat(owenScramble(sobolDimension0(index), key.y)),
                uintToUnitFloat(owenScramble(sobolDimension1(index), key.z)));
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
