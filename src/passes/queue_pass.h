// queue: one invocation that turns append counters into indirect-dispatch arguments and
// resets them (shaders/queue.comp): the "queue bookkeeping" of the timings.
#pragma once
#include "passes/pass.h"

namespace wf {

class QueuePass {
public:
    explicit QueuePass(const PassResources& resources)
        : pass_(resources, "queue", "queue.comp") {}
    void record(VkCommandBuffer cmd, uint32_t depth) const;

private:
    Pass pass_;
};

} // namespace wf
