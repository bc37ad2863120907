// The guided GPU tests' render settings: 32x32 images (8x8 regions), max depth 6.
#pragma once
#include <cstdint>

#include "render/render_settings.h"

namespace wf::test {

constexpr uint32_t kGuidedSize = 32, kGuidedBlock = 8;

inline RenderSettings guidedTestSettings(uint32_t spp, uint32_t seed, bool guiding,
                                         bool combine = true) {
    RenderSettings settings;
    settings.width = kGuidedSize;
    settings.height = kGuidedSize;
    settings.samplesPerPixel = spp;
    settings.maxDepth = 6;
    settings.seed = seed;
    settings.guiding = guiding;
    settings.guideCombineIterations = combine;
    return settings;
}

} // namespace wf::test
