// raygen: camera rays for every path of a wave (shaders/raygen.comp).
#pragma once
#include "passes/pass.h"

namespace wf {

class RaygenPass {
public:
    explicit RaygenPass(const PassResources& resources)
        : pass_(resources, "raygen", "raygen.comp") {}
    void record(VkCommandBuffer cmd, const PassConstants& wave) const;

private:
    Pass pass_;
};

} // namespace wf
