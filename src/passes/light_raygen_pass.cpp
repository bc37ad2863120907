#include "passes/light_raygen_pass.h"

namespace wf {

void LightRaygenPass::record(VkCommandBuffer cmd, const PassConstants& wave) const {
    pass_.dispatch(cmd, groupsFor(wave.pathCount), wave);
}

} // namespace wf
