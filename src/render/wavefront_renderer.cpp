#include "render/wavefront_renderer.h"

#include <algorithm>
#include <chrono>

#include "errors.h"
#include "gpu/compute_program.h"
#include "gpu/context.h"
#include "render/guiding/path_guide.h"
#include "render/path_buffers.h"
#include "render/render_params.h"
#include "render/samplers/sampler_tables.h"
#include "render/gpu_scene/scene_buffers.h"
#include "render/wave_recorder.h"
#include "render/integrator_support.h"
#include "passes/workgroup.h"
#include "shaders/types/render_types.h"
#include "shaders/sampling/sampler_tables.h"

namespace wf {

using gpu_types::PassConstants;
using gpu_types::QueueCounters;
using gpu_types::RenderParams;

WavefrontRenderer::WavefrontRenderer(const Context& context, const PreparedScene& scene,
                                     const RenderSettings& settings,
                                     const ShaderCompiler& compiler,
                                     std::shared_ptr<const SceneBuffers> sharedScene)
    : context_(context), settings_(settings), scene_(&scene) {
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
    const uint32_t replicates = errorReplicatesFor(settings);
    if (replicates > 1 && pixels * (replicates - 1) > maxPixels)
        throw UsageError("--error-replicates " + std::to_string(replicates) + " at " +
                         std::to_string(pixels) + " pixels needs a replicate film over this "
                         "device's buffer limit (" + std::to_string(maxPixels) +
                         " entries of 16 bytes): take fewer replicates");
    pixelCount_ = static_cast<uint32_t>(pixels);
    const bool lightTracing = settings.integrator != Integrator::Path;
    if (lightTracing) {
        requireIntegratorSupport(settings, scene);
        if (pixels > maxPaths)
            throw UsageError(std::string("--integrator ") + integratorName(settings.integrator) +
                             " traces a whole sample of the image per wave: at most " +
                             std::to_string(maxPaths) + " pixels");
    }
    // Guided renders keep 4 training records of 64 bytes per path: at most 2^19 paths keep
    // them within a 128 MiB storage buffer.
    const uint64_t guideMaxPaths = settings.guiding ? uint64_t(1) << 19 : maxPaths;
    pathCapacity_ = static_cast<uint32_t>(std::max<uint64_t>(
        1, std::min({uint64_t(settings.maxPathsPerWave), maxPaths, guideMaxPaths,
                     pixels * settings.samplesPerPixel})));
    // Light tracing's splats land anywhere in the image, so each wave holds whole samples.
    if (lightTracing)
        pathCapacity_ = std::max(pathCapacity_, pixelCount_);
    // The first wave's size is a guess (a CPU device traces ~1e5-1e6 paths/s, a GPU far more);
    // later waves follow the measured time.
    const bool cpu = context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    wavePaths_ = settings.submitBudgetSeconds > 0.0 && cpu ? std::min(pathCapacity_, 1u << 12)
                                                           : pathCapacity_;
    if (lightTracing)
        wavePaths_ = std::max(wavePaths_, pixelCount_);
    variant_ = deviceVariant(context, scene, settings);
    defines_ = variant_.defines();
    if (sharedScene && sharedScene->defines() != defines_)
        throw InternalError("scene buffers shared between renderers of different variants");
    sceneBuffers_ = sharedScene ? std::move(sharedScene)
                                : std::make_shared<const SceneBuffers>(context, scene, variant_);
    const PathStateUse pathState = settings.megakernel ? PathStateUse::Megakernel
                                   : variant_.nextEventEstimation
                                       ? PathStateUse::WavefrontWithShadowRays
                                       : PathStateUse::Wavefront;
    if (bidirectional(variant_.integrator)) {
        // Every light vertex field in one storage buffer; the shadow queue likewise. Waves
        // shrink to fit (whole samples of the image still), down to one sample per pixel.
        const uint64_t perPath = 1 + PathBuffers::bdptLightVertices(variant_, settings.maxDepth);
        const uint64_t fitting =
            context.properties().limits.maxStorageBufferRange / (perPath * 16);
        if (fitting >= pixelCount_ && pathCapacity_ > fitting) {
            pathCapacity_ = static_cast<uint32_t>(fitting);
            wavePaths_ = std::min(wavePaths_, pathCapacity_);
        }
        if (uint64_t(pathCapacity_) * perPath * 16 > context.properties().limits.maxStorageBufferRange)
            throw UsageError(std::string("--integrator ") + integratorName(variant_.integrator) +
                             " keeps " + std::to_string(perPath - 1) +
                             " light vertices per pixel at --max-depth " +
                             std::to_string(settings.maxDepth) + ": at " +
                             std::to_string(pixels) + " pixels that is over this device's "
                             "buffer limit; take a smaller image or --max-depth");
    }
    pathBuffers_ = std::make_unique<PathBuffers>(context, pathCapacity_, pixelCount_, pathState,
                                                 variant_, settings.maxDepth);
    if (samplerReadsTable(settings.sampler))
        samplerTable_ = std::make_unique<Buffer>(makeSamplerTableBuffer(context, setSize()));
    if (settings.guiding) {
        const glm::vec3 radius(scene.bounds.radius);
        guide_ = std::make_unique<PathGuide>(context, scene.bounds.center - radius,
                                             scene.bounds.center + radius, pathCapacity_,
                                             settings.guideBsdfFraction,
                                             settings.guideMaxDepth,
                                             settings.guideLearnFraction,
                                             settings.guideParallax);
    }
    bindTables();
    waves_ = std::make_unique<WaveRecorder>(context, compiler, defines_, *table_,
                                            pathBuffers_->counters, variant_,
                                            settings.megakernel, settings.maxDepth,
                                            settings.timePasses,
                                            pathBuffers_->mergeLists ? &pathBuffers_->mergeLists
                                                                     : nullptr,
                                            PathBuffers::mergeCells(
                                                pathCapacity_, PathBuffers::bdptLightVertices(
                                                                   variant_, settings.maxDepth)));

    camera_ = scene.camera;
    uploadParams();
    reset();
}

WavefrontRenderer::~WavefrontRenderer() = default;

// Makes the descriptor table over the scene's tables and the renderer's own buffers, or points
// the one already made (and the pipelines over it) at them.
void WavefrontRenderer::bindTables() {
    DescriptorBindings bindings;
    sceneBuffers_->appendBindings(bindings);
    pathBuffers_->appendBindings(bindings);
    if (samplerTable_)
        bindings.push_back(
            {WF_BINDING_SAMPLER_TABLES, samplerTable_.get(), BufferAccess::Uint1Texels});
    if (guide_)
        guide_->appendBindings(bindings);
    AccelerationBinding acceleration;
    if (const AccelerationStructureSet* structures = sceneBuffers_->acceleration())
        acceleration = {WF_BINDING_TOP_LEVEL, structures->topLevel()};
    if (table_)
        table_->rewrite(context_, bindings, acceleration);
    else
        table_ = std::make_unique<DescriptorTable>(context_, bindings, acceleration);
}

bool WavefrontRenderer::setScene(const PreparedScene& scene) {
    if (guide_) // its tree spans the old scene's bounds
        return false;
    ShaderVariant variant = deviceVariant(context_, scene, settings_);
    if (variant.defines() != defines_)
        return false;
    // The new tables first: the old ones stay bound until the new ones are complete.
    auto buffers = std::make_shared<const SceneBuffers>(context_, scene, variant);
    std::swap(sceneBuffers_, buffers);
    try {
        bindTables();
    } catch (...) {
        std::swap(sceneBuffers_, buffers);
        throw;
    }
    variant_ = std::move(variant);
    scene_ = &scene;
    camera_ = scene.camera;
    uploadParams();
    reset();
    return true;
}

void WavefrontRenderer::uploadParams() {
    const RenderParams params =
        renderParams(*scene_, camera_, settings_, variant_, pixelCount_, pathCapacity_);
    pathBuffers_->params.upload(&params, sizeof params);
}

void WavefrontRenderer::runWave(uint32_t pixelBase, uint32_t pixels, uint32_t firstSample,
                                uint32_t samples) {
    const auto start = std::chrono::steady_clock::now();
    const uint32_t paths = pixels * samples;
    // Sample indices start at --spp-offset, so that partial renders merge.
    const PassConstants wave{
        0, settings_.sppOffset + firstSample, paths, samples, pixelBase, pixels, 0, 0};
    context_.submitAndWait([&](VkCommandBuffer cmd) { waves_->record(cmd, wave); });
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
    for (const auto& [pass, ms] : waves_->collectTimes())
        stats_.passMilliseconds[pass] += ms;
    ++stats_.waves;
    stats_.seconds += seconds;
    stats_.longestSubmitSeconds = std::max(stats_.longestSubmitSeconds, seconds);
    adaptWaveSize(paths, seconds);
}

std::vector<glm::uvec4> WavefrontRenderer::intersectRays(const std::vector<glm::vec4>& origins,
                                                         const std::vector<glm::vec4>& directions) {
    const size_t count = origins.size();
    if (count != directions.size() || count > pathCapacity_ || settings_.megakernel)
        throw InternalError("intersectRays: as many directions as origins, at most the path "
                            "capacity, and not in the megakernel");
    if (count == 0)
        return {};
    pathBuffers_->rayOrigin.upload(origins);
    pathBuffers_->rayDirection.upload(directions);
    std::vector<uint32_t> queue(count);
    for (size_t i = 0; i < count; ++i)
        queue[i] = static_cast<uint32_t>(i);
    pathBuffers_->rayQueues.upload(queue);
    context_.submitAndWait(
        [&](VkCommandBuffer cmd) { waves_->recordIntersect(cmd, uint32_t(count)); });
    waves_->collectTimes();
    std::vector<glm::uvec4> hits(count);
    pathBuffers_->hits.download(hits.data(), count * sizeof(glm::uvec4));
    return hits;
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
    const uint32_t floor = settings_.integrator != Integrator::Path
                               ? pixelCount_ // whole samples of the image per wave
                               : std::min(pathCapacity_, 1024u);
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
    if (settings_.integrator != Integrator::Path) { // whole samples only
        advance(1);
        return pixelCount_;
    }
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
    if (guide_) {
        renderGuided(settings_.samplesPerPixel, onWave, stop);
        return;
    }
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

void WavefrontRenderer::clearFilm() {
    std::vector<float> zeros(size_t(pixelCount_) * 4, 0.0f);
    pathBuffers_->film.upload(zeros);
    if (pathBuffers_->momentFilm)
        pathBuffers_->momentFilm.upload(zeros);
    if (pathBuffers_->replicateFilm)
        pathBuffers_->replicateFilm.upload(
            std::vector<float>(size_t(pixelCount_) * (pathBuffers_->replicates - 1) * 4, 0.0f));
    if (pathBuffers_->aovFilm)
        pathBuffers_->aovFilm.upload(std::vector<float>(size_t(pixelCount_) * 8, 0.0f));
}

void WavefrontRenderer::reset() {
    clearFilm();
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
    if (guide_)
        guide_->reset(); // each seed trains its own guide
    reset();
}

uint32_t WavefrontRenderer::setSize() const {
    const uint32_t total = settings_.sampleSetSize != 0
                               ? settings_.sampleSetSize
                               : settings_.sppOffset + settings_.samplesPerPixel;
    // Each replicate is a set of its own, of its share of the samples (rng.h).
    const uint32_t replicates = pathBuffers_ ? pathBuffers_->replicates : 1u;
    return (total + replicates - 1) / replicates;
}

void WavefrontRenderer::setCamera(const Camera& camera) {
    camera_ = camera;
    uploadParams();
    reset();
}

const Buffer& WavefrontRenderer::film() const { return pathBuffers_->film; }

std::vector<float> WavefrontRenderer::readImage() const {
    return readFilmImage(*pathBuffers_, pixelCount_);
}

FilmMoments WavefrontRenderer::readMoments() const {
    return readFilmMoments(*pathBuffers_, pixelCount_);
}

AovImages WavefrontRenderer::readAovs() const { return readFilmAovs(*pathBuffers_, pixelCount_); }

uint64_t WavefrontRenderer::lightSubpathBytes() const {
    return pathBuffers_->lightSubpathBytes(pathCapacity_);
}

std::vector<std::pair<std::string, uint64_t>> WavefrontRenderer::memoryReport() const {
    std::vector<std::pair<std::string, uint64_t>> report;
    sceneBuffers_->appendMemoryReport(report);
    if (samplerTable_)
        report.emplace_back(samplerTable_->name(), samplerTable_->size());
    pathBuffers_->appendMemoryReport(report);
    if (guide_)
        guide_->appendMemoryReport(report);
    return report;
}

} // namespace wf
