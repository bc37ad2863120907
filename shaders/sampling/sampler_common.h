// Building blocks of the samplers behind sample1D/sample2D (rng.h): the sampler ids, integer
// hashes, base-2 Owen scrambling, hash-based permutations of [0, n) and conversions to [0, 1).
// Compiles as GLSL and as C++ (glsl_cpp.h), so the CPU tests check what the GPU runs.
#ifndef WF_SAMPLER_COMMON_H
#define WF_SAMPLER_COMMON_H

#include "types/glsl_cpp.h"

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm; // bitfieldReverse, bitCount, min, max as in GLSL
#endif

// Values of WF_SAMPLER (the shader variant) and of wf::SamplerKind.
#define WF_SAMPLER_INDEPENDENT 0
#define WF_SAMPLER_STRATIFIED 1
#define WF_SAMPLER_MULTIJITTER 2
#define WF_SAMPLER_HALTON 3
#define WF_SAMPLER_HAMMERSLEY 4
#define WF_SAMPLER_SOBOL 5
#define WF_SAMPLER_BLUENOISE 6

// Largest float below 1: samples live in [0, 1).
#define WF_ONE_MINUS_EPSILON 0.99999994f
// Salt that keeps per-(pixel, dimension) keys apart from the per-sample hashes.
#define WF_KEY_SALT 0x5bd1e995u

// PCG-style 4D hash (Jarzynski & Olano, "Hash Functions for GPU Rendering", 2020): good
// avalanche in all four inputs at a few integer multiplies.
WF_INLINE uvec4 pcg4d(uvec4 v) {
    v = v * 1664525u + uvec4(1013904223u);
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    v = v ^ (v >> uvec4(16u));
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    return v;
}

// Top 24 bits to [0, 1): exactly representable, never 1.
WF_INLINE float uintToUnitFloat(uint bits) { return float(bits >> 8u) * (1.0f / 16777216.0f); }

// [0, 1) to a 32-bit fraction, exactly for the 24 bits a float in [0, 1) can carry below 1.
WF_INLINE uint unitFloatToFixed(float value) { return uint(value * 16777216.0f) << 8u; }

// Four independent 32-bit keys per (pixel, dimension, seed): index shuffles, scrambles and
// rotations that stay fixed across the samples of one pixel.
WF_INLINE uvec4 samplerKeys(uint pixel, uint dimension, uint seed) {
    return pcg4d(uvec4(pixel, dimension, seed, WF_KEY_SALT));
}

WF_INLINE uint reverseBits32(uint x) { return bitfieldReverse(x); }

// Base-2 Owen scrambling of a bit-reversed value (Laine & Karras 2011, with the stronger
// constants of Vegdahl, "Building a Better LK Hash", 2021). Every step only carries from lower
// to higher bits, so output bit k depends on input bits 0..k and the seed: once the bits are
// reversed back, each digit is flipped by a random function of the digits above it, which is
// exactly a nested uniform (Owen) scramble.
WF_INLINE uint owenScrambleReversed(uint x, uint seed) {
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16u) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

// Owen scramble of a 32-bit fraction (most significant digit first). Used on sample indices
// too (Burley 2020, "Practical Hash-based Owen Scrambling"): the first 2^k indices then map
// onto one aligned block of 2^k, so every power-of-two prefix of a (0, 2)-sequence stays a net.
WF_INLINE uint owenScramble(uint x, uint seed) {
    return reverseBits32(owenScrambleReversed(reverseBits32(x), seed));
}

// A random permutation of [0, n) chosen by `key` (the cycle-walking construction of Kensler,
// "Correlated Multi-Jittered Sampling", 2013, with our own mixing steps): a bijection of the
// enclosing power of two built from steps invertible on the masked bits, repeated until the
// value lands below n, then a rotation by the key. The rotation makes every element equally
// likely at every position over keys, whatever the mixing quality, which keeps a partial
// stratified set (n > samples) unbiased.
WF_INLINE uint permuteIndex(uint i, uint n, uint key) {
    uint mask = n - 1u;
    mask |= mask >> 1u;
    mask |= mask >> 2u;
    mask |= mask >> 4u;
    mask |= mask >> 8u;
    mask |= mask >> 16u;
    uint shift = max(uint(bitCount(mask)) / 2u, 1u);
    do {
        i = (i ^ key) & mask;
        i = (i * 0x2c1b3c6du) & mask; // odd multipliers: invertible modulo a power of two
        i ^= i >> shift;              // xor-shifts carry the high bits back down
        i = (i + (key >> 8u)) & mask;
        i = (i * 0x297a2d39u) & mask;
        i ^= i >> shift;
        i = (i * ((key >> 16u) | 1u)) & mask;
        i ^= i >> 1u;
    } while (i >= n);
    return (i + key % n) % n;
}

// Splits a sample index of a finite set of `setSize` samples into the index inside the set and
// the repetition: samples past the set start a fresh, independently randomized copy of it.
WF_INLINE uvec2 setIndex(uint sampleIndex, uint setSize) {
    uint size = max(setSize, 1u);
    return uvec2(sampleIndex % size, sampleIndex / size);
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
