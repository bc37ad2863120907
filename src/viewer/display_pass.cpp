#include "viewer/display_pass.h"

#include <algorithm>
#include <cmath>

#include "gpu/buffer.h"
#include "shaders/types/display_types.h"

namespace wf {

using gpu_types::DisplayConstants;

DisplayPass::DisplayPass(const Context& context, const ShaderCompiler& compiler,
                         const Buffer& film, DisplaySize filmSize, const Buffer& output,
                         DisplaySize outputSize)
    : filmSize_(filmSize), outputSize_(outputSize) {
    table_ = std::make_unique<DescriptorTable>(
        context, DescriptorBindings{{0, &film}, {1, &output}});
    CompiledShader shader = compiler.compile("display.comp", {});
    program_ = std::make_unique<ComputeProgram>(context, "display", shader.spirv, *table_,
                                                sizeof(DisplayConstants));
}

DisplayPass::~DisplayPass() = default;

void DisplayPass::record(VkCommandBuffer cmd, float exposure, Tonemap tonemap) const {
    DisplayConstants constants{};
    constants.filmWidth = filmSize_.width;
    constants.filmHeight = filmSize_.height;
    constants.outWidth = outputSize_.width;
    constants.outHeight = outputSize_.height;
    constants.exposureScale = std::exp2(exposure);
    constants.tonemap = static_cast<uint32_t>(tonemap);
    // The shader loops over the pixels, so the group count only needs to fill the device.
    const uint64_t pixels = uint64_t(outputSize_.width) * outputSize_.height;
    const uint32_t groups = static_cast<uint32_t>(std::clamp<uint64_t>((pixels + 63) / 64, 1,
                                                                       65535));
    program_->dispatch(cmd, groups, &constants);
}

} // namespace wf
