// Helpers for GPU tests: a validation-enabled context shared by a test binary, analytic scenes
// built in code, and a one-call render.
#pragma once
#include <string>
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
// The same on another context (the ray-tracing tests' own, rayTracingContext()).
RenderResult renderScene(const Scene& scene, const RenderSettings& settings, Context& context);

// A second validation-enabled context with the driver's ray tracing enabled, or null where the
// device has none (Mesa 22.3's lavapipe): the --traversal rt tests skip there.
Context* rayTracingContext();

struct MeanAndError {
    double mean;
    double standardError;
};

// Mean of the image (channels averaged) and its standard error from the spread of the
// pixels, which are independent estimates (disjoint sample streams).
MeanAndError imageMean(const std::vector<float>& rgb);

// Each block x block region's mean over `images` (independent renders of `width` x `height`
// pixels, rgb) against the reference's, within 5 standard errors (the images' spread and the
// reference's variance layer, rgb per pixel) plus 0.2%: a gtest failure per region that is
// not, named by `what`. Returns the regions checked.
// `skipRegion`, when given, holds one flag per region (row by row): those are not checked.
int expectRegionsUnbiased(const std::vector<std::vector<float>>& images,
                          const std::vector<float>& reference,
                          const std::vector<float>& referenceVariance, uint32_t width,
                          uint32_t height, uint32_t block, const std::string& what,
                          const std::vector<bool>* skipRegion = nullptr);

// A shade variant with the switches that touch the BSDF set by the bits of `bits`: 1 textures
// (with ray cones), 2 volume, 4 the layers (clear coat and sheen), 8 path guiding. The
// extensions' tests add their own switch and compile it beside each.
inline ShaderDefines materialSwitchDefines(int bits) {
    const bool textures = bits & 1;
    return {{"WF_WORKGROUP_SIZE", "64"},
            {"WF_HAS_EMITTERS", "1"},
            {"WF_HAS_TRIANGLE_EMITTERS", "1"},
            {"WF_LIGHT_SAMPLING", "2"},
            {"WF_HAS_NORMALS", "1"},
            {"WF_HAS_TEXTURES", textures ? "1" : "0"},
            {"WF_TEXEL_PAGES", textures ? "1" : "0"},
            {"WF_RAY_CONES", textures ? "1" : "0"},
            {"WF_HAS_VOLUME", bits & 2 ? "1" : "0"},
            {"WF_HAS_CLEARCOAT", bits & 4 ? "1" : "0"},
            {"WF_HAS_SHEEN", bits & 4 ? "1" : "0"},
            {"WF_GUIDING", bits & 8 ? "1" : "0"}};
}

// Whether a shader variant defines `key` (the extensions' switches are defined only where used).
inline bool hasDefine(const ShaderDefines& defines, const std::string& key) {
    for (const auto& [name, value] : defines)
        if (name == key)
            return true;
    return false;
}

} // namespace wf::test
