// shadow: any-hit visibility of the NEE connections in the shadow queue (shaders/shadow.comp).
#pragma once
#include <memory>

#include "passes/pass.h"
#include "passes/trace_pass.h"

namespace wf {

class ShadowPass {
public:
    explicit ShadowPass(const PassResources& resources) {
        if (resources.rayTracing)
            trace_ = std::make_unique<TracePass>(resources, "shadow", TraceKind::Shadow);
        else
            pass_ = std::make_unique<Pass>(resources, "shadow", "shadow.comp");
    }
    void record(VkCommandBuffer cmd, uint32_t depth) const;

private:
    std::unique_ptr<Pass> pass_;       // compute: the project's BVH
    std::unique_ptr<TracePass> trace_; // or the driver's acceleration structures
};

} // namespace wf
