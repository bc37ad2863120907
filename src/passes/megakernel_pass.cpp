#include "passes/megakernel_pass.h"

namespace wf {

void MegakernelPass::record(VkCommandBuffer cmd, const PassConstants& wave) const {
    pass_.dispatch(cmd, groupsFor(wave.pathCount), wave);
}

} // namespace wf
