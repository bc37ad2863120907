// What every pass shares: its compiled program, the timestamp bracket around its dispatch and
// the barrier after it. The per-pass files only say which shader and how many invocations.
#pragma once
#include <memory>
#include <string>

#include "gpu/compute_program.h"
#include "gpu/shader_compiler.h"
#include "shaders/types/render_types.h"

namespace wf {

class Buffer;
class Context;
class TimestampTimer;

struct PassResources {
    const Context& context;
    const ShaderCompiler& compiler;
    const ShaderDefines& defines;
    const DescriptorTable& table;
    const Buffer& counters;
    TimestampTimer& timer;
    bool rayTracing = false; // intersect and shadow as ray-tracing pipelines (trace_pass.h)
};

using gpu_types::PassConstants;

class Pass {
public:
    Pass(const PassResources& resources, const char* name, const char* shaderFile);

    const char* name() const { return name_; }
    bool compiledFromCache() const { return fromCache_; }

    void dispatch(VkCommandBuffer cmd, uint32_t groups, const PassConstants& constants) const;
    // Group count read from QueueCounters at `argsOffset`, written by an earlier pass.
    void dispatchIndirect(VkCommandBuffer cmd, VkDeviceSize argsOffset,
                          const PassConstants& constants) const;

private:
    const char* name_;
    const Buffer& counters_;
    TimestampTimer& timer_;
    std::unique_ptr<ComputeProgram> program_;
    bool fromCache_ = false;
};

uint32_t groupsFor(uint32_t items);

} // namespace wf
