// What the integrators other than the path tracer (--integrator light, bdpt) do not take yet,
// or cannot: checked before a renderer is made, a one-line UsageError each.
#pragma once
#include "render/render_settings.h"

namespace wf {

struct PreparedScene;

// UsageError naming the integrator and what it refuses; nothing for the path tracer.
void requireIntegratorSupport(const RenderSettings& settings, const PreparedScene& scene);

} // namespace wf
