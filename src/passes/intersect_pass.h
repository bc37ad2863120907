// intersect: closest hits of the current ray queue (shaders/intersect.comp), sized by the
// indirect arguments the queue pass wrote.
#pragma once
#include <memory>

#include "passes/pass.h"
#include "passes/trace_pass.h"

namespace wf {

class IntersectPass {
public:
    explicit IntersectPass(const PassResources& resources) {
        if (resources.rayTracing)
            trace_ = std::make_unique<TracePass>(resources, "intersect", TraceKind::Closest);
        else
            pass_ = std::make_unique<Pass>(resources, "intersect", "intersect.comp");
    }
    void record(VkCommandBuffer cmd, uint32_t depth) const;

private:
    std::unique_ptr<Pass> pass_;       // compute: the project's BVH
    std::unique_ptr<TracePass> trace_; // or the driver's acceleration structures
};

} // namespace wf
