#include "viewer/render_targets.h"

#include <algorithm>
#include <chrono>

#include "gpu/buffer.h"
#include "render/gpu_scene/scene_buffers.h"

namespace wf {

RenderTargets::RenderTargets(const Context& context, const ShaderCompiler& compiler,
                             const PreparedScene& scene)
    : context_(context), compiler_(compiler), scene_(&scene) {}

void RenderTargets::setScene(const PreparedScene& scene) {
    scene_ = &scene;
    if (preview_.renderer && !preview_.renderer->setScene(scene))
        preview_ = {};
    preview_.cameraVersion = ~uint64_t(0);
    if (!full_.renderer)
        return;
    if (!full_.renderer->setScene(scene)) {
        const SampleBudget budget = full_.budget;
        full_ = {};
        full_ = makeTarget(1);
        full_.budget = budget;
    }
    full_.cameraVersion = ~uint64_t(0); // setScene took the file's camera: follow the view's
}

void RenderTargets::rebuild(VkExtent2D size, const RenderSettings& settings,
                            const Buffer& displayBuffer) {
    // Keep the measured cost across a rebuild of the same size: the next frame's budget and
    // the preview choice stay sensible instead of starting again from one sample.
    const bool sameSize = size.width == size_.width && size.height == size_.height;
    const SampleBudget budget = full_.budget;
    preview_ = {};
    full_ = {};
    size_ = size;
    settings_ = settings;
    settings_.width = size.width;
    settings_.height = size.height;
    settings_.samplesPerPixel = 1u << 30; // the viewer asks for samples frame by frame
    settings_.errorEstimate = false;      // it shows no error estimate: no moment film
    displayBuffer_ = &displayBuffer;
    full_ = makeTarget(1);
    if (sameSize)
        full_.budget = budget;
}

void RenderTargets::setTargetSeconds(double seconds) {
    targetSeconds_ = seconds;
    full_.budget.setTarget(seconds);
    preview_.budget.setTarget(seconds);
}

RenderTarget RenderTargets::makeTarget(uint32_t divisor) {
    RenderSettings settings = settings_;
    settings.width = std::max(1u, size_.width / divisor);
    settings.height = std::max(1u, size_.height / divisor);
    // A frame renders the budget's few samples, so path buffers for one sample of every pixel
    // suffice (not the render command's 2^20 paths per renderer); the floor keeps a small
    // window's frame to one wave.
    settings.maxPathsPerWave = std::max(settings.width * settings.height, 1u << 18);
    if (divisor > 1)
        settings.guiding = false; // the moving-camera preview is too brief to train a guide
    RenderTarget target;
    target.divisor = divisor;
    target.budget = SampleBudget(targetSeconds_);
    // The preview reads the full-size renderer's scene tables rather than a copy of its own.
    std::shared_ptr<const SceneBuffers> sharedScene =
        divisor > 1 && full_.renderer ? full_.renderer->sceneBuffers() : nullptr;
    target.renderer = std::make_unique<WavefrontRenderer>(context_, *scene_, settings, compiler_,
                                                          std::move(sharedScene));
    target.display = std::make_unique<DisplayPass>(
        context_, compiler_, target.renderer->film(), DisplaySize{settings.width, settings.height},
        *displayBuffer_, DisplaySize{size_.width, size_.height});
    return target;
}

RenderTarget& RenderTargets::preview(uint32_t divisor) {
    if (!preview_.renderer || preview_.divisor != divisor)
        preview_ = makeTarget(divisor);
    return preview_;
}

uint32_t RenderTargets::movingDivisor() const {
    const double pixels = double(size_.width) * size_.height;
    return previewDivisor(size_.width, size_.height, full_.budget.secondsPerSample() / pixels,
                          targetSeconds_);
}

void RenderTargets::follow(RenderTarget& target, const Camera& camera, uint64_t version) {
    if (target.cameraVersion == version)
        return;
    target.renderer->setCamera(camera);
    target.cameraVersion = version;
}

uint32_t RenderTargets::render(RenderTarget& target, uint32_t sppLimit) {
    WavefrontRenderer& renderer = *target.renderer;
    const uint32_t done = renderer.samplesDone();
    if (sppLimit > 0 && done >= sppLimit)
        return 0;
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    const double perSample = target.budget.secondsPerSample();
    const uint32_t pixels = renderer.pixelCount();
    if (perSample > targetSeconds_ || renderer.pixelsOfNextSample() > 0) {
        // One sample of the image is over the frame-time target: trace the part of it that
        // fits, so the frame stays responsive; the sample completes over several frames.
        const double fraction = perSample > 0.0 ? targetSeconds_ / perSample : 1.0;
        const uint32_t paths = static_cast<uint32_t>(std::max(1.0, fraction * pixels));
        const uint32_t traced = renderer.renderPixels(paths);
        target.budget.record(double(traced) / pixels, elapsed());
        return renderer.samplesDone() - done;
    }
    uint32_t samples = target.budget.nextSamples();
    if (sppLimit > 0)
        samples = std::min(samples, sppLimit - done);
    renderer.renderSamples(samples);
    target.budget.record(samples, elapsed());
    return samples;
}

} // namespace wf
