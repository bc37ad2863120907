// light_shade: one vertex of every light subpath in the ray queue, its camera connection and
// its continuation (shaders/light_shade.comp).
#pragma once
#include "passes/pass.h"

namespace wf {

class LightShadePass {
public:
    explicit LightShadePass(const PassResources& resources)
        : pass_(resources, "light_shade", "light_shade.comp") {}
    // `depth`: the light bounce; `wave` maps each path to its pixel and sample index.
    void record(VkCommandBuffer cmd, uint32_t depth, const PassConstants& wave) const;

private:
    Pass pass_;
};

} // namespace wf
