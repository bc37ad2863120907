// The intersect and shadow passes as ray-tracing pipelines (--traversal rt): a ray-generation
// shader that reads the queue and writes the records the compute passes write, over the
// scene's acceleration structures (shaders/rt/), traced by the arguments the queue pass wrote
// (QueueCounters::rayTrace, shadowTrace). Compiles only the hit shaders the scene needs: the
// alpha test where some mesh is alpha-tested, the sphere test where there are sphere lights.
#pragma once
#include <memory>

#include "gpu/ray_tracing_program.h"
#include "passes/pass.h"

namespace wf {

enum class TraceKind { Closest, Shadow };

class TracePass {
public:
    TracePass(const PassResources& resources, const char* name, TraceKind kind);
    void record(VkCommandBuffer cmd, uint32_t depth) const;

private:
    const char* name_;
    TraceKind kind_;
    const Buffer& counters_;
    TimestampTimer& timer_;
    std::unique_ptr<RayTracingProgram> program_;
};

} // namespace wf
