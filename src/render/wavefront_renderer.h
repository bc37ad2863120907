// The frame loop of the wavefront path tracer. A render is a sequence of waves; each wave is
// one command buffer and one submit:
//   raygen; for depth in [0, maxDepth): intersect, shade, queue, shadow; accumulate
// with queue sizes passed from pass to pass on the GPU through indirect dispatch.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/shader_compiler.h"
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

struct RenderSettings {
    uint32_t width = 512;
    uint32_t height = 512;
    uint32_t samplesPerPixel = 64;
    uint32_t maxDepth = 16;
    uint32_t rrDepth = 3;
    uint32_t seed = 0;
    uint32_t maxPathsPerWave = 1u << 20; // bounds buffer sizes and the length of one submit
    LightSampling lightSampling = LightSampling::Mis;
    bool triangleSolidAngle = true; // --triangle-sampling solid-angle (else area)
    bool sphereSolidAngle = true;   // --sphere-sampling solid-angle (else area)
    float minThroughput = 0.0f;     // --min-throughput: biased termination, 0 = off
    float clampRadiance = 0.0f;     // --clamp: biased firefly clamp, 0 = off
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
    std::map<std::string, double> passMilliseconds; // GPU time per pass, summed over waves
};

struct WaveProgress {
    uint32_t samplesDone;
    uint32_t samplesTotal;
    double secondsElapsed;
};

class WavefrontRenderer {
public:
    WavefrontRenderer(const Context& context, const PreparedScene& scene,
                      const RenderSettings& settings, const ShaderCompiler& compiler);
    ~WavefrontRenderer();

    // Renders the remaining samples of settings.samplesPerPixel, calling `onWave` after each
    // wave.
    void render(const std::function<void(const WaveProgress&)>& onWave = {});
    // Progressive use (the viewer): adds `samples` more samples per pixel, in as many waves as
    // needed, and returns the total so far.
    uint32_t renderSamples(uint32_t samples);
    // Clears the film and the statistics; the next sample is sample 0 again.
    void reset();
    // Moves the camera (and resets).
    void setCamera(const Camera& camera);
    uint32_t samplesDone() const { return samplesDone_; }
    // The film: per pixel, RGB radiance sum and sample count (vec4), for display passes.
    const Buffer& film() const;

    // Linear radiance per pixel (mean of the samples), RGB, top row first.
    std::vector<float> readImage() const;
    const RenderStats& stats() const { return stats_; }
    const ShaderDefines& shaderDefines() const { return defines_; }
    const ShaderVariant& variant() const { return variant_; }
    uint32_t samplesPerWave() const { return samplesPerWave_; }
    std::vector<std::pair<std::string, uint64_t>> memoryReport() const;

private:
    void uploadParams();
    void recordWave(VkCommandBuffer cmd, uint32_t sampleBase, uint32_t samples);
    void runWave(uint32_t samples);

    const Context& context_;
    RenderSettings settings_;
    uint32_t pixelCount_;
    uint32_t samplesPerWave_;
    uint32_t pathCapacity_;
    ShaderVariant variant_;
    const PreparedScene& scene_;
    uint32_t samplesDone_ = 0;
    Camera camera_;
    ShaderDefines defines_;
    RenderStats stats_;
    std::unique_ptr<SceneBuffers> sceneBuffers_;
    std::unique_ptr<PathBuffers> pathBuffers_;
    std::unique_ptr<DescriptorTable> table_;
    std::unique_ptr<TimestampTimer> timer_;
    std::unique_ptr<RaygenPass> raygen_;
    std::unique_ptr<IntersectPass> intersect_;
    std::unique_ptr<ShadePass> shade_;
    std::unique_ptr<QueuePass> queue_;
    std::unique_ptr<ShadowPass> shadow_;
    std::unique_ptr<AccumulatePass> accumulate_;
};

// The camera looking at the scene: the file's, with the image's aspect.
gpu_types::vec3 cameraRight(const Camera& camera);

} // namespace wf
