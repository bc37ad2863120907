// What a render did: samples, paths and rays by kind, waves, GPU time per pass and queue
// occupancy per depth, as the --json statistics and `wavefront bench` report them.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace wf {

struct RenderStats {
    uint32_t samplesPerPixel = 0;
    double seconds = 0.0;
    uint64_t paths = 0;
    uint64_t cameraRays = 0;
    uint64_t extensionRays = 0;
    uint64_t shadowRays = 0;
    uint64_t nonFiniteSamples = 0;
    uint32_t waves = 0;
    double longestSubmitSeconds = 0.0; // wall time of the longest wave (one submit each)
    std::map<std::string, double> passMilliseconds; // GPU time per pass, summed over waves
    // Queue occupancy: rays traced at each depth (0: camera rays) and NEE connections made at
    // each depth; the last entry also counts every deeper bounce (WF_TRACKED_DEPTHS entries).
    std::vector<uint64_t> depthRays;
    std::vector<uint64_t> depthShadowRays;
    // --guiding: the training iterations.
    struct GuideIterationStats {
        uint32_t samplesPerPixel = 0;
        uint64_t spatialLeaves = 0;
        uint64_t directionalNodes = 0;
        double meanBsdfFraction = 0.0; // the leaves' BSDF shares after it, weighted by records
        uint64_t guidedLeaves = 0;     // leaves that sample the guide after it (share < 1)
        uint64_t payingLeaves = 0;     // of those, the ones whose share pays (kMinVarianceCut)
        double seconds = 0.0;        // rendering the iteration
        double rebuildSeconds = 0.0; // reading back, rebuilding and uploading the trees
    };
    std::vector<GuideIterationStats> guideIterations;
    // Training ended early: the learnt shares said the guide does not pay (GuideSchedule);
    // the image then samples the BSDF alone.
    bool guideStoppedUnused = false;
    uint32_t guideFinalSamples = 0; // samples per pixel in the image (all iterations combined)
    // Combined images: each iteration's weight (training iterations, then the last), sum 1.
    std::vector<double> guideWeights;
    uint64_t guideBytes = 0;        // device memory of the guide
};

// Adds `more`'s counts and times to `total`: sums, except the longest submit (the larger).
void addRenderStats(RenderStats& total, const RenderStats& more);

struct WaveProgress {
    uint32_t samplesDone;
    uint32_t samplesTotal;
    double secondsElapsed;
};

} // namespace wf
