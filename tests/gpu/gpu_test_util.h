// Helpers for GPU tests: a validation-enabled context shared by a test binary, analytic scenes
// built in code, and a one-call render.
#pragma once
#include <vector>

#include "gpu/context.h"
#include "image/error_estimate.h"
#include "render/wavefront_renderer.h"
#include "scene/scene.h"

namespace wf::test {

// One context per process, validation on; tests check its message count stays at zero.
Context& gpuContext();

// A closed axis-aligned cube [-1,1]^3 whose walls all emit `emission` and reflect `albedo`
// (double-sided), with the camera at the centre.
Scene furnaceBox(float albedo, float emission);

struct RenderResult {
    std::vector<float> rgb; // mean radiance per pixel
    RenderStats stats;
    AovImages aov;          // with RenderSettings.aov only
    ErrorEstimate estimate; // the render's own (with RenderSettings.errorEstimate)
};

RenderResult renderScene(const Scene& scene, const RenderSettings& settings);

struct MeanAndError {
    double mean;
    double standardError;
};

// Mean of the image (channels averaged) and its standard error from the spread of the
// pixels, which are independent estimates (disjoint sample streams).
MeanAndError imageMean(const std::vector<float>& rgb);

} // namespace wf::test
