#include "render/render_stats.h"

#include <algorithm>

namespace wf {

void addRenderStats(RenderStats& total, const RenderStats& more) {
    total.samplesPerPixel += more.samplesPerPixel;
    total.seconds += more.seconds;
    total.paths += more.paths;
    total.cameraRays += more.cameraRays;
    total.extensionRays += more.extensionRays;
    total.shadowRays += more.shadowRays;
    total.nonFiniteSamples += more.nonFiniteSamples;
    total.waves += more.waves;
    total.longestSubmitSeconds = std::max(total.longestSubmitSeconds, more.longestSubmitSeconds);
    for (const auto& [pass, ms] : more.passMilliseconds)
        total.passMilliseconds[pass] += ms;
    total.depthRays.resize(std::max(total.depthRays.size(), more.depthRays.size()), 0);
    total.depthShadowRays.resize(
        std::max(total.depthShadowRays.size(), more.depthShadowRays.size()), 0);
    for (size_t d = 0; d < more.depthRays.size(); ++d)
        total.depthRays[d] += more.depthRays[d];
    for (size_t d = 0; d < more.depthShadowRays.size(); ++d)
        total.depthShadowRays[d] += more.depthShadowRays[d];
}

} // namespace wf
