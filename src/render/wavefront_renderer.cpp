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
#include "passes/megakernel_pass.h"
#include "passes/queue_pass.h"
#include "passes/raygen_pass.h"
#include "passes/shade_pass.h"
#include "passes/shadow_pass.h"
#include "render/path_buffers.h"
#include "render/samplers/sampler_tables.h"
#include "render/gpu_scene/scene_buffers.h"
#include "render/workgroup.h"
#include "shaders/types/render_types.h"
#include "shaders/sampling/sampler_tables.h"

namespace wf {

using gpu_types::DispatchArgs;
using gpu_types::PassConstants;
using gpu_types::QueueCounters;
using gpu_types::RenderParams;

double varianceOfMean(double sum, double sumOfSquares, double n) {
    // (sum x^2 - (sum x)^2 / n) / (n (n - 1)): the sample variance over n.
    return n > 1.0 ? std::max(0.0, sumOfSquares - sum * sum / n) / (n * (n - 1.0)) : 0.0;
}

void addRenderStats(RenderStats& total, const RenderStats& more) {
    total.samplesPerPixel += more.samplesPerPixel;
    total.seconds += more.seconds;
    total.paths += more.paths;
    total.cameraRays += more.cameraRays;
    total.extensionRays += more.extensionRays;
    total.shadowRays += more.shadowRays;
    total.nonFiniteSamples += more.nonFiniteSamples;
    total.waves += more.waves;
    total.longestSubmitSeconds = std::max(total.longestSubmitSeconds, more.longestSubmitSeconds);
    for (const auto& [pass, ms] : more.passMilliseconds)
        total.passMilliseconds[pass] += ms;
    total.depthRays.resize(std::max(total.depthRays.size(), more.depthRays.size()), 0);
    total.depthShadowRays.resize(
        std::max(total.depthShadowRays.size(), more.depthShadowRays.size()), 0);
    for (size_t d = 0; d < more.depthRays.size(); ++d)
        total.depthRays[d] += more.depthRays[d];
    for (size_t d = 0; d < more.depthShadowRays.size(); ++d)
        total.depthShadowRays[d] += more.depthShadowRays[d];
}

gpu_types::vec3 cameraRight(const Camera& camera) {
    return glm::normalize(glm::cross(camera.forward, camera.up));
}

WavefrontRenderer::WavefrontRenderer(const Context& context, const PreparedScene& scene,
                                     const RenderSettings& settings,
                                     const ShaderCompiler& compiler,
                                     std::shared_ptr<const SceneBuffers> sharedScene)
    : context_(context), settings_(settings), scene_(scene) {
    if (settings.width == 0 || settings.height == 0 || settings.samplesPerPixel == 0 ||
        settings.maxDepth == 0)
        throw UsageError("width, height, spp and max depth must all be at least 1");
    const uint64_t pixels = uint64_t(settings.width) * settings.height;
    const uint64_t maxPaths = uint64_t(kMaxGroupsX) * kWorkgroupSize;
    // Waves may cover part of the image, so only the film (16 bytes a pixel) bounds its size.
    const uint64_t maxPixels = context.properties().limits.maxStorageBufferRange / 16;
    if (pixels > maxPixels)
        throw UsageError("image of " + std::to_string(pixels) + " pixels is over this device's "
                         "limit of " + std::to_string(maxPixels) + " pixels");
    pixelCount_ = static_cast<uint32_t>(pixels);
    pathCapacity_ = static_cast<uint32_t>(std::max<uint64_t>(
        1, std::min({uint64_t(settings.maxPathsPerWave), maxPaths,
                     pixels * settings.samplesPerPixel})));
    // The first wave's size is a guess (a CPU device traces ~1e5-1e6 paths/s, a GPU far more);
    // later waves follow the measured time.
    const bool cpu = context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    wavePaths_ = settings.submitBudgetSeconds > 0.0 && cpu ? std::min(pathCapacity_, 1u << 12)
                                                           : pathCapacity_;
    variant_ = chooseVariant(scene, settings);
    variant_.surface = surfaceFeatures(scene.surface, scene.materials, texelPageBytes(context));
    variant_.rayCones = variant_.surface.textures && settings.textureLod;
    variant_.packedStores = settings.packedStores && context.shaderInt64();
    const VkPhysicalDeviceLimits& limits = context.properties().limits;
    const uint64_t pageBytes =
        settings.tablePageBytes > 0
            ? settings.tablePageBytes
            : std::min<uint64_t>(limits.maxStorageBufferRange,
                                 uint64_t(limits.maxTexelBufferElements) * 16);
    variant_.trianglePages =
        tablePaging(scene.triangles.size(), sizeof(Triangle), pageBytes, "triangles");
    variant_.bvhPages =
        tablePaging(scene.bvhPairs.size(), sizeof(BvhPair), pageBytes, "BVH nodes");
    variant_.instancePages =
        tablePaging(scene.instances.size(), sizeof(Instance), pageBytes, "instances");
    defines_ = variant_.defines();
    if (sharedScene && sharedScene->defines() != defines_)
        throw InternalError("scene buffers shared between renderers of different variants");
    sceneBuffers_ = sharedScene ? std::move(sharedScene)
                                : std::make_shared<const SceneBuffers>(context, scene, variant_);
    const PathStateUse pathState = settings.megakernel ? PathStateUse::Megakernel
                                   : variant_.nextEventEstimation
                                       ? PathStateUse::WavefrontWithShadowRays
                                       : PathStateUse::Wavefront;
    pathBuffers_ = std::make_unique<PathBuffers>(context, pathCapacity_, pixelCount_, pathState,
                                                 variant_);
    DescriptorBindings bindings;
    sceneBuffers_->appendBindings(bindings);
    pathBuffers_->appendBindings(bindings);
    if (samplerReadsTable(settings.sampler)) {
        samplerTable_ = std::make_unique<Buffer>(makeSamplerTableBuffer(context, setSize()));
        bindings.push_back(
            {WF_BINDING_SAMPLER_TABLES, samplerTable_.get(), BufferAccess::Uint1Texels});
    }
    table_ = std::make_unique<DescriptorTable>(context, bindings);
    // Four passes per depth (with shade bins, a shade pass per bin), plus raygen and accumulate.
    const uint32_t passesPerDepth = 3 + std::max(variant_.shadeBins(), 1u);
    timer_ = std::make_unique<TimestampTimer>(context, passesPerDepth * settings.maxDepth + 2);

    PassResources resources{context, compiler, defines_, *table_, pathBuffers_->counters,
                            *timer_};
    if (settings.megakernel) {
        megakernel_ = std::make_unique<MegakernelPass>(resources);
    } else {
        raygen_ = std::make_unique<RaygenPass>(resources);
        intersect_ = std::make_unique<IntersectPass>(resources);
        if (variant_.shadeKinds == 0) {
            shades_.push_back(std::make_unique<ShadePass>(resources));
        } else {
            for (uint32_t k = 0; k < kShadeKinds; ++k)
                if (variant_.shadeKinds & (1u << k))
                    shades_.push_back(std::make_unique<ShadePass>(
                        resources, static_cast<uint32_t>(shades_.size()), ShadeKind(k)));
        }
        queue_ = std::make_unique<QueuePass>(resources);
        if (variant_.nextEventEstimation)
            shadow_ = std::make_unique<ShadowPass>(resources);
    }
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
    params.emitterCount = static_cast<uint32_t>(scene_.lights.emitters.size()) +
                          (variant_.lightTree() ? 1u : 0u); // the tree's own slot
    params.pathCapacity = pathCapacity_;
    params.sphereLightCount = scene_.lights.sphereLights;
    params.environmentEmitter = scene_.lights.environmentEmitter;
    params.sceneCenter = scene_.bounds.center;
    params.sceneRadius = scene_.bounds.radius;
    params.environmentWidth = scene_.environment.width;
    params.environmentHeight = scene_.environment.height;
    params.minThroughput = settings_.minThroughput;
    params.clampRadiance = settings_.clampRadiance;
    params.lensRadius = 0.5f * camera.aperture;
    params.focusDistance = camera.focusDistance;
    pathBuffers_->params.upload(&params, sizeof params);
}

void WavefrontRenderer::recordWave(VkCommandBuffer cmd, const PassConstants& wave) {
    timer_->reset(cmd);
    QueueCounters initial{};
    initial.rayArgs = {groupsFor(wave.pathCount), 1, 1, wave.pathCount};
    initial.depthRays[0] = wave.pathCount;
    for (DispatchArgs& args : initial.kindArgs)
        args = {0, 1, 1, 0}; // intersect raises groupsX
    vkCmdUpdateBuffer(cmd, pathBuffers_->counters.handle(), 0, sizeof initial, &initial);
    computeBarrier(cmd);

    if (megakernel_) {
        megakernel_->record(cmd, wave);
    } else {
        raygen_->record(cmd, wave);
        for (uint32_t depth = 0; depth < settings_.maxDepth; ++depth) {
            intersect_->record(cmd, depth);
            for (const auto& shade : shades_)
                shade->record(cmd, depth, wave);
            if (depth + 1 == settings_.maxDepth)
                break; // the last bounce queues nothing
            queue_->record(cmd, depth);
            if (shadow_)
                shadow_->record(cmd, depth);
        }
    }
    accumulate_->record(cmd, wave);
    timer_->finish(cmd);
}

void WavefrontRenderer::runWave(uint32_t pixelBase, uint32_t pixels, uint32_t firstSample,
                                uint32_t samples) {
    const auto start = std::chrono::steady_clock::now();
    const uint32_t paths = pixels * samples;
    // Sample indices start at --spp-offset, so that partial renders merge.
    const PassConstants wave{
        0, settings_.sppOffset + firstSample, paths, samples, pixelBase, pixels, 0, 0};
    context_.submitAndWait([&](VkCommandBuffer cmd) { recordWave(cmd, wave); });
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    QueueCounters counters{};
    pathBuffers_->counters.download(&counters, sizeof counters);
    stats_.cameraRays += paths;
    stats_.paths += paths;
    stats_.extensionRays += counters.extensionRays;
    stats_.shadowRays += counters.shadowRays;
    stats_.nonFiniteSamples += counters.nonFiniteSamples;
    for (uint32_t d = 0; d < WF_TRACKED_DEPTHS; ++d) {
        stats_.depthRays[d] += counters.depthRays[d];
        stats_.depthShadowRays[d] += counters.depthShadowRays[d];
    }
    for (const auto& [pass, ms] : timer_->collect())
        stats_.passMilliseconds[pass] += ms;
    ++stats_.waves;
    stats_.seconds += seconds;
    stats_.longestSubmitSeconds = std::max(stats_.longestSubmitSeconds, seconds);
    adaptWaveSize(paths, seconds);
}

void WavefrontRenderer::adaptWaveSize(uint32_t paths, double seconds) {
    // Only full-size waves say how long a full-size wave takes: the image's last pixel range
    // may be tiny, and fixed costs would dominate it.
    if (settings_.submitBudgetSeconds <= 0.0 || 2ull * paths < wavePaths_ || seconds <= 0.0)
        return;
    // The cost per path follows a slowdown at once and a speed-up slowly, as waves over other
    // pixels (or a busier machine) may cost more; waves aim at 60% of the budget and grow at
    // most 4x at a time.
    secondsPerPath_ = std::max(seconds / paths, 0.75 * secondsPerPath_);
    const double wanted = 0.6 * settings_.submitBudgetSeconds / secondsPerPath_;
    const double grown = std::min(wanted, 4.0 * wavePaths_);
    const uint32_t floor = std::min(pathCapacity_, 1024u);
    wavePaths_ = static_cast<uint32_t>(std::clamp(grown, double(floor), double(pathCapacity_)));
}

// One step: several whole samples of every pixel in one wave, or, when a whole sample is over
// the wave size, one sample in pixel ranges. Either way each pixel receives its samples in
// order, which is what makes the film independent of the wave sizes.
uint32_t WavefrontRenderer::advance(uint32_t maxSamples) {
    if (variant_.adaptive)
        throw InternalError("a renderer of pixel lists traces through renderPixelList only");
    if (pixelCursor_ > 0) { // a sample left in progress by renderPixels comes first
        finishSample();
        return 1;
    }
    uint32_t samples = 1;
    if (wavePaths_ >= pixelCount_) {
        samples = std::min(wavePaths_ / pixelCount_, maxSamples);
        runWave(0, pixelCount_, samplesDone_, samples);
    } else {
        for (uint32_t base = 0; base < pixelCount_;) {
            const uint32_t pixels = std::min(wavePaths_, pixelCount_ - base);
            runWave(base, pixels, samplesDone_, 1);
            base += pixels;
        }
    }
    samplesDone_ += samples;
    stats_.samplesPerPixel = samplesDone_;
    return samples;
}

uint32_t WavefrontRenderer::renderPixels(uint32_t paths) {
    if (variant_.adaptive)
        throw InternalError("a renderer of pixel lists traces through renderPixelList only");
    const uint32_t left = std::min(pathCapacity_, pixelCount_ - pixelCursor_);
    const uint32_t pixels = std::clamp(paths, 1u, left);
    runWave(pixelCursor_, pixels, samplesDone_, 1);
    pixelCursor_ += pixels;
    if (pixelCursor_ == pixelCount_) {
        pixelCursor_ = 0;
        ++samplesDone_;
        stats_.samplesPerPixel = samplesDone_;
    }
    return pixels;
}

void WavefrontRenderer::finishSample() {
    while (pixelCursor_ > 0)
        renderPixels(wavePaths_);
}

uint32_t WavefrontRenderer::renderSamples(uint32_t samples) {
    for (uint32_t done = 0; done < samples;)
        done += advance(samples - done);
    return samplesDone_;
}

void WavefrontRenderer::render(const std::function<void(const WaveProgress&)>& onWave,
                               const std::atomic<bool>* stop) {
    const auto start = std::chrono::steady_clock::now();
    const uint32_t first = samplesDone_;
    while (samplesDone_ < settings_.samplesPerPixel && !(stop && stop->load())) {
        uint32_t samples = settings_.samplesPerPixel - samplesDone_;
        if (settings_.timeLimitSeconds > 0.0 && samplesDone_ > first) {
            // Whole passes only: as many as the pace so far says still fit.
            const double elapsed =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const double fit = (settings_.timeLimitSeconds - elapsed) /
                               (elapsed / double(samplesDone_ - first));
            if (fit < 1.0)
                break;
            samples = std::min(samples, static_cast<uint32_t>(std::min(fit, 1e9)));
        }
        advance(samples);
        if (onWave)
            onWave({samplesDone_, settings_.samplesPerPixel, stats_.seconds});
    }
}

void WavefrontRenderer::renderPixelList(const std::vector<uint32_t>& pixels,
                                        uint32_t firstSample, uint32_t samples) {
    if (!pathBuffers_->activePixels)
        throw InternalError("renderPixelList: the renderer was made without pixelList");
    if (pixels.size() > pixelCount_)
        throw InternalError("renderPixelList: more pixels than the image has");
    if (pixels.empty() || samples == 0)
        return;
    pathBuffers_->activePixels.upload(pixels);
    const uint32_t count = static_cast<uint32_t>(pixels.size());
    // As advance(): whole samples of every listed pixel per wave, or one sample in ranges.
    for (uint32_t done = 0; done < samples;) {
        if (wavePaths_ >= count) {
            const uint32_t n = std::min(wavePaths_ / count, samples - done);
            runWave(0, count, firstSample + done, n);
            done += n;
            continue;
        }
        for (uint32_t base = 0; base < count;) {
            const uint32_t n = std::min(wavePaths_, count - base);
            runWave(base, n, firstSample + done, 1);
            base += n;
        }
        ++done;
    }
}

void WavefrontRenderer::reset() {
    std::vector<float> zeros(size_t(pixelCount_) * 4, 0.0f);
    pathBuffers_->film.upload(zeros);
    if (pathBuffers_->momentFilm)
        pathBuffers_->momentFilm.upload(zeros);
    if (pathBuffers_->aovFilm)
        pathBuffers_->aovFilm.upload(std::vector<float>(size_t(pixelCount_) * 8, 0.0f));
    samplesDone_ = 0;
    pixelCursor_ = 0;
    stats_ = {};
    stats_.depthRays.assign(WF_TRACKED_DEPTHS, 0);
    stats_.depthShadowRays.assign(WF_TRACKED_DEPTHS, 0);
}

void WavefrontRenderer::restart(uint32_t seed, uint32_t sppOffset, uint32_t sampleSetSize) {
    settings_.seed = seed;
    settings_.sppOffset = sppOffset;
    settings_.sampleSetSize = sampleSetSize;
    uploadParams();
    if (samplerTable_)
        setSamplerSetSize(*samplerTable_, setSize());
    reset();
}

uint32_t WavefrontRenderer::setSize() const {
    return settings_.sampleSetSize != 0 ? settings_.sampleSetSize
                                        : settings_.sppOffset + settings_.samplesPerPixel;
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

FilmMoments WavefrontRenderer::readMoments() const {
    if (!pathBuffers_->momentFilm)
        throw InternalError("readMoments: the renderer keeps no second moment");
    const std::vector<float> film = pathBuffers_->film.download<float>();
    const std::vector<float> squares = pathBuffers_->momentFilm.download<float>();
    FilmMoments moments;
    moments.sum.resize(size_t(pixelCount_) * 3);
    moments.count.resize(pixelCount_);
    moments.squares.resize(size_t(pixelCount_) * 3);
    for (size_t i = 0; i < pixelCount_; ++i) {
        for (int c = 0; c < 3; ++c) {
            moments.sum[3 * i + c] = film[4 * i + c];
            moments.squares[3 * i + c] = squares[4 * i + c];
        }
        moments.count[i] = film[4 * i + 3];
    }
    return moments;
}

AovImages WavefrontRenderer::readAovs() const {
    if (!pathBuffers_->aovFilm)
        throw InternalError("readAovs: the renderer was made without RenderSettings.aov");
    const FilmMoments moments = readMoments();
    const std::vector<float> aov = pathBuffers_->aovFilm.download<float>();
    AovImages images;
    images.albedo.resize(size_t(pixelCount_) * 3);
    images.normal.resize(size_t(pixelCount_) * 3);
    images.depth.resize(pixelCount_);
    images.variance.resize(size_t(pixelCount_) * 3);
    for (size_t i = 0; i < pixelCount_; ++i) {
        const double n = moments.count[i];
        if (!(n > 0.0))
            continue;
        const float* sums = &aov[8 * i];
        for (int c = 0; c < 3; ++c) {
            images.albedo[3 * i + c] = float(sums[c] / n);
            images.normal[3 * i + c] = float(sums[4 + c] / n);
            images.variance[3 * i + c] = float(
                varianceOfMean(moments.sum[3 * i + c], moments.squares[3 * i + c], n));
        }
        images.depth[i] = float(sums[3] / n);
    }
    return images;
}

std::vector<std::pair<std::string, uint64_t>> WavefrontRenderer::memoryReport() const {
    std::vector<std::pair<std::string, uint64_t>> report;
    sceneBuffers_->appendMemoryReport(report);
    if (samplerTable_)
        report.emplace_back(samplerTable_->name(), samplerTable_->size());
    pathBuffers_->appendMemoryReport(report);
    return report;
}

} // namespace wf
