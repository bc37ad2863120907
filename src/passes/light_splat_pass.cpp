#include "passes/light_splat_pass.h"

#include <cstddef>

namespace wf {

void LightSplatPass::record(VkCommandBuffer cmd, uint32_t depth) const {
    pass_.dispatchIndirect(cmd, offsetof(gpu_types::QueueCounters, shadowArgs),
                           PassConstants{depth, 0, 0, 0, 0, 0, 0, 0});
}

} // namespace wf
