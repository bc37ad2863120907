// shadow: any-hit visibility of the NEE connections in the shadow queue (shaders/shadow.comp).
#pragma once
#include "passes/pass.h"

namespace wf {

class ShadowPass {
public:
    explicit ShadowPass(const PassResources& resources)
        : pass_(resources, "shadow", "shadow.comp") {}
    void record(VkCommandBuffer cmd, uint32_t depth) const;

private:
    Pass pass_;
};

} // namespace wf
