#include "passes/queue_pass.h"

namespace wf {

void QueuePass::record(VkCommandBuffer cmd) const {
    pass_.dispatch(cmd, 1, PassConstants{0, 0, 0, 0});
}

} // namespace wf
