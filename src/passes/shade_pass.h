// shade: emission, next-event estimation and the continuation ray for every hit of the current
// ray queue (shaders/shade.comp); appends to the next ray queue and the shadow queue. Scenes
// shaded by material kind have one per shade bin, each compiled for its kind's BSDF.
#pragma once
#include <cstddef>

#include "passes/pass.h"
#include "passes/shade_kinds.h"

namespace wf {

class ShadePass {
public:
    explicit ShadePass(const PassResources& resources)
        : pass_(resources, "shade", "shade.comp") {}
    // The pass of shade bin `bin`, which holds the hits on materials of `kind`.
    ShadePass(const PassResources& resources, uint32_t bin, ShadeKind kind);
    void record(VkCommandBuffer cmd, uint32_t depth, const PassConstants& wave) const;

private:
    Pass pass_;
    VkDeviceSize argsOffset_ = offsetof(gpu_types::QueueCounters, rayArgs);
};

} // namespace wf
