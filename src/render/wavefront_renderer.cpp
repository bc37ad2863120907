#include "render/wavefront_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "errors.h"
#include "gpu/compute_program.h"
#include "gpu/context.h"
#include "gpu/timestamp_timer.h"
#include "passes/accumulate_pass.h"
#include "passes/intersect_pass.h"
#include "passes/queue_pass.h"
#include "passes/raygen_pass.h"
#include "passes/shade_pass.h"
#include "passes/shadow_pass.h"
#include "render/path_buffers.h"
#include "render/scene_buffers.h"
#include "render/workgroup.h"
#include "shaders/shared/render_types.h"

namespace wf {

using gpu_types::QueueCounters;
using gpu_types::RenderParams;

gpu_types::vec3 cameraRight(const Camera& camera) {
    return glm::normalize(glm::cross(camera.forward, camera.up));
}

WavefrontRenderer::WavefrontRenderer(const Context& context, const PreparedScene& scene,
                                     const RenderSettings& settings,
                                     const ShaderCompiler& compiler)
    : context_(context), settings_(settings), scene_(scene) {
    if (settings.width == 0 || settings.height == 0 || settings.samplesPerPixel == 0 ||
        settings.maxDepth == 0)
        throw UsageError("width, height, spp and max depth must all be at least 1");
    const uint64_t pixels = uint64_t(settings.width) * settings.height;
    const uint64_t maxPaths = uint64_t(kMaxGroupsX) * kWorkgroupSize;
    if (pixels > maxPaths)
        throw UsageError("image of " + std::to_string(pixels) + " pixels is over the limit of " +
                         std::to_string(maxPaths) + " pixels per wave");
    pixelCount_ = static_cast<uint32_t>(pixels);
    // A wave holds whole samples of every pixel, as many as fit the per-wave path budget.
    samplesPerWave_ = std::clamp<uint32_t>(
        static_cast<uint32_t>(std::min<uint64_t>(settings.maxPathsPerWave, maxPaths) / pixels), 1,
        settings.samplesPerPixel);
    pathCapacity_ = pixelCount_ * samplesPerWave_;
    variant_ = chooseVariant(scene, settings);
    variant_.surface = surfaceFeatures(scene.surface, scene.materials,
                                       context.properties().limits.maxStorageBufferRange);
    defines_ = variant_.defines();
    sceneBuffers_ = std::make_unique<SceneBuffers>(context, scene, variant_);
    pathBuffers_ = std::make_unique<PathBuffers>(context, pathCapacity_, pixelCount_,
                                                 variant_.nextEventEstimation);
    std::vector<std::pair<uint32_t, const Buffer*>> bindings;
    sceneBuffers_->appendBindings(bindings);
    pathBuffers_->appendBindings(bindings);
    table_ = std::make_unique<DescriptorTable>(context, bindings);
    // Two intervals per depth for each of four passes, plus raygen and accumulate.
    timer_ = std::make_unique<TimestampTimer>(context, 4 * settings.maxDepth + 2);

    PassResources resources{context, compiler, defines_, *table_, pathBuffers_->counters,
                            *timer_};
    raygen_ = std::make_unique<RaygenPass>(resources);
    intersect_ = std::make_unique<IntersectPass>(resources);
    shade_ = std::make_unique<ShadePass>(resources);
    queue_ = std::make_unique<QueuePass>(resources);
    if (variant_.nextEventEstimation)
        shadow_ = std::make_unique<ShadowPass>(resources);
    accumulate_ = std::make_unique<AccumulatePass>(resources);

    camera_ = scene.camera;
    uploadParams();
    reset();
}

WavefrontRenderer::~WavefrontRenderer() = default;

void WavefrontRenderer::uploadParams() {
    const Camera& camera = camera_;
    RenderParams params{};
    params.cameraPosition = camera.position;
    params.tanHalfFovY = std::tan(0.5f * camera.yfov);
    params.cameraForward = camera.forward;
    params.aspect = float(settings_.width) / float(settings_.height);
    params.cameraUp = camera.up;
    params.seed = settings_.seed;
    params.cameraRight = cameraRight(camera);
    params.maxDepth = settings_.maxDepth;
    params.width = settings_.width;
    params.height = settings_.height;
    params.pixelCount = pixelCount_;
    params.rrDepth = settings_.rrDepth;
    params.emitterCount = static_cast<uint32_t>(scene_.lights.emitters.size());
    params.pathCapacity = pathCapacity_;
    params.sphereLightCount = scene_.lights.sphereLights;
    params.environmentEmitter = scene_.lights.environmentEmitter;
    params.sceneCenter = scene_.bounds.center;
    params.sceneRadius = scene_.bounds.radius;
    params.environmentWidth = scene_.environment.width;
    params.environmentHeight = scene_.environment.height;
    params.minThroughput = settings_.minThroughput;
    params.clampRadiance = settings_.clampRadiance;
    pathBuffers_->params.upload(&params, sizeof params);
}

void WavefrontRenderer::recordWave(VkCommandBuffer cmd, uint32_t sampleBase, uint32_t samples) {
    const uint32_t paths = pixelCount_ * samples;
    timer_->reset(cmd);
    QueueCounters initial{};
    initial.rayArgs = {groupsFor(paths), 1, 1, paths};
    vkCmdUpdateBuffer(cmd, pathBuffers_->counters.handle(), 0, sizeof initial, &initial);
    computeBarrier(cmd);

    raygen_->record(cmd, sampleBase, paths);
    for (uint32_t depth = 0; depth < settings_.maxDepth; ++depth) {
        intersect_->record(cmd, depth);
        shade_->record(cmd, depth, sampleBase);
        if (depth + 1 == settings_.maxDepth)
            break; // the last bounce queues nothing
        queue_->record(cmd);
        if (shadow_)
            shadow_->record(cmd, depth);
    }
    accumulate_->record(cmd, pixelCount_, samples);
}

void WavefrontRenderer::runWave(uint32_t samples) {
    const auto start = std::chrono::steady_clock::now();
    const uint32_t sampleBase = samplesDone_;
    context_.submitAndWait([&](VkCommandBuffer cmd) { recordWave(cmd, sampleBase, samples); });

    QueueCounters counters{};
    pathBuffers_->counters.download(&counters, sizeof counters);
    stats_.cameraRays += uint64_t(pixelCount_) * samples;
    stats_.paths += uint64_t(pixelCount_) * samples;
    stats_.extensionRays += counters.extensionRays;
    stats_.shadowRays += counters.shadowRays;
    stats_.nonFiniteSamples += counters.nonFiniteSamples;
    for (const auto& [pass, ms] : timer_->collect())
        stats_.passMilliseconds[pass] += ms;
    ++stats_.waves;
    samplesDone_ += samples;
    stats_.samplesPerPixel = samplesDone_;
    stats_.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

uint32_t WavefrontRenderer::renderSamples(uint32_t samples) {
    uint32_t done = 0;
    while (done < samples) {
        const uint32_t wave = std::min(samplesPerWave_, samples - done);
        runWave(wave);
        done += wave;
    }
    return samplesDone_;
}

void WavefrontRenderer::render(const std::function<void(const WaveProgress&)>& onWave) {
    while (samplesDone_ < settings_.samplesPerPixel) {
        runWave(std::min(samplesPerWave_, settings_.samplesPerPixel - samplesDone_));
        if (onWave)
            onWave({samplesDone_, settings_.samplesPerPixel, stats_.seconds});
    }
}

void WavefrontRenderer::reset() {
    std::vector<float> zeros(size_t(pixelCount_) * 4, 0.0f);
    pathBuffers_->film.upload(zeros);
    samplesDone_ = 0;
    stats_ = {};
}

void WavefrontRenderer::setCamera(const Camera& camera) {
    camera_ = camera;
    uploadParams();
    reset();
}

const Buffer& WavefrontRenderer::film() const { return pathBuffers_->film; }

std::vector<float> WavefrontRenderer::readImage() const {
    std::vector<float> film = pathBuffers_->film.download<float>();
    std::vector<float> rgb(size_t(pixelCount_) * 3);
    for (size_t i = 0; i < pixelCount_; ++i) {
        float count = film[4 * i + 3];
        for (int c = 0; c < 3; ++c)
            rgb[3 * i + c] = count > 0.0f ? film[4 * i + c] / count : 0.0f;
    }
    return rgb;
}

std::vector<std::pair<std::string, uint64_t>> WavefrontRenderer::memoryReport() const {
    std::vector<std::pair<std::string, uint64_t>> report;
    sceneBuffers_->appendMemoryReport(report);
    pathBuffers_->appendMemoryReport(report);
    return report;
}

} // namespace wf
