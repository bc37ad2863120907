#include "render/wave_recorder.h"

#include <algorithm>

#include "errors.h"
#include "gpu/buffer.h"
#include "gpu/compute_program.h"
#include "gpu/timestamp_timer.h"
#include "passes/accumulate_pass.h"
#include "passes/intersect_pass.h"
#include "passes/light_raygen_pass.h"
#include "passes/light_shade_pass.h"
#include "passes/light_splat_pass.h"
#include "passes/megakernel_pass.h"
#include "passes/queue_pass.h"
#include "passes/raygen_pass.h"
#include "passes/shade_pass.h"
#include "passes/shadow_pass.h"
#include "render/shader_variant.h"
#include "passes/workgroup.h"
#include "shaders/types/render_types.h"

namespace wf {

using gpu_types::DispatchArgs;
using gpu_types::PassConstants;
using gpu_types::QueueCounters;

WaveRecorder::WaveRecorder(const Context& context, const ShaderCompiler& compiler,
                           const ShaderDefines& defines, const DescriptorTable& table,
                           const Buffer& counters, const ShaderVariant& variant,
                           bool megakernel, uint32_t maxDepth, bool timePasses,
                           const Buffer* mergeLists, uint32_t mergeCells)
    : counters_(counters), mergeLists_(mergeLists), mergeCells_(mergeCells),
      maxDepth_(maxDepth) {
    // Four passes per depth (with shade bins, a shade pass per bin), plus raygen and accumulate.
    // Light tracing: four more per light bounce (intersect, light_shade, queue, light_splat)
    // and two to start its subpaths.
    const uint32_t passesPerDepth = 3 + std::max(variant.shadeBins(), 1u) +
                                    (variant.lightSubpaths() ? 4 : 0);
    timer_ = std::make_unique<TimestampTimer>(context, passesPerDepth * maxDepth + 4, timePasses);
    integrator_ = variant.integrator;

    PassResources resources{context, compiler, defines, table, counters, *timer_,
                            variant.rayTracing && !megakernel};
    if (megakernel) {
        megakernel_ = std::make_unique<MegakernelPass>(resources);
    } else {
        raygen_ = std::make_unique<RaygenPass>(resources);
        intersect_ = std::make_unique<IntersectPass>(resources);
        if (variant.shadeKinds == 0) {
            shades_.push_back(std::make_unique<ShadePass>(resources));
        } else {
            for (uint32_t k = 0; k < kShadeKinds; ++k)
                if (variant.shadeKinds & (1u << k))
                    shades_.push_back(std::make_unique<ShadePass>(
                        resources, static_cast<uint32_t>(shades_.size()), ShadeKind(k)));
        }
        queue_ = std::make_unique<QueuePass>(resources);
        if (variant.nextEventEstimation && integrator_ == Integrator::Path)
            shadow_ = std::make_unique<ShadowPass>(resources);
        if (variant.lightSubpaths()) {
            lightRaygen_ = std::make_unique<LightRaygenPass>(resources);
            lightShade_ = std::make_unique<LightShadePass>(resources);
            lightSplat_ = std::make_unique<LightSplatPass>(resources);
        }
    }
    accumulate_ = std::make_unique<AccumulatePass>(resources);
}

WaveRecorder::~WaveRecorder() = default;

void WaveRecorder::record(VkCommandBuffer cmd, const PassConstants& wave) const {
    timer_->reset(cmd);
    QueueCounters initial{};
    initial.rayArgs = {groupsFor(wave.pathCount), 1, 1, wave.pathCount};
    initial.rayTrace = {wave.pathCount, 1, 1, 0};
    initial.depthRays[0] = wave.pathCount;
    for (DispatchArgs& args : initial.kindArgs)
        args = {0, 1, 1, 0}; // intersect raises groupsX
    vkCmdUpdateBuffer(cmd, counters_.handle(), 0, sizeof initial, &initial);
    if (mergeLists_) // VCM: the grid's cells start empty (WF_VCM_END) each wave
        vkCmdFillBuffer(cmd, mergeLists_->handle(), 0, uint64_t(mergeCells_) * 4, ~0u);
    computeBarrier(cmd);

    if (megakernel_) {
        megakernel_->record(cmd, wave);
    } else {
        // BDPT's camera vertices connect to (VCM's also merge with) the light vertices its
        // light subpaths keep.
        if (lightRaygen_ && bidirectional(integrator_))
            recordLightSubpaths(cmd, wave);
        raygen_->record(cmd, wave);
        if (bidirectional(integrator_))
            queue_->record(cmd, ~0u); // raygen's count: the light passes left the arguments
        // Light tracing's camera rays find the emitters they see and end.
        const uint32_t cameraDepth = integrator_ == Integrator::Light ? 1 : maxDepth_;
        for (uint32_t depth = 0; depth < cameraDepth; ++depth) {
            intersect_->record(cmd, depth);
            for (const auto& shade : shades_)
                shade->record(cmd, depth, wave);
            if (depth + 1 == cameraDepth)
                break; // the last bounce queues nothing
            queue_->record(cmd, depth);
            if (shadow_)
                shadow_->record(cmd, depth);
            if (bidirectional(integrator_) && lightSplat_)
                lightSplat_->record(cmd, depth);
        }
        if (lightRaygen_ && integrator_ == Integrator::Light)
            recordLightSubpaths(cmd, wave);
    }
    accumulate_->record(cmd, wave);
    timer_->finish(cmd);
}

// The light subpaths of the wave's paths, after the camera's pass (which queued nothing):
// their vertex at light bounce d connects to the camera as a path of d + 2 segments, so
// bounces 0 .. maxDepth - 2 are traced.
void WaveRecorder::recordLightSubpaths(VkCommandBuffer cmd, const PassConstants& wave) const {
    if (maxDepth_ < 2)
        return;
    lightRaygen_->record(cmd, wave);
    // Its appends become light bounce 0's arguments; their statistics count with the camera
    // rays' (depthRays[0]).
    queue_->record(cmd, ~0u);
    for (uint32_t depth = 0; depth + 2 <= maxDepth_; ++depth) {
        intersect_->record(cmd, depth);
        lightShade_->record(cmd, depth, wave);
        queue_->record(cmd, depth);
        lightSplat_->record(cmd, depth);
    }
}

void WaveRecorder::recordIntersect(VkCommandBuffer cmd, uint32_t count) const {
    if (!intersect_)
        throw InternalError("recordIntersect: the megakernel has no intersect pass");
    timer_->reset(cmd);
    QueueCounters initial{};
    initial.rayArgs = {groupsFor(count), 1, 1, count};
    initial.rayTrace = {count, 1, 1, 0};
    for (DispatchArgs& args : initial.kindArgs)
        args = {0, 1, 1, 0};
    vkCmdUpdateBuffer(cmd, counters_.handle(), 0, sizeof initial, &initial);
    computeBarrier(cmd);
    intersect_->record(cmd, 0);
    timer_->finish(cmd);
}

std::map<std::string, double> WaveRecorder::collectTimes() { return timer_->collect(); }

} // namespace wf
