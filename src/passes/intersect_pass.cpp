#include "passes/intersect_pass.h"

#include <cstddef>

namespace wf {

void IntersectPass::record(VkCommandBuffer cmd, uint32_t depth) const {
    if (trace_) {
        trace_->record(cmd, depth);
        return;
    }
    pass_->dispatchIndirect(cmd, offsetof(gpu_types::QueueCounters, rayArgs),
                           PassConstants{depth, 0, 0, 0, 0, 0, 0, 0});
}

} // namespace wf
