// megakernel: the baseline that traces whole paths in one dispatch (shaders/megakernel.comp),
// built from the same GLSL functions as the passes. The renderer runs it instead of raygen,
// intersect, shade, queue and shadow when RenderSettings::megakernel is set; accumulate
// follows as usual.
#pragma once
#include "passes/pass.h"

namespace wf {

class MegakernelPass {
public:
    explicit MegakernelPass(const PassResources& resources)
        : pass_(resources, "megakernel", "megakernel.comp") {}
    void record(VkCommandBuffer cmd, const PassConstants& wave) const;

private:
    Pass pass_;
};

} // namespace wf
