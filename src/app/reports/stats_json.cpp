#include "app/reports/stats_json.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "errors.h"
#include "image/atomic_file.h"
#include "render/adaptive_sampling.h"
#include "render/gpu_scene/scene_buffers.h"

namespace wf {

std::string jsonQuoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
            out += escaped;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

std::string jsonNumber(double value) {
    if (!std::isfinite(value))
        return "null";
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

namespace {

std::string quoted(const std::string& text) { return jsonQuoted(text); }
std::string number(double value) { return jsonNumber(value); }

} // namespace

std::string errorEstimateJson(const ErrorEstimate& e) {
    return "{\"relMse\": " + jsonNumber(e.relMse) + ", \"standardError\": " +
           jsonNumber(e.standardError) + ", \"fromSingleSamples\": " +
           jsonNumber(e.singleSampleShare) + ", \"reliable\": " +
           (e.reliable ? "true" : "false") + ", \"reason\": " + jsonQuoted(e.reason) +
           ", \"upperBound\": " + (e.upperBound ? "true" : "false") +
           ", \"replicates\": " + std::to_string(e.replicates) +
           ", \"effectivePixels\": " + jsonNumber(e.effectivePixels) + "}";
}

std::string statsToJson(const RenderStats& stats, const StatsContext& context) {
    const double seconds = stats.seconds > 0.0 ? stats.seconds : 1e-9;
    const uint64_t totalRays = stats.cameraRays + stats.extensionRays + stats.shadowRays;
    std::ostringstream out;
    out << "{\n"
        << "  \"scene\": " << quoted(context.scene) << ",\n"
        << "  \"device\": " << quoted(context.device) << ",\n"
        << "  \"width\": " << context.width << ",\n"
        << "  \"height\": " << context.height << ",\n"
        << "  \"maxDepth\": " << context.maxDepth << ",\n"
        << "  \"seed\": " << context.seed << ",\n"
        << "  \"spp\": " << stats.samplesPerPixel << ",\n"
        << "  \"seconds\": " << number(stats.seconds) << ",\n"
        << "  \"waves\": " << stats.waves << ",\n"
        << "  \"paths\": " << stats.paths << ",\n"
        << "  \"pathsPerSecond\": " << number(stats.paths / seconds) << ",\n"
        << "  \"rays\": {\"camera\": " << stats.cameraRays
        << ", \"extension\": " << stats.extensionRays << ", \"shadow\": " << stats.shadowRays
        << ", \"total\": " << totalRays << "},\n"
        << "  \"raysPerSecond\": {\"camera\": " << number(stats.cameraRays / seconds)
        << ", \"extension\": " << number(stats.extensionRays / seconds)
        << ", \"shadow\": " << number(stats.shadowRays / seconds)
        << ", \"total\": " << number(totalRays / seconds) << "},\n"
        << "  \"nonFiniteSamples\": " << stats.nonFiniteSamples << ",\n";
    for (const auto& [name, json] : context.extraFields)
        out << "  " << quoted(name) << ": " << json << ",\n";
    out << "  \"gpuMilliseconds\": {";
    bool first = true;
    for (const auto& [pass, ms] : stats.passMilliseconds) {
        out << (first ? "" : ", ") << quoted(pass) << ": " << number(ms);
        first = false;
    }
    out << "}\n}\n";
    return out.str();
}

void writeStatsJson(const std::string& path, const RenderStats& stats,
                    const StatsContext& context) {
    const std::string text = statsToJson(stats, context);
    writeFileAtomically(path, [&](const std::string& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        if (!out)
            throw InputError("cannot write " + path);
    });
}

// The scene's size and its BVH build, for --json.
std::vector<std::pair<std::string, std::string>> sceneStatsFields(const PreparedScene& scene) {
    const BvhBuildStats& bvh = scene.bvhStats;
    const double perSecond = scene.triangles.size() / std::max(bvh.buildSeconds, 1e-9);
    return {{"triangles", std::to_string(scene.triangles.size())},
            {"instances", std::to_string(scene.instances.size())},
            {"instancedTriangles", std::to_string(scene.instancedTriangles)},
            {"bvh", "{\"nodes\": " + std::to_string(bvh.nodeCount) +
                        ", \"depth\": " + std::to_string(bvh.maxDepth) +
                        ", \"sahCost\": " + jsonNumber(bvh.sahCost) +
                        ", \"traversalCost\": " + jsonNumber(bvh.traversalCost) +
                        ", \"buildSeconds\": " + jsonNumber(bvh.buildSeconds) +
                        ", \"trianglesPerSecond\": " + jsonNumber(perSecond) +
                        ", \"threads\": " + std::to_string(bvh.threads) + "}"}};
}

std::string describeTraversal(const WavefrontRenderer& renderer) {
    const AccelerationStructureSet* structures = renderer.sceneBuffers()->acceleration();
    if (renderer.traversal() == Traversal::Bvh || !structures)
        return "bvh (the project's BVH in compute)";
    char text[160];
    std::snprintf(text, sizeof text,
                  "rt (ray-tracing pipelines; acceleration structures %.2f MiB, built in %.3f s)",
                  structures->bytes() / (1024.0 * 1024.0), structures->buildSeconds());
    return text;
}

std::pair<std::string, std::string> traversalStatsField(const WavefrontRenderer& renderer) {
    const AccelerationStructureSet* structures = renderer.sceneBuffers()->acceleration();
    if (renderer.traversal() == Traversal::Bvh || !structures)
        return {"traversal", "{\"mode\": \"bvh\"}"};
    return {"traversal", "{\"mode\": \"rt\", \"accelerationBytes\": " +
                             std::to_string(structures->bytes()) +
                             ", \"accelerationBuildSeconds\": " +
                             jsonNumber(structures->buildSeconds()) + "}"};
}

std::pair<std::string, std::string> adaptiveStatsField(const AdaptiveResult& result,
                                                       double targetError, uint32_t maxSpp) {
    const SampleAllocation& allocation = result.allocation;
    return {"adaptive",
            std::string("{\"targetError\": ") + jsonNumber(targetError) +
                ", \"targetMet\": " + (result.targetMet ? "true" : "false") +
                ", \"stoppedBy\": " + jsonQuoted(result.stoppedBy) +
                ", \"estimatedRelMse\": " + jsonNumber(result.estimate.relMse) +
                ", \"predictedRelMse\": " + jsonNumber(allocation.predictedRelMse) +
                ", \"meanSpp\": " + jsonNumber(result.meanSpp) +
                ", \"pilotSpp\": " + std::to_string(result.pilotSpp) +
                ", \"imageRounds\": " + std::to_string(result.imageRounds) +
                ", \"minSpp\": " + std::to_string(allocation.levels.front()) +
                ", \"maxSpp\": " + std::to_string(maxSpp) +
                ", \"levels\": " + std::to_string(allocation.levels.size()) + "}"};
}

} // namespace wf
