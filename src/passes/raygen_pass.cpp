#include "passes/raygen_pass.h"

namespace wf {

void RaygenPass::record(VkCommandBuffer cmd, uint32_t sampleBase, uint32_t pathCount) const {
    PassConstants constants{0, sampleBase, pathCount, 0};
    pass_.dispatch(cmd, groupsFor(pathCount), constants);
}

} // namespace wf
