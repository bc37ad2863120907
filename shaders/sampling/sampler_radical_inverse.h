// `halton` and `hammersley`: radical inverses in prime bases, one prime per sample dimension
// (prime table in sampler_tables.h), randomized by a Cranley-Patterson rotation: every
// coordinate shifted modulo 1 by a random offset per (pixel, dimension, seed). The rotation
// makes each point uniform (unbiased) and decorrelates pixels, but unlike Owen scrambling it
// keeps the bases' structure: high dimensions use large primes whose first points crowd into
// a short interval. --no-randomize drops the rotation: every pixel gets the same points, and
// the structured artefacts show.
//   halton:     dimension d is the radical inverse of the sample index in prime(d).
//   hammersley: a finite set of N = set size points, dimension 0 is i / N, dimension d >= 1 the
//               radical inverse of i in prime(d - 1); samples past N repeat the set with fresh
//               rotations (sampler_common.h, setIndex).
// Dimensions past the prime table fall back to independent random numbers.
#ifndef WF_SAMPLER_RADICAL_INVERSE_H
#define WF_SAMPLER_RADICAL_INVERSE_H

#include "sampling/sampler_common.h"
#include "sampling/sampler_tables.h"

#ifdef __cplusplus
namespace wf::gpu_types {
#endif

// Digits of `index` in `base`, mirrored about the radix point, as a 32-bit fraction (24 bits
// significant). Base 2 is exact: a bit reversal.
WF_INLINE uint radicalInverseFixed(uint base, uint index) {
    if (base == 2u)
        return reverseBits32(index);
    float inverseBase = 1.0f / float(base);
    float scale = inverseBase;
    float result = 0.0f;
    while (index != 0u) {
        uint next = index / base;
        result += float(index - next * base) * scale;
        scale *= inverseBase;
        index = next;
    }
    return unitFloatToFixed(min(result, WF_ONE_MINUS_EPSILON));
}

WF_INLINE uint samplerPrime(uint n) { return samplerTable(WF_SAMPLER_TABLE_PRIMES + n); }

// A coordinate as a 32-bit fraction, rotated (mod 1, exactly, by integer wrap-around).
WF_INLINE float rotatedCoordinate(uint fixedPoint, uint rotation, bool randomize) {
    return uintToUnitFloat(randomize ? fixedPoint + rotation : fixedPoint);
}

WF_INLINE float haltonSample1D(uint pixel, uint sampleIndex, uint dimension, uint seed,
                               bool randomize) {
    if (dimension >= WF_SAMPLER_PRIME_COUNT)
        return uintToUnitFloat(pcg4d(uvec4(pixel, sampleIndex, dimension, seed)).x);
    uvec4 key = samplerKeys(pixel, dimension, seed);
    return rotatedCoordinate(radicalInverseFixed(samplerPrime(dimension), sampleIndex), key.x,
                             randomize);
}

WF_INLINE vec2 haltonSample2D(uint pixel, uint sampleIndex, uint dimension, uint seed,
                              bool randomize) {
    if (dimension + 1u >= WF_SAMPLER_PRIME_COUNT) {
        uvec4 h = pcg4d(uvec4(pixel, sampleIndex, dimension, seed));
        return vec2(uintToUnitFloat(h.x), uintToUnitFloat(h.y));
    }
    uvec4 key = samplerKeys(pixel, dimension, seed);
    return vec2(rotatedCoordinate(radicalInverseFixed(samplerPrime(dimension), sampleIndex),
                                  key.x, randomize),
                rotatedCoordinate(radicalInverseFixed(samplerPrime(dimension + 1u), sampleIndex),
                                  key.y, randomize));
}

// Coordinate `dimension` of point `index` of the Hammersley set of `setSize` points.
WF_INLINE uint hammersleyFixed(uint index, uint dimension, uint setSize) {
    if (dimension == 0u)
        return unitFloatToFixed(min(float(index) / float(max(setSize, 1u)), WF_ONE_MINUS_EPSILON));
    return radicalInverseFixed(samplerPrime(dimension - 1u), index);
}

WF_INLINE float hammersleySample1D(uint pixel, uint sampleIndex, uint dimension, uint seed,
                                   uint setSize, bool randomize) {
    if (dimension > WF_SAMPLER_PRIME_COUNT)
        return uintToUnitFloat(pcg4d(uvec4(pixel, sampleIndex, dimension, seed)).x);
    uvec2 at = setIndex(sampleIndex, setSize);
    uvec4 key = samplerKeys(pixel, dimension, seed + at.y * 0x9e3779b9u);
    return rotatedCoordinate(hammersleyFixed(at.x, dimension, setSize), key.x, randomize);
}

WF_INLINE vec2 hammersleySample2D(uint pixel, uint sampleIndex, uint dimension, uint seed,
                                  uint setSize, bool randomize) {
    if (dimension + 1u > WF_SAMPLER_PRIME_COUNT) {
        uvec4 h = pcg4d(uvec4(pixel, sampleIndex, dimension, seed));
        return vec2(uintToUnitFloat(h.x), uintToUnitFloat(h.y));
    }
    uvec2 at = setIndex(sampleIndex, setSize);
    uvec4 key = samplerKeys(pixel, dimension, seed + at.y * 0x9e3779b9u);
    return vec2(rotatedCoordinate(hammersleyFixed(at.x, dimension, setSize), key.x, randomize),
                rotatedCoordinate(hammersleyFixed(at.x, dimension + 1u, setSize), key.y,
                                  randomize));
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
