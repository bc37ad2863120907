// What the integrators other than the path tracer (--integrator light, bdpt, vcm) do not take
// yet, or cannot: checked before a renderer is made, a one-line UsageError each; and how many
// pixels share each of their light subpaths (--light-share).
#pragma once
#include <cstdint>
#include <vector>

#include "render/render_settings.h"
#include "scene/scene.h"

namespace wf {

struct PreparedScene;

// UsageError naming the integrator and what it refuses; nothing for the path tracer.
void requireIntegratorSupport(const RenderSettings& settings, const PreparedScene& scene);

// Pixels per light subpath (ShaderVariant::lightShare): --light-share, else its default. bdpt
// and vcm share each light subpath among 8 pixels where no material has a Dirac lobe: on the
// Cornell box bdpt's relMSE per sample fell by 17% at 30% less time against one per pixel (the
// light tracer's splats, which no pixel's sampler stratifies, weigh less), while on the glass
// caustic, seen directly only through those splats, 8 cost 1.5x the efficiency, and vcm's
// merges on the mirror + glass box want every photon (docs/bidirectional.md). Light tracing
// keeps one per pixel, and every integrator does where something moves (a shared subpath
// would have to share its camera subpaths' instants).
uint32_t lightShareFor(const RenderSettings& settings, Integrator integrator, bool motion,
                       const std::vector<Material>& materials);

// Light subpaths per sample index of a `pixelCount` image (RenderParams::lightPaths): one per
// `share` pixels, rounded up.
uint32_t lightSubpathsPerSample(uint32_t share, uint32_t pixelCount);

} // namespace wf
