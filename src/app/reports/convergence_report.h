// The files of `wavefront converge DIR`: convergence.csv (one row per method, seed and
// checkpoint), convergence.json (the run, per-checkpoint medians and quartiles, slopes, the
// ranking), equal-time crops, and the ranking as printed text.
#pragma once
#include <limits>
#include <string>
#include <vector>

#include "render/convergence_summary.h"

namespace wf {

struct ConvergenceInfo {
    std::string scene;
    std::string device;
    std::string traversal = "bvh"; // what intersect and shadow traced with: bvh or rt
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t maxDepth = 0;
    std::vector<uint32_t> seeds;
    double timeBudget = 0.0;
    std::string reference;        // the reference's path
    std::string referenceMethod;  // how Wavefront rendered it, or "given"
    uint32_t referenceSpp = 0;    // 0 when given
    // The relMSE the reference's own noise adds to every figure against it (error_metrics.h's
    // referenceNoiseRelMse of its two halves); NaN when unknown (a given reference).
    double referenceNoise = std::numeric_limits<double>::quiet_NaN();
    double target = 0.0;          // relMSE of the ranking
    int crop[4] = {0, 0, 0, 0};   // x, y, width, height of the equal-time crops
};

struct EqualTimeCrop {
    std::string method;
    std::string file; // relative to DIR
    uint32_t spp = 0;
    double gpuSeconds = 0.0;
};

void writeConvergenceCsv(const std::string& path, const std::vector<MethodRun>& runs);

// Crops of the first seed's images, one per method, each at its checkpoint closest (in log
// time) to the GPU time every method reached (the smallest of the final medians), plus the
// reference's: DIR/crops/<method>.png, tonemapped like render's PNG.
std::vector<EqualTimeCrop> writeEqualTimeCrops(const std::string& dir,
                                               const std::vector<MethodRun>& runs,
                                               const std::vector<MethodSummary>& summaries,
                                               const std::vector<float>& reference,
                                               const ConvergenceInfo& info);

void writeConvergenceJson(const std::string& path, const ConvergenceInfo& info,
                          const std::vector<MethodRun>& runs,
                          const std::vector<MethodSummary>& summaries,
                          const std::vector<EqualTimeCrop>& crops);

// "rank  method  time to target  slope ..." lines, fastest first.
std::string rankingText(const std::vector<MethodSummary>& summaries, double target);

} // namespace wf
