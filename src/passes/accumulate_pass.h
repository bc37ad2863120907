// accumulate: adds a wave's samples into the film per pixel (shaders/accumulate.comp).
#pragma once
#include "passes/pass.h"

namespace wf {

class AccumulatePass {
public:
    explicit AccumulatePass(const PassResources& resources)
        : pass_(resources, "accumulate", "accumulate.comp") {}
    void record(VkCommandBuffer cmd, const PassConstants& wave) const;

private:
    Pass pass_;
};

} // namespace wf
