#include "passes/accumulate_pass.h"

namespace wf {

void AccumulatePass::record(VkCommandBuffer cmd, const PassConstants& wave) const {
    pass_.dispatch(cmd, groupsFor(wave.wavePixels), wave);
}

} // namespace wf
