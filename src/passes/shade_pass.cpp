#include "passes/shade_pass.h"

#include <cstddef>

namespace wf {

void ShadePass::record(VkCommandBuffer cmd, uint32_t depth, uint32_t sampleBase) const {
    pass_.dispatchIndirect(cmd, offsetof(gpu_types::QueueCounters, rayArgs),
                           PassConstants{depth, sampleBase, 0, 0});
}

} // namespace wf
