// intersect: closest hits of the current ray queue (shaders/intersect.comp), sized by the
// indirect arguments the queue pass wrote.
#pragma once
#include "passes/pass.h"

namespace wf {

class IntersectPass {
public:
    explicit IntersectPass(const PassResources& resources)
        : pass_(resources, "intersect", "intersect.comp") {}
    void record(VkCommandBuffer cmd, uint32_t depth) const;

private:
    Pass pass_;
};

} // namespace wf
