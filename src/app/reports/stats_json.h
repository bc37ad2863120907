// The --json statistics file of `wavefront render`.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "image/error_estimate.h"
#include "render/wavefront_renderer.h"

namespace wf {
struct AdaptiveResult;
}

namespace wf {

struct StatsContext {
    std::string scene;
    std::string device;
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t maxDepth = 0;
    uint32_t seed = 0;
    // More top-level fields, each a name and its JSON text (--target-error's "adaptive").
    std::vector<std::pair<std::string, std::string>> extraFields;
};

// JSON text pieces, shared with the bench report: a quoted, escaped string; a number (null when
// not finite).
std::string jsonQuoted(const std::string& text);
std::string jsonNumber(double value);

// {"relMse", "standardError", "fromSingleSamples", "reliable", "reason", "upperBound"}
std::string errorEstimateJson(const ErrorEstimate& estimate);

// The scene's size and its BVH build: the fields --json adds about the scene.
std::vector<std::pair<std::string, std::string>> sceneStatsFields(const PreparedScene& scene);
// "traversal": {"mode": "bvh"} or {"mode": "rt", "accelerationBytes", "accelerationBuildSeconds"}
std::pair<std::string, std::string> traversalStatsField(const WavefrontRenderer& renderer);
// The same for --verbose and the bench: "bvh (...)" or "rt (... MiB, built in ... s)".
std::string describeTraversal(const WavefrontRenderer& renderer);

// The "adaptive" field of a --target-error render (maxSpp: --spp, the most a pixel gets).
std::pair<std::string, std::string> adaptiveStatsField(const AdaptiveResult& result,
                                                       double targetError, uint32_t maxSpp);

std::string statsToJson(const RenderStats& stats, const StatsContext& context);
void writeStatsJson(const std::string& path, const RenderStats& stats,
                    const StatsContext& context);

} // namespace wf
