#include "passes/light_shade_pass.h"

#include <cstddef>

namespace wf {

void LightShadePass::record(VkCommandBuffer cmd, uint32_t depth, const PassConstants& wave) const {
    PassConstants constants = wave;
    constants.depth = depth;
    pass_.dispatchIndirect(cmd, offsetof(gpu_types::QueueCounters, rayArgs), constants);
}

} // namespace wf
