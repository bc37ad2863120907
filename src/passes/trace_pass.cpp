#include "passes/trace_pass.h"

#include <algorithm>
#include <cstddef>

#include "gpu/timestamp_timer.h"

namespace wf {
namespace {

bool defined(const ShaderDefines& defines, const char* name) {
    return std::any_of(defines.begin(), defines.end(),
                       [&](const auto& d) { return d.first == name && d.second != "0"; });
}

} // namespace

TracePass::TracePass(const PassResources& resources, const char* name, TraceKind kind)
    : name_(name), kind_(kind), counters_(resources.counters), timer_(resources.timer) {
    const ShaderCompiler& compiler = resources.compiler;
    const ShaderDefines& defines = resources.defines;
    const bool shadow = kind == TraceKind::Shadow;
    RayTracingShaders shaders;
    shaders.rayGeneration =
        compiler.compile(shadow ? "rt/shadow.rgen" : "rt/intersect.rgen", defines).spirv;
    shaders.miss = compiler.compile("rt/miss.rmiss", defines).spirv;
    // Shadow rays skip closest hits (the first accepted hit ends them), but their hit group
    // keeps the shader all the same: Mesa 25.0's lavapipe at 4 lanes (LP_NATIVE_VECTOR_WIDTH
    // 128) jumped to a null address in the shadow pass with an empty triangle hit group, which
    // Vulkan allows (3 of 3 runs of the Cornell box at depth 5; none with the shader present).
    // Were it ever run, it would still mean "occluded": it leaves w off WF_MISS.
    shaders.triangleClosestHit = compiler.compile("rt/triangle.rchit", defines).spirv;
    if (defined(defines, "WF_HAS_ALPHA_MASK"))
        shaders.triangleAnyHit = compiler.compile("rt/alpha.rahit", defines).spirv;
    if (defined(defines, "WF_HAS_SPHERE_LIGHTS")) {
        ShaderDefines sphereDefines = defines;
        sphereDefines.emplace_back("WF_RT_SHADOW", shadow ? "1" : "0");
        shaders.boxIntersection = compiler.compile("rt/sphere.rint", sphereDefines).spirv;
        if (!shadow)
            shaders.boxClosestHit = compiler.compile("rt/sphere.rchit", defines).spirv;
    }
    program_ = std::make_unique<RayTracingProgram>(resources.context, name, shaders,
                                                   resources.table, sizeof(PassConstants));
}

void TracePass::record(VkCommandBuffer cmd, uint32_t depth) const {
    const PassConstants constants{depth, 0, 0, 0, 0, 0, 0, 0};
    const VkDeviceSize args = kind_ == TraceKind::Shadow
                                  ? offsetof(gpu_types::QueueCounters, shadowTrace)
                                  : offsetof(gpu_types::QueueCounters, rayTrace);
    timer_.mark(cmd, name_);
    rayTracingBarrier(cmd); // the compute passes' barriers leave the ray-tracing stage out
    program_->traceIndirect(cmd, counters_, args, &constants);
    rayTracingBarrier(cmd);
}

} // namespace wf
