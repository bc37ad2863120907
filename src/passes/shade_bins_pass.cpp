#include "passes/shade_bins_pass.h"

namespace wf {

void ShadeBinsPass::record(VkCommandBuffer cmd, uint32_t depth) const {
    pass_.dispatch(cmd, 1, PassConstants{depth, 0, 0, 0, 0, 0, 0, 0});
}

} // namespace wf
