// light_raygen: the first ray of a light subpath for every path of a light-tracing wave
// (shaders/light_raygen.comp).
#pragma once
#include "passes/pass.h"

namespace wf {

class LightRaygenPass {
public:
    explicit LightRaygenPass(const PassResources& resources)
        : pass_(resources, "light_raygen", "light_raygen.comp") {}
    void record(VkCommandBuffer cmd, const PassConstants& wave) const;

private:
    Pass pass_;
};

} // namespace wf
