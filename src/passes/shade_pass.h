// shade: emission, next-event estimation and the continuation ray for every hit of the current
// ray queue (shaders/shade.comp); appends to the next ray queue and the shadow queue.
#pragma once
#include "passes/pass.h"

namespace wf {

class ShadePass {
public:
    explicit ShadePass(const PassResources& resources)
        : pass_(resources, "shade", "shade.comp") {}
    void record(VkCommandBuffer cmd, uint32_t depth, const PassConstants& wave) const;

private:
    Pass pass_;
};

} // namespace wf
