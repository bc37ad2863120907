// What `wavefront bench` measures and how it reports it: per-frame samples of one kernel
// (wavefront or megakernel), summarised as min/median/max, printed as a table and as JSON.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "render/wavefront_renderer.h"
#include "scene/bvh/bvh_builder.h"

namespace wf {

struct FrameSample {
    double seconds = 0.0;                        // wall time of the frame, submits included
    std::map<std::string, double> passMilliseconds; // GPU time per pass within the frame
};

struct BenchRun {
    std::string kernel;               // "wavefront" or "megakernel"
    std::vector<FrameSample> frames;  // timed frames only
    RenderStats timed;                // rays, occupancy, waves of the timed frames
    std::vector<std::pair<std::string, uint64_t>> memory; // device memory per buffer

    double seconds() const;           // sum of the timed frames' wall times
    double pathsPerSecond() const;
};

struct BenchSetup {
    std::string scene;
    std::string device;
    std::string driver;
    std::string variant;
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t samplesPerFrame = 0;
    uint32_t maxDepth = 0;
    uint32_t seed = 0;
    uint32_t warmupFrames = 0;
    uint32_t frames = 0;
    double submitBudgetSeconds = 0.0;
    uint64_t triangles = 0;
    uint64_t materials = 0;
    BvhBuildStats bvh;
    uint64_t instances = 0;          // top-level instances (0: one flat BVH)
    uint64_t instancedTriangles = 0; // triangles as rendered, every placement counted
    uint64_t peakHostMemoryBytes = 0; // VmHWM after the runs
    double loadSeconds = 0.0;         // reading and converting the glTF file
    std::string lightSelection;      // resolved: uniform, power or tree
    std::string lightSelectionText;  // describeLightSelection
    uint32_t lightTreeLights = 0;    // with the tree: its lights, depth and build time
    uint32_t lightTreeDepth = 0;
    double lightTreeBuildSeconds = 0.0;
    // What the wavefront's intersect and shadow passes traced with (the megakernel always
    // walks the BVH): "bvh" or "rt", with the acceleration structures' size and build time.
    std::string traversal = "bvh";
    std::string traversalText;
    uint64_t accelerationBytes = 0;
    double accelerationBuildSeconds = 0.0;
    // --guiding: whether the kernels guided (auto's decision and why), and the untimed
    // training before the frames (both kernels then sample the same frozen guide).
    bool guiding = false;
    std::string guidingText;
    uint32_t guideTrainingSpp = 0;
    double guideTrainingSeconds = 0.0;
};

struct Spread {
    double min = 0.0;
    double median = 0.0;
    double max = 0.0;
};
Spread spreadOf(std::vector<double> values);

// Per-frame difference of two cumulative renderer statistics (after - before).
RenderStats statsBetween(const RenderStats& before, const RenderStats& after);

std::string benchTable(const BenchSetup& setup, const BenchRun& run);
// "wavefront / megakernel: 1.23x paths/s" and the like, for runs of both kernels.
std::string benchRatioLine(const BenchRun& wavefront, const BenchRun& megakernel);
std::string benchJson(const BenchSetup& setup, const std::vector<BenchRun>& runs);

} // namespace wf
