// shade bins: one invocation that turns the shade bins' append counters into the per-bin shade
// passes' indirect arguments and resets them (shaders/shade_bins.comp). Scenes shaded by
// material kind only (WF_SHADE_BINS > 1).
#pragma once
#include "passes/pass.h"

namespace wf {

class ShadeBinsPass {
public:
    explicit ShadeBinsPass(const PassResources& resources)
        : pass_(resources, "shade bins", "shade_bins.comp") {}
    void record(VkCommandBuffer cmd, uint32_t depth) const;

private:
    Pass pass_;
};

} // namespace wf
