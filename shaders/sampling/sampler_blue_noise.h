// `bluenoise`: the Sobol (0, 2)-sequence of sampler_sobol.h, digitally shifted per pixel by keys
// read from a blue-noise mask (a void-and-cluster rank mask, src/render/samplers/blue_noise.cpp), in the
// spirit of Heitz et al., "A Low-Discrepancy Sampler that Distributes Monte Carlo Errors as a
// Blue Noise in Screen Space" (2019): there, optimised per-pixel scrambling keys; here, the
// mask's ranks as the keys' leading bits.
//   - Every pixel uses the same points in the same order (the index shuffle depends on the
//     dimension and seed only), XORed with its own key. A digital shift keeps each pixel's
//     power-of-two prefixes (0, m, 2)-nets, and at low sample counts neighbouring pixels get
//     keys far apart, so their errors anti-correlate: error as blue noise.
//   - Each dimension reads the mask at its own toroidal offset, slot * 6451 (odd, so the first
//     16384 dimensions all get distinct offsets): dimensions stay uncorrelated.
//   - Randomization: one offset per seed, uniform over the mask, plus random low bits below the
//     rank's 14, make each key uniform over [0, 2^32) at every pixel: unbiased over seeds.
// Without randomization the offset is 0 and the low bits fixed: every seed gives the same image.
#ifndef WF_SAMPLER_BLUE_NOISE_H
#define WF_SAMPLER_BLUE_NOISE_H

#include "sampling/sampler_sobol.h"
#include "sampling/sampler_tables.h"

#ifdef __cplusplus
namespace wf::gpu_types {
#endif

#define WF_BLUE_NOISE_SLOT_STRIDE 6451u

// The mask's rank under `pixelXY`, with the mask shifted for this slot and seed offset.
WF_INLINE uint blueNoiseRank(uvec2 pixelXY, uint slot, uint seedOffset) {
    uint shift = (seedOffset + slot * WF_BLUE_NOISE_SLOT_STRIDE) & (WF_BLUE_NOISE_TEXELS - 1u);
    uint x = (pixelXY.x + shift % WF_BLUE_NOISE_SIZE) % WF_BLUE_NOISE_SIZE;
    uint y = (pixelXY.y + shift / WF_BLUE_NOISE_SIZE) % WF_BLUE_NOISE_SIZE;
    return samplerTable(WF_SAMPLER_TABLE_BLUE_NOISE + y * WF_BLUE_NOISE_SIZE + x);
}

// x: index shuffle, y and z: low key bits of the two coordinates, w: the seed's mask offset.
WF_INLINE uvec4 blueNoiseKeys(uint dimension, uint seed, bool randomize) {
    uvec4 keys = samplerKeys(0xffffffffu, dimension, randomize ? seed : 0u);
    keys.w = randomize ? pcg4d(uvec4(seed, WF_KEY_SALT, 0u, 0u)).x : 0u;
    if (!randomize) {
        keys.y = 0x80000000u; // the middle of each rank's interval
        keys.z = 0x80000000u;
    }
    return keys;
}

WF_INLINE uint blueNoiseKey(uvec2 pixelXY, uint slot, uint seedOffset, uint lowBits) {
    return (blueNoiseRank(pixelXY, slot, seedOffset) << (32u - WF_BLUE_NOISE_LOG2_TEXELS)) |
           (lowBits >> WF_BLUE_NOISE_LOG2_TEXELS);
}

WF_INLINE float blueNoiseSample1D(uvec2 pixelXY, uint sampleIndex, uint dimension, uint seed,
                                  bool randomize) {
    uvec4 keys = blueNoiseKeys(dimension, seed, randomize);
    uint index = owenScramble(sampleIndex, keys.x);
    return uintToUnitFloat(sobolDimension0(index) ^
                           blueNoiseKey(pixelXY, dimension, keys.w, keys.y));
}

WF_INLINE vec2 blueNoiseSample2D(uvec2 pixelXY, uint sampleIndex, uint dimension, uint seed,
                                 bool randomize) {
    uvec4 keys = blueNoiseKeys(dimension, seed, randomize);
    uint index = owenScramble(sampleIndex, keys.x);
    return vec2(
        uintToUnitFloat(sobolDimension0(index) ^ blueNoiseKey(pixelXY, dimension, keys.w, keys.y)),
        uintToUnitFloat(sobolDimension1(index) ^
                        blueNoiseKey(pixelXY, dimension + 1u, keys.w, keys.z)));
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
