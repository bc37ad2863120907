// Counter-based random numbers: a sample is a pure function of (pixel, sample index, dimension,
// seed), so an image does not depend on which path lands in which queue slot, waves can be
// split any way, and a render is reproducible bit for bit.
//
// Sample dimensions, in this fixed order (every sampler plugs into the same numbering):
//   0-1               pixel position inside the pixel (box filter)
//   per bounce d:     WF_DIM_BOUNCE_BASE + d * WF_DIMS_PER_BOUNCE + offset, offset:
//     0               light choice
//     1-2             point on the light
//     3-4             BSDF direction
//     5               Russian roulette
//     6               BSDF lobe choice
//     7               light extra (environment texel choice)
#ifndef WF_RNG_H
#define WF_RNG_H

#include "glsl_cpp.h"

#ifdef __cplusplus
namespace wf::gpu_types {
#endif

#define WF_DIM_PIXEL 0u
#define WF_DIM_BOUNCE_BASE 2u
#define WF_DIMS_PER_BOUNCE 8u
#define WF_DIM_LIGHT_CHOICE 0u
#define WF_DIM_LIGHT_POINT 1u
#define WF_DIM_BSDF 3u
#define WF_DIM_ROULETTE 5u
#define WF_DIM_BSDF_LOBE 6u
#define WF_DIM_LIGHT_EXTRA 7u

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

WF_INLINE vec2 sample2D(uint pixel, uint sampleIndex, uint dimension, uint seed) {
    uvec4 h = pcg4d(uvec4(pixel, sampleIndex, dimension, seed));
    return vec2(uintToUnitFloat(h.x), uintToUnitFloat(h.y));
}

WF_INLINE float sample1D(uint pixel, uint sampleIndex, uint dimension, uint seed) {
    return uintToUnitFloat(pcg4d(uvec4(pixel, sampleIndex, dimension, seed)).x);
}

WF_INLINE uint bounceDimension(uint depth, uint offset) {
    return WF_DIM_BOUNCE_BASE + depth * WF_DIMS_PER_BOUNCE + offset;
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
