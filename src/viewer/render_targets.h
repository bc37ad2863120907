// The renderers a viewer frame can draw from, each with its display pass and sample budget:
// the full-resolution one, which accumulates, and a preview at 1/d of the resolution that the
// viewer uses while the camera moves and one full-resolution sample is over the frame target
// (on lavapipe one sample of 800x600 takes most of a second). The preview is created on first
// use and holds its own copy of the scene's buffers. A target follows the camera lazily: only
// the one drawn from is moved (which restarts its accumulation).
#pragma once
#include <cstdint>
#include <memory>

#include <vulkan/vulkan.h>

#include "render/wavefront_renderer.h"
#include "viewer/display_pass.h"
#include "viewer/sample_budget.h"

namespace wf {

class Buffer;
class Context;
struct PreparedScene;

struct RenderTarget {
    std::unique_ptr<WavefrontRenderer> renderer;
    std::unique_ptr<DisplayPass> display;
    SampleBudget budget{0.033};
    uint32_t divisor = 1;
    uint64_t cameraVersion = ~uint64_t(0); // the camera it renders; none yet
};

class RenderTargets {
public:
    RenderTargets(const Context& context, const ShaderCompiler& compiler,
                  const PreparedScene& scene);

    // Drops every renderer and builds the full-resolution one for `size` and `settings`
    // (width and height are taken from `size`), displaying into `displayBuffer`.
    void rebuild(VkExtent2D size, const RenderSettings& settings, const Buffer& displayBuffer);
    void setTargetSeconds(double seconds);

    RenderTarget& full() { return full_; }
    uint32_t fullSpp() const { return full_.renderer ? full_.renderer->samplesDone() : 0; }
    // The preview at 1/divisor resolution (divisor > 1), created or rebuilt on demand.
    RenderTarget& preview(uint32_t divisor);
    // The divisor to use while the camera moves: 1 when a full sample fits the target.
    uint32_t movingDivisor() const;

    // Another pose of the scene (the viewer's playback; `scene` must outlive the targets or the
    // next call): each renderer takes its tables under the same pipelines (the preview then
    // holds a copy of its own), or is rebuilt (the preview: dropped) where the shaders differ.
    // Both follow the camera afresh and restart their accumulation.
    void setScene(const PreparedScene& scene);

    // Moves `target` to `camera` unless it is there already (`version` counts camera changes).
    static void follow(RenderTarget& target, const Camera& camera, uint64_t version);
    // Renders this frame's samples into `target` (at most up to `sppLimit`, 0: no limit) and
    // feeds the time into its budget. Returns the samples rendered.
    uint32_t render(RenderTarget& target, uint32_t sppLimit);

private:
    RenderTarget makeTarget(uint32_t divisor);

    const Context& context_;
    const ShaderCompiler& compiler_;
    const PreparedScene* scene_; // setScene moves it on
    RenderSettings settings_;
    VkExtent2D size_{};
    const Buffer* displayBuffer_ = nullptr;
    double targetSeconds_ = 0.033;
    RenderTarget full_;
    RenderTarget preview_;
};

} // namespace wf
