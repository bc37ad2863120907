// light_splat: the visibility of the camera connections light_shade queued, and the splats of
// the visible ones into the light film (shaders/light_splat.comp).
#pragma once
#include "passes/pass.h"

namespace wf {

class LightSplatPass {
public:
    explicit LightSplatPass(const PassResources& resources)
        : pass_(resources, "light_splat", "light_splat.comp") {}
    void record(VkCommandBuffer cmd, uint32_t depth) const;

private:
    Pass pass_;
};

} // namespace wf
