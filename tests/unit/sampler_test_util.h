// Test-side view of the samplers: one call that runs any sampler's shared function
// (shaders/sampling/sampler_*.h, exactly what the shaders run), as rng.h's compile-time dispatch
// would in a shader built for that sampler, plus point-set figures (L2-star discrepancy).
#ifndef WF_TESTS_SAMPLER_TEST_UTIL_H
#define WF_TESTS_SAMPLER_TEST_UTIL_H

#include <algorithm>
#include <cstdint>
#include <vector>

#include "render/samplers/samplers.h"
#include "shaders/sampling/rng.h"

namespace wf::test {

// Where a sample is taken: the pixel (index and coordinates in an image `width` wide), the seed,
// the finite-set size and whether the sampler randomizes.
struct SampleSite {
    uint32_t x = 0;
    uint32_t y = 0;
    uint32_t width = 64;
    uint32_t seed = 0;
    uint32_t setSize = 64;
    bool randomize = true;
    uint32_t pixel() const { return y * width + x; }
};

inline glm::vec2 samplePoint2D(SamplerKind kind, const SampleSite& s, uint32_t index,
                               uint32_t dimension) {
    using namespace gpu_types;
    const uint32_t p = s.pixel();
    switch (kind) {
    case SamplerKind::Stratified:
        return stratifiedSample2D(p, index, dimension, s.seed, s.setSize, s.randomize);
    case SamplerKind::Multijitter:
        return multijitterSample2D(p, index, dimension, s.seed, s.setSize, s.randomize);
    case SamplerKind::Halton: return haltonSample2D(p, index, dimension, s.seed, s.randomize);
    case SamplerKind::Hammersley:
        return hammersleySample2D(p, index, dimension, s.seed, s.setSize, s.randomize);
    case SamplerKind::Sobol: return sobolSample2D(p, index, dimension, s.seed, s.randomize);
    case SamplerKind::BlueNoise:
        return blueNoiseSample2D(uvec2(s.x, s.y), index, dimension, s.seed, s.randomize);
    default: return independentSample2D(p, index, dimension, s.seed);
    }
}

inline float samplePoint1D(SamplerKind kind, const SampleSite& s, uint32_t index,
                           uint32_t dimension) {
    using namespace gpu_types;
    const uint32_t p = s.pixel();
    switch (kind) {
    case SamplerKind::Stratified:
    case SamplerKind::Multijitter:
        return stratifiedSample1D(p, index, dimension, s.seed, s.setSize, s.randomize);
    case SamplerKind::Halton: return haltonSample1D(p, index, dimension, s.seed, s.randomize);
    case SamplerKind::Hammersley:
        return hammersleySample1D(p, index, dimension, s.seed, s.setSize, s.randomize);
    case SamplerKind::Sobol: return sobolSample1D(p, index, dimension, s.seed, s.randomize);
    case SamplerKind::BlueNoise:
        return blueNoiseSample1D(uvec2(s.x, s.y), index, dimension, s.seed, s.randomize);
    default: return independentSample1D(p, index, dimension, s.seed);
    }
}

// The value of dimension `dimension` as the renderer would read it: sample2D calls start at
// the pixel pair and at the light-point and BSDF pairs of each bounce, sample1D calls elsewhere.
inline float sampleCoordinate(SamplerKind kind, const SampleSite& s, uint32_t index,
                              uint32_t dimension) {
    if (dimension < WF_DIM_BOUNCE_BASE)
        return samplePoint2D(kind, s, index, WF_DIM_PIXEL)[dimension];
    const uint32_t offset = (dimension - WF_DIM_BOUNCE_BASE) % WF_DIMS_PER_BOUNCE;
    const uint32_t base = dimension - offset;
    for (uint32_t pairStart : {WF_DIM_LIGHT_POINT, WF_DIM_BSDF})
        if (offset == pairStart || offset == pairStart + 1)
            return samplePoint2D(kind, s, index, base + pairStart)[offset - pairStart];
    return samplePoint1D(kind, s, index, dimension);
}

// Squared L2-star discrepancy of points in [0, 1)^2 (Warnock's formula). Expectation for N
// independent uniform points: (1/4 - 1/9) / N.
inline double l2StarDiscrepancySquared(const std::vector<glm::vec2>& points) {
    const double n = double(points.size());
    double single = 0.0, pairs = 0.0;
    for (const glm::vec2& a : points) {
        single += (1.0 - double(a.x) * a.x) * (1.0 - double(a.y) * a.y);
        for (const glm::vec2& b : points)
            pairs += (1.0 - std::max<double>(a.x, b.x)) * (1.0 - std::max<double>(a.y, b.y));
    }
    return 1.0 / 9.0 - single / (2.0 * n) + pairs / (n * n);
}

inline double randomL2StarDiscrepancySquared(size_t n) { return (0.25 - 1.0 / 9.0) / double(n); }

} // namespace wf::test

#endif
