// The sampler table: one read-only array of uints that the table-driven samplers read (the
// set size of the finite-set samplers, the primes of Halton and Hammersley, the blue-noise
// mask). The host builds it (src/render/samplers/sampler_tables.cpp: a sieve and a void-and-cluster
// generator, both run at start-up, nothing stored) and binds it only for samplers that read
// it (WF_SAMPLER_TABLES). The C++ side reads the same numbers through samplerTable().
#ifndef WF_SAMPLER_TABLES_H
#define WF_SAMPLER_TABLES_H

#include "types/glsl_cpp.h"

#define WF_BINDING_SAMPLER_TABLES 32

// Layout, in uints.
#define WF_SAMPLER_TABLE_SET_SIZE 0u // samples in one finite set (stratified, ..., hammersley)
#define WF_SAMPLER_TABLE_PRIMES 4u   // the first WF_SAMPLER_PRIME_COUNT primes, 2 first
#define WF_SAMPLER_PRIME_COUNT 1024u
#define WF_SAMPLER_TABLE_BLUE_NOISE (WF_SAMPLER_TABLE_PRIMES + WF_SAMPLER_PRIME_COUNT)
#define WF_BLUE_NOISE_SIZE 128u      // the mask is WF_BLUE_NOISE_SIZE^2 ranks, tiled
#define WF_BLUE_NOISE_LOG2_TEXELS 14u
#define WF_BLUE_NOISE_TEXELS (WF_BLUE_NOISE_SIZE * WF_BLUE_NOISE_SIZE)
#define WF_SAMPLER_TABLE_SIZE (WF_SAMPLER_TABLE_BLUE_NOISE + WF_BLUE_NOISE_TEXELS)

#ifdef __cplusplus
namespace wf::gpu_types {
// The table without a set size (the CPU tests pass set sizes explicitly), built once.
uint samplerTable(uint index);
} // namespace wf::gpu_types
#else
#if WF_SAMPLER_TABLES
// An R32UI storage texel buffer: scattered reads are cheapest as imageLoad (scene_tables.glsl).
layout(binding = WF_BINDING_SAMPLER_TABLES, r32ui) uniform readonly restrict uimageBuffer
    samplerTableTexels;
uint samplerTable(uint index) { return imageLoad(samplerTableTexels, int(index)).x; }
#endif
#endif

#endif
