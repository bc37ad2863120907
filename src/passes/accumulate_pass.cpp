#include "passes/accumulate_pass.h"

namespace wf {

void AccumulatePass::record(VkCommandBuffer cmd, uint32_t pixelCount,
                            uint32_t samplesPerPixel) const {
    pass_.dispatch(cmd, groupsFor(pixelCount), PassConstants{0, 0, 0, samplesPerPixel});
}

} // namespace wf
