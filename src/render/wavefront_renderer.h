// The frame loop of the wavefront path tracer. A render is a sequence of waves; each wave is
// one command buffer and one submit:
//   raygen; for depth in [0, maxDepth): intersect, shade, queue, shadow; accumulate
// with queue sizes passed from pass to pass on the GPU through indirect dispatch. A wave holds
// whole samples of every pixel, or one sample of a range of pixels when a whole sample would
// overrun the submit budget; its size follows the measured time of the previous waves.
// What a wave records is wave_recorder.h's; reading the film back, film_readback.h's; the
// variant and parameter block, render_params.h's; the guided renders' iterations are defined
// in guided_render.cpp.
#pragma once
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/shader_compiler.h"
#include "render/film_readback.h"
#include "render/render_settings.h"
#include "render/render_stats.h"
#include "render/shader_variant.h"
#include "scene/scene.h"

namespace wf {

class Buffer;
class Context;
class DescriptorTable;
class WaveRecorder;
class PathGuide;
struct PreparedScene;
class SceneBuffers;
struct PathBuffers;

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
    // Guided renderers only: trains afresh over a budget of `budget` samples per pixel (at
    // most settings.samplesPerPixel; render() is this with that) and leaves the image in the
    // film. Call restart() first for a render from scratch (converge: one per checkpoint).
    void renderGuided(uint32_t budget,
                      const std::function<void(const WaveProgress&)>& onWave = {},
                      const std::atomic<bool>* stop = nullptr);
    // Guided renderers: ends training iteration `iteration` (0-based) of `spp` samples per
    // pixel that took `seconds`: the guide rebuilds from its splats (host time counted in the
    // stats). Returns the iteration's statistics, also appended to stats().guideIterations.
    const RenderStats::GuideIterationStats& endGuideIteration(uint32_t iteration, uint32_t spp,
                                                              double seconds);
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
    // Zeroes the image but keeps the sample indices counting (the viewer's guide restarts its
    // image after each training iteration with samples the guide never saw).
    void clearImage() { clearFilm(); }
    // Clears the film and the statistics; the next sample is sample sppOffset again.
    void reset();
    // Starts over like reset() with another seed, first sample index and (finite-set samplers)
    // set size, 0 = sppOffset + samplesPerPixel; pipelines and scene buffers are kept.
    void restart(uint32_t seed, uint32_t sppOffset, uint32_t sampleSetSize = 0);
    // Moves the camera (and resets).
    void setCamera(const Camera& camera);
    // Another frame of the same scene (render --frames, the viewer's playback): when `scene`
    // needs the same shader variant, its tables replace this renderer's (rebinding the one
    // descriptor set, so the pipelines stay), the camera becomes its camera and the film is
    // reset; returns false, changing nothing, where the variant differs or the renderer guides
    // (the caller then makes a new renderer). `scene` must outlive the renderer or the next
    // setScene, as the constructor's.
    bool setScene(const PreparedScene& scene);
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
    // The closest hits of the given rays (xyz of each; at most pathCapacity()), as the
    // intersect pass writes them (shaders/intersect.comp), by this renderer's traversal: the
    // tests that hold the two traversals to the same hits. Not for the megakernel.
    std::vector<glm::uvec4> intersectRays(const std::vector<glm::vec4>& origins,
                                          const std::vector<glm::vec4>& directions);
    const RenderStats& stats() const { return stats_; }
    const ShaderDefines& shaderDefines() const { return defines_; }
    const ShaderVariant& variant() const { return variant_; }
    // Starts the longest-submit record afresh (the bench, after its warm-up frames).
    void resetLongestSubmit() { stats_.longestSubmitSeconds = 0.0; }
    uint32_t pathCapacity() const { return pathCapacity_; } // most paths in one wave
    PathGuide* guide() { return guide_.get(); }              // --guiding only, else null
    uint32_t pathsPerWave() const { return wavePaths_; }    // the current target
    std::vector<std::pair<std::string, uint64_t>> memoryReport() const;
    uint64_t lightSubpathBytes() const; // PathBuffers::lightSubpathBytes; 0 for path tracing
    std::shared_ptr<const SceneBuffers> sceneBuffers() const { return sceneBuffers_; }
    // What intersect and shadow trace with, and the driver's structures where that is rt.
    Traversal traversal() const {
        return variant_.rayTracing ? Traversal::RayTracing : Traversal::Bvh;
    }

private:
    void countGuideHostTime(std::chrono::steady_clock::time_point start);
    void bindTables();
    void uploadParams();
    void clearFilm();
    uint32_t advance(uint32_t maxSamples);
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
    const PreparedScene* scene_; // setScene moves it on
    uint32_t samplesDone_ = 0;
    Camera camera_;
    ShaderDefines defines_;
    RenderStats stats_;
    std::shared_ptr<const SceneBuffers> sceneBuffers_;
    std::unique_ptr<PathBuffers> pathBuffers_;
    std::unique_ptr<DescriptorTable> table_;
    std::unique_ptr<WaveRecorder> waves_; // the passes, recorded wave by wave
    std::unique_ptr<Buffer> samplerTable_; // only for samplers that read it
    std::unique_ptr<PathGuide> guide_;     // --guiding only
};

} // namespace wf
