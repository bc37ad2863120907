// One wave as commands: the queue counters' reset, raygen, then for each depth intersect,
// shade (one pass per shade bin), queue and shadow, and accumulate; or the megakernel in place
// of the passes between raygen's and accumulate's places. Light tracing: raygen, intersect
// and shade at depth 0 (emitters seen directly), then light_raygen, queue and per light bounce
// intersect, light_shade, queue and light_splat, then accumulate. BDPT: the light subpaths
// first, then raygen, queue and per depth intersect, shade, queue and light_splat (NEE and
// the connections to the light vertices), then accumulate. Owns the passes and the timestamp
// queries that time them; the renderer owns the buffers and decides what each wave covers.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/shader_compiler.h"
#include "render/shader_variant.h"

namespace wf {

class Buffer;
class Context;
class DescriptorTable;
class TimestampTimer;
class RaygenPass;
class IntersectPass;
class ShadePass;
class QueuePass;
class ShadowPass;
class AccumulatePass;
class MegakernelPass;
class LightRaygenPass;
class LightShadePass;
class LightSplatPass;
struct ShaderVariant;
namespace gpu_types {
struct PassConstants;
}

class WaveRecorder {
public:
    // `counters` is the queue counter buffer every pass reads its indirect arguments from.
    // `mergeLists`: VCM's hash grid (its first `mergeCells` words are cleared per wave), or
    // null.
    WaveRecorder(const Context& context, const ShaderCompiler& compiler,
                 const ShaderDefines& defines, const DescriptorTable& table,
                 const Buffer& counters, const ShaderVariant& variant, bool megakernel,
                 uint32_t maxDepth, bool timePasses, const Buffer* mergeLists = nullptr,
                 uint32_t mergeCells = 0);
    ~WaveRecorder();

    void record(VkCommandBuffer cmd, const gpu_types::PassConstants& wave) const;
    // The intersect pass alone over rays 0 .. count-1 already in the ray buffers (ray queue 0
    // holding 0 .. count-1): what the tests that compare traversals read back.
    void recordIntersect(VkCommandBuffer cmd, uint32_t count) const;
    // GPU milliseconds per pass of the last wave recorded, after its fence.
    std::map<std::string, double> collectTimes();

private:
    const Buffer& counters_;
    const Buffer* mergeLists_;
    uint32_t mergeCells_;
    uint32_t maxDepth_;
    std::unique_ptr<TimestampTimer> timer_;
    std::unique_ptr<RaygenPass> raygen_;
    std::unique_ptr<IntersectPass> intersect_;
    std::vector<std::unique_ptr<ShadePass>> shades_; // one, or one per shade bin
    std::unique_ptr<QueuePass> queue_;
    std::unique_ptr<ShadowPass> shadow_;
    std::unique_ptr<AccumulatePass> accumulate_;
    std::unique_ptr<MegakernelPass> megakernel_;
    Integrator integrator_ = Integrator::Path;
    std::unique_ptr<LightRaygenPass> lightRaygen_; // light tracing in scenes with emitters
    std::unique_ptr<LightShadePass> lightShade_;
    std::unique_ptr<LightSplatPass> lightSplat_;

    void recordLightSubpaths(VkCommandBuffer cmd, const gpu_types::PassConstants& wave) const;
};

} // namespace wf
