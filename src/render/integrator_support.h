// What the integrators other than the path tracer (--integrator light, bdpt) do not take yet,
// or cannot: checked before a renderer is made, a one-line UsageError each.
#pragma once
#include "render/render_settings.h"

namespace wf {

struct PreparedScene;

// UsageError naming the integrator and what it refuses; nothing for the path tracer.
void requireIntegratorSupport(const RenderSettings& settings, const PreparedScene& scene);

// --light-share's default: bdpt shares each light subpath among 8 pixels (on the Cornell box
// its relMSE per sample fell by 17% and its time by 30% against one per pixel: the light
// tracer's splats, which no pixel's sampler stratifies, weigh less; docs/bidirectional.md);
// light tracing and vcm keep one per pixel.
uint32_t defaultLightShare(Integrator integrator);

// Light subpaths per sample index of a `pixelCount` image (RenderParams::lightPaths): one per
// --light-share pixels, rounded up; one per pixel where something moves (a shared subpath
// would have to share its camera subpaths' instants).
uint32_t lightSubpathsPerSample(const RenderSettings& settings, Integrator integrator,
                                bool motion, uint32_t pixelCount);

} // namespace wf
