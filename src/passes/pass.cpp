#include "passes/pass.h"

#include "gpu/buffer.h"
#include "gpu/timestamp_timer.h"
#include "passes/workgroup.h"

namespace wf {

Pass::Pass(const PassResources& resources, const char* name, const char* shaderFile)
    : name_(name), counters_(resources.counters), timer_(resources.timer) {
    CompiledShader shader = resources.compiler.compile(shaderFile, resources.defines);
    fromCache_ = shader.fromCache;
    program_ = std::make_unique<ComputeProgram>(resources.context, name, shader.spirv,
                                                resources.table, sizeof(PassConstants));
}

void Pass::dispatch(VkCommandBuffer cmd, uint32_t groups, const PassConstants& constants) const {
    timer_.mark(cmd, name_);
    program_->dispatch(cmd, groups, &constants);
    computeBarrier(cmd);
}

void Pass::dispatchIndirect(VkCommandBuffer cmd, VkDeviceSize argsOffset,
                            const PassConstants& constants) const {
    timer_.mark(cmd, name_);
    program_->dispatchIndirect(cmd, counters_, argsOffset, &constants);
    computeBarrier(cmd);
}

uint32_t groupsFor(uint32_t items) { return (items + kWorkgroupSize - 1) / kWorkgroupSize; }

} // namespace wf
