#include "passes/raygen_pass.h"

namespace wf {

void RaygenPass::record(VkCommandBuffer cmd, const PassConstants& wave) const {
    pass_.dispatch(cmd, groupsFor(wave.pathCount), wave);
}

} // namespace wf
