// The --json statistics file of `wavefront render`.
#pragma once
#include <string>

#include "render/wavefront_renderer.h"

namespace wf {

struct StatsContext {
    std::string scene;
    std::string device;
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t maxDepth = 0;
    uint32_t seed = 0;
};

std::string statsToJson(const RenderStats& stats, const StatsContext& context);
void writeStatsJson(const std::string& path, const RenderStats& stats,
                    const StatsContext& context);

} // namespace wf
