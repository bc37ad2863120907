// The frame loop of the wavefront path tracer. A render is a sequence of waves; each wave is
// one command buffer and one submit:
//   raygen; for depth in [0, maxDepth): intersect, shade, queue, shadow; accumulate
// with queue sizes passed from pass to pass on the GPU through indirect dispatch. A wave holds
// whole samples of every pixel, or one sample of a range of pixels when a whole sample would
// overrun the submit budget; its size follows the measured time of the previous waves.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/shader_compiler.h"
#include "render/shade_kinds.h"
#include "render/shader_variant.h"
#include "scene/scene.h"

namespace wf {

class Buffer;
class Context;
class TimestampTimer;
class DescriptorTable;
struct PreparedScene;
class SceneBuffers;
struct PathBuffers;
class RaygenPass;
class IntersectPass;
class ShadePass;
class QueuePass;
class ShadowPass;
class AccumulatePass;
class MegakernelPass;
namespace gpu_types {
struct PassConstants;
}

struct RenderSettings {
    uint32_t width = 512;
    uint32_t height = 512;
    uint32_t samplesPerPixel = 64;
    // --time-limit: render() stops before a sample pass that its pace so far says would end
    // past this many seconds of wall time (0: none). The first pass always runs.
    double timeLimitSeconds = 0.0;
    uint32_t maxDepth = 16;
    uint32_t rrDepth = 3;
    uint32_t seed = 0;
    uint32_t maxPathsPerWave = 1u << 20; // bounds buffer sizes and the length of one submit
    // Waves are sized so that one submit takes about this long or less, so that a long render
    // never trips a GPU watchdog (0: waves of maxPathsPerWave regardless of time).
    double submitBudgetSeconds = 0.25;
    // Trace whole paths in one dispatch (shaders/megakernel.comp) instead of the wavefront's
    // passes: the baseline `wavefront bench` compares against. Same samples, same image.
    bool megakernel = false;
    LightSampling lightSampling = LightSampling::Mis;
    LightSelection lightSelection = LightSelection::Auto; // --light-selection
    bool triangleSolidAngle = true; // --triangle-sampling solid-angle (else area)
    bool sphereSolidAngle = true;   // --sphere-sampling solid-angle (else area)
    float minThroughput = 0.0f;     // --min-throughput: biased termination, 0 = off
    float clampRadiance = 0.0f;     // --clamp: biased firefly clamp, 0 = off
    SamplerKind sampler = kDefaultSampler; // --sampler
    bool randomizeSamples = true;   // --no-randomize turns it off
    uint32_t sppOffset = 0;         // --spp-offset: index of the first sample per pixel
    // Finite-set samplers (stratified, multijitter, hammersley): samples in one set, 0 =
    // sppOffset + samplesPerPixel (--spp-total). Parts of one render must agree on it.
    uint32_t sampleSetSize = 0;
    // Store 16-byte path-state entries as two 64-bit words where the device has shaderInt64
    // (WF_PACKED_STORES, faster on lavapipe); off, the vec4 stores every device has. Same image.
    bool packedStores = true;
    // Keep the traversal stack in vectors where the tree's stack need fits in 8 entries, and
    // any-hit traversal's where it fits in 16 (WF_BVH_REGISTER_STACK, faster on lavapipe);
    // off, a private array. Same image.
    bool registerStack = true;
    // --aov: also accumulate the camera ray's first hit (albedo, shading normal, distance) and
    // the radiance squared per pixel (readAovs). The wavefront only; the image is unchanged.
    bool aov = false;
    // Textured scenes: filter textures by ray cones from their mip chains (WF_RAY_CONES,
    // ray_cones.glsl); off, every lookup reads level 0 bilinearly, as before the chains.
    bool textureLod = true;
    // Scenes with materials of two or more kinds (shade_kinds.h): bin each bounce's hits by
    // kind and shade each bin with a pass compiled for its kind. Auto splits only scenes
    // without the general kind, where it paid; On splits any scene of two kinds or more; Off
    // keeps one pass for every hit, as single-kind scenes always have. The same image up to
    // float rounding.
    ShadeSplit shadeSplit = ShadeSplit::Auto;
    // --target-error: waves cover lists of pixels (renderPixelList) and the film keeps each
    // pixel's radiance squared (readMoments); render() and the progressive calls are refused.
    bool pixelList = false;
    // Most bytes of the triangle or BVH table in one buffer (0: the device's limit); a test
    // sets it low to spread a small scene over pages as a large one spreads.
    uint64_t tablePageBytes = 0;
};

// The film and its second moment, per pixel: rgb sums, sample counts and rgb sums of squares.
struct FilmMoments {
    std::vector<float> sum;     // rgb per pixel
    std::vector<float> count;   // samples per pixel
    std::vector<float> squares; // rgb per pixel
};

// Per pixel, the mean over its samples of the camera ray's first hit (zero where it found no
// surface), and the variance of the pixel's radiance estimate (of its mean, per channel).
struct AovImages {
    std::vector<float> albedo;   // rgb per pixel
    std::vector<float> normal;   // xyz per pixel, the mean of unit normals (not renormalised)
    std::vector<float> depth;    // one per pixel: distance along the camera ray
    std::vector<float> variance; // rgb per pixel
};

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
};

// Adds `more`'s counts and times to `total`: sums, except the longest submit (the larger).
void addRenderStats(RenderStats& total, const RenderStats& more);

struct WaveProgress {
    uint32_t samplesDone;
    uint32_t samplesTotal;
    double secondsElapsed;
};

class WavefrontRenderer {
public:
    // `sharedScene`, when given, holds the scene's GPU tables from another renderer of the same
    // scene and variant (the viewer's preview, the bench's megakernel), which this one then
    // reads instead of uploading a second copy; InternalError if its variant differs.
    WavefrontRenderer(const Context& context, const PreparedScene& scene,
                      const RenderSettings& settings, const ShaderCompiler& compiler,
                      std::shared_ptr<const SceneBuffers> sharedScene = nullptr);
    ~WavefrontRenderer();

    // Renders the remaining samples of settings.samplesPerPixel, calling `onWave` after each
    // wave.
    // `stop`, when given and set (a signal handler may set it), ends the render before the
    // next sample pass.
    void render(const std::function<void(const WaveProgress&)>& onWave = {},
                const std::atomic<bool>* stop = nullptr);
    // Progressive use (the viewer): adds `samples` more samples per pixel, in as many waves as
    // needed, and returns the total so far.
    uint32_t renderSamples(uint32_t samples);
    // Finer than a sample, for a frame-time target: traces up to `paths` more pixels of the
    // sample in progress (pixels in order, one wave), completing it at the last pixel, and
    // returns the paths traced. Each pixel still receives its samples in order, so the film
    // matches a render of the same sample count once the sample is complete.
    uint32_t renderPixels(uint32_t paths);
    // Completes the sample in progress, if renderPixels left one.
    void finishSample();
    uint32_t pixelsOfNextSample() const { return pixelCursor_; }
    // Clears the film and the statistics; the next sample is sample sppOffset again.
    void reset();
    // Starts over like reset() with another seed, first sample index and (finite-set samplers)
    // set size, 0 = sppOffset + samplesPerPixel; pipelines and scene buffers are kept.
    void restart(uint32_t seed, uint32_t sppOffset, uint32_t sampleSetSize = 0);
    // Moves the camera (and resets).
    void setCamera(const Camera& camera);
    uint32_t samplesDone() const { return samplesDone_; }
    uint32_t pixelCount() const { return pixelCount_; }
    // The film: per pixel, RGB radiance sum and sample count (vec4), for display passes.
    const Buffer& film() const;

    // Linear radiance per pixel (mean of the samples), RGB, top row first.
    std::vector<float> readImage() const;
    AovImages readAovs() const; // needs RenderSettings.aov
    FilmMoments readMoments() const; // needs RenderSettings.aov or pixelList
    // Needs RenderSettings.pixelList: traces samples [firstSample, firstSample + samples) of
    // sppOffset on of the listed pixels only (image indices, each at most once), adding them
    // to the film. samplesDone() is left alone: the pixels' counts are in the film.
    void renderPixelList(const std::vector<uint32_t>& pixels, uint32_t firstSample,
                         uint32_t samples);
    const RenderStats& stats() const { return stats_; }
    const ShaderDefines& shaderDefines() const { return defines_; }
    const ShaderVariant& variant() const { return variant_; }
    // Starts the longest-submit record afresh (the bench, after its warm-up frames).
    void resetLongestSubmit() { stats_.longestSubmitSeconds = 0.0; }
    uint32_t pathCapacity() const { return pathCapacity_; } // most paths in one wave
    uint32_t pathsPerWave() const { return wavePaths_; }    // the current target
    std::vector<std::pair<std::string, uint64_t>> memoryReport() const;
    std::shared_ptr<const SceneBuffers> sceneBuffers() const { return sceneBuffers_; }

private:
    void uploadParams();
    uint32_t advance(uint32_t maxSamples);
    void recordWave(VkCommandBuffer cmd, const gpu_types::PassConstants& wave);
    // Samples [firstSample, firstSample + samples) of sppOffset on, of pixels [pixelBase,
    // pixelBase + pixels) of the image or (pixelList) of the list.
    void runWave(uint32_t pixelBase, uint32_t pixels, uint32_t firstSample, uint32_t samples);
    void adaptWaveSize(uint32_t paths, double seconds);
    uint32_t setSize() const; // of the finite-set samplers

    const Context& context_;
    RenderSettings settings_;
    uint32_t pixelCount_;
    uint32_t pathCapacity_;
    uint32_t wavePaths_;
    double secondsPerPath_ = 0.0; // measured, for sizing waves to the submit budget
    uint32_t pixelCursor_ = 0;    // pixels of sample samplesDone_ already traced
    ShaderVariant variant_;
    const PreparedScene& scene_;
    uint32_t samplesDone_ = 0;
    Camera camera_;
    ShaderDefines defines_;
    RenderStats stats_;
    std::shared_ptr<const SceneBuffers> sceneBuffers_;
    std::unique_ptr<PathBuffers> pathBuffers_;
    std::unique_ptr<DescriptorTable> table_;
    std::unique_ptr<TimestampTimer> timer_;
    std::unique_ptr<RaygenPass> raygen_;
    std::unique_ptr<IntersectPass> intersect_;
    std::vector<std::unique_ptr<ShadePass>> shades_; // one, or one per shade bin
    std::unique_ptr<QueuePass> queue_;
    std::unique_ptr<ShadowPass> shadow_;
    std::unique_ptr<AccumulatePass> accumulate_;
    std::unique_ptr<MegakernelPass> megakernel_;
    std::unique_ptr<Buffer> samplerTable_; // only for samplers that read it
};

// The variance of the mean of n samples with these sums (0 below two samples).
double varianceOfMean(double sum, double sumOfSquares, double n);

// The camera looking at the scene: the file's, with the image's aspect.
gpu_types::vec3 cameraRight(const Camera& camera);

} // namespace wf
