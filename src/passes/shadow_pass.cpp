#include "passes/shadow_pass.h"

#include <cstddef>

namespace wf {

void ShadowPass::record(VkCommandBuffer cmd, uint32_t depth) const {
    if (trace_) {
        trace_->record(cmd, depth);
        return;
    }
    pass_->dispatchIndirect(cmd, offsetof(gpu_types::QueueCounters, shadowArgs),
                           PassConstants{depth, 0, 0, 0, 0, 0, 0, 0});
}

} // namespace wf
