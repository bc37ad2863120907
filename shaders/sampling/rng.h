// Sample values: a sample is a pure function of (pixel, sample index, dimension, seed), so an
// image does not depend on which path lands in which queue slot, waves can be split any way, a
// render is reproducible bit for bit, and sample index ranges (--spp-offset) merge.
//
// sample1D/sample2D are the only entry points; they dispatch to the sampler of WF_SAMPLER:
// independent, stratified, multijitter, halton, hammersley, sobol, bluenoise (sampler_*.h).
// A sample2D call takes dimensions d and d + 1 as one 2D pattern (the pixel position, a light
// point, a BSDF direction), a sample1D call dimension d alone.
//
// Sample dimensions, in this fixed order (every sampler plugs into the same numbering):
//   0-1               pixel position inside the pixel (box filter)
//   2-3               with a thin lens only (WF_THIN_LENS): the point on the lens, so that
//                     pinhole renders keep their numbering
//   next 2            with motion blur only (WF_MOTION): the ray's time within the shutter
//                     (the first of the pair, a 1D sample), so still renders keep theirs
//   per bounce d:     WF_DIM_BOUNCE_BASE + d * WF_DIMS_PER_BOUNCE + offset, offset:
//     0               light choice
//     1-2             point on the light
//     3-4             BSDF direction
//     5               Russian roulette
//     6               BSDF lobe choice
//     7               light extra (environment texel choice)
//     8               with dispersion only (WF_HAS_DISPERSION): the wavelength a path picks
//                     at its first dispersive vertex (bsdf/dispersion.h)
//     9               with dispersion only: under --spectral hero (WF_SPECTRAL_HERO) the lane
//                     that samples a later dispersive vertex (wave/hero_lanes.glsl); unused
//                     otherwise, so that bounces still start on a pair and other scenes keep
//                     their numbering
#ifndef WF_RNG_H
#define WF_RNG_H

#include "types/glsl_cpp.h"
#include "sampling/sampler_common.h"

// The sampler is chosen at compile time (WF_SAMPLER, shader_variant.cpp); C++ code that does
// not choose gets `independent`. The CPU tests call each sampler's functions directly.
#ifndef WF_SAMPLER
#define WF_SAMPLER WF_SAMPLER_INDEPENDENT
#endif
#ifndef WF_SAMPLER_RANDOMIZE
#define WF_SAMPLER_RANDOMIZE 1
#endif
// Samplers that read the sampler table (set size, primes, blue-noise mask): the host binds it.
#define WF_SAMPLER_TABLES (WF_SAMPLER != WF_SAMPLER_INDEPENDENT && WF_SAMPLER != WF_SAMPLER_SOBOL)

#include "sampling/sampler_sobol.h"
#include "sampling/sampler_stratified.h"
#include "sampling/sampler_tables.h"
#if defined(__cplusplus) || WF_SAMPLER_TABLES
#include "sampling/sampler_radical_inverse.h"
#include "sampling/sampler_blue_noise.h"
#endif

#ifdef __cplusplus
namespace wf::gpu_types {
#endif

#define WF_DIM_PIXEL 0u
#ifndef WF_THIN_LENS
#define WF_THIN_LENS 0
#endif
#ifndef WF_MOTION
#define WF_MOTION 0
#endif
// The camera's dimensions: the point in the pixel, the point on the lens (WF_THIN_LENS), the
// time within the shutter (WF_MOTION, one dimension of a pair, so bounces start on a pair).
#define WF_DIM_LENS 2u
#if WF_THIN_LENS
#define WF_DIM_TIME 4u
#else
#define WF_DIM_TIME 2u
#endif
#if WF_MOTION
#define WF_DIM_BOUNCE_BASE (WF_DIM_TIME + 2u)
#else
#define WF_DIM_BOUNCE_BASE WF_DIM_TIME
#endif
#ifndef WF_HAS_DISPERSION
#define WF_HAS_DISPERSION 0
#endif
#if WF_HAS_DISPERSION
#define WF_DIMS_PER_BOUNCE 10u
#else
#define WF_DIMS_PER_BOUNCE 8u
#endif
#define WF_DIM_LIGHT_CHOICE 0u
#define WF_DIM_LIGHT_POINT 1u
#define WF_DIM_BSDF 3u
#define WF_DIM_ROULETTE 5u
#define WF_DIM_BSDF_LOBE 6u
#define WF_DIM_LIGHT_EXTRA 7u
#define WF_DIM_WAVELENGTH 8u
#define WF_DIM_HERO_LANE 9u

// `independent`: a fresh hash of (pixel, sample, dimension, seed) per call.
WF_INLINE vec2 independentSample2D(uint pixel, uint sampleIndex, uint dimension, uint seed) {
    uvec4 h = pcg4d(uvec4(pixel, sampleIndex, dimension, seed));
    return vec2(uintToUnitFloat(h.x), uintToUnitFloat(h.y));
}

WF_INLINE float independentSample1D(uint pixel, uint sampleIndex, uint dimension, uint seed) {
    return uintToUnitFloat(pcg4d(uvec4(pixel, sampleIndex, dimension, seed)).x);
}

#define WF_RANDOMIZE (WF_SAMPLER_RANDOMIZE != 0)

// Error replicates (--error-replicates K, WF_ERROR_REPLICATES): sample i of a pixel is sample
// i / K of replicate i % K, and each replicate randomizes the sampler with a seed of its own.
// Every replicate is then a whole sequence of the sampler (its power-of-two prefixes nets, for
// sobol), independent of the others, and interleaving keeps them equally long in any prefix
// of a pixel's samples. Replicate 0 keeps the render's seed.
#ifndef WF_ERROR_REPLICATES
#define WF_ERROR_REPLICATES 1
#endif
#define WF_REPLICATE_SALT 0x7265706cu
WF_INLINE uint replicateSeed(uint seed, uint replicate) {
    return replicate == 0u ? seed : pcg4d(uvec4(seed, replicate, WF_REPLICATE_SALT, WF_KEY_SALT)).x;
}

#if !defined(__cplusplus) && WF_SAMPLER == WF_SAMPLER_BLUENOISE
// The blue-noise mask is laid over the image: it needs the pixel's coordinates.
uvec2 samplerPixelXY(uint pixel) { return uvec2(pixel % params.width, pixel / params.width); }
#endif
#if !defined(__cplusplus) && WF_SAMPLER_TABLES
uint samplerSetSize() { return samplerTable(WF_SAMPLER_TABLE_SET_SIZE); }
#endif

WF_INLINE vec2 sample2D(uint pixel, uint sampleIndex, uint dimension, uint seed) {
#if WF_ERROR_REPLICATES > 1
    seed = replicateSeed(seed, sampleIndex % uint(WF_ERROR_REPLICATES));
    sampleIndex /= uint(WF_ERROR_REPLICATES);
#endif
#if WF_SAMPLER == WF_SAMPLER_SOBOL
    return sobolSample2D(pixel, sampleIndex, dimension, seed, WF_RANDOMIZE);
#elif WF_SAMPLER == WF_SAMPLER_STRATIFIED
    return stratifiedSample2D(pixel, sampleIndex, dimension, seed, samplerSetSize(), WF_RANDOMIZE);
#elif WF_SAMPLER == WF_SAMPLER_MULTIJITTER
    return multijitterSample2D(pixel, sampleIndex, dimension, seed, samplerSetSize(), WF_RANDOMIZE);
#elif WF_SAMPLER == WF_SAMPLER_HALTON
    return haltonSample2D(pixel, sampleIndex, dimension, seed, WF_RANDOMIZE);
#elif WF_SAMPLER == WF_SAMPLER_HAMMERSLEY
    return hammersleySample2D(pixel, sampleIndex, dimension, seed, samplerSetSize(), WF_RANDOMIZE);
#elif WF_SAMPLER == WF_SAMPLER_BLUENOISE
    return blueNoiseSample2D(samplerPixelXY(pixel), sampleIndex, dimension, seed, WF_RANDOMIZE);
#else
    return independentSample2D(pixel, sampleIndex, dimension, seed);
#endif
}

WF_INLINE float sample1D(uint pixel, uint sampleIndex, uint dimension, uint seed) {
#if WF_ERROR_REPLICATES > 1
    seed = replicateSeed(seed, sampleIndex % uint(WF_ERROR_REPLICATES));
    sampleIndex /= uint(WF_ERROR_REPLICATES);
#endif
#if WF_SAMPLER == WF_SAMPLER_SOBOL
    return sobolSample1D(pixel, sampleIndex, dimension, seed, WF_RANDOMIZE);
#elif WF_SAMPLER == WF_SAMPLER_STRATIFIED || WF_SAMPLER == WF_SAMPLER_MULTIJITTER
    return stratifiedSample1D(pixel, sampleIndex, dimension, seed, samplerSetSize(), WF_RANDOMIZE);
#elif WF_SAMPLER == WF_SAMPLER_HALTON
    return haltonSample1D(pixel, sampleIndex, dimension, seed, WF_RANDOMIZE);
#elif WF_SAMPLER == WF_SAMPLER_HAMMERSLEY
    return hammersleySample1D(pixel, sampleIndex, dimension, seed, samplerSetSize(), WF_RANDOMIZE);
#elif WF_SAMPLER == WF_SAMPLER_BLUENOISE
    return blueNoiseSample1D(samplerPixelXY(pixel), sampleIndex, dimension, seed, WF_RANDOMIZE);
#else
    return independentSample1D(pixel, sampleIndex, dimension, seed);
#endif
}

WF_INLINE uint bounceDimension(uint depth, uint offset) {
    return WF_DIM_BOUNCE_BASE + depth * WF_DIMS_PER_BOUNCE + offset;
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
