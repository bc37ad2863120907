// The viewer's display pass (shaders/display.comp): film -> tone-mapped RGBA8 for the window.
// It binds only its two buffers, in a descriptor set of its own, so the renderer's passes and
// their shared set know nothing about displaying. One DisplayPass per (film, output) pair.
#pragma once
#include <cstdint>
#include <memory>

#include <vulkan/vulkan.h>

#include "gpu/compute_program.h"
#include "gpu/shader_compiler.h"
#include "image/tonemap.h"

namespace wf {

class Buffer;
class Context;


struct DisplaySize {
    uint32_t width;
    uint32_t height;
};

class DisplayPass {
public:
    // `film`: vec4 per pixel (radiance sum, sample count), filmSize pixels. `output`: one
    // packed RGBA8 uint per pixel, outputSize pixels.
    DisplayPass(const Context& context, const ShaderCompiler& compiler, const Buffer& film,
                DisplaySize filmSize, const Buffer& output, DisplaySize outputSize);
    ~DisplayPass();

    // Exposure in stops (EV): the radiance is scaled by 2^exposure before the tone curve.
    void record(VkCommandBuffer cmd, float exposure, Tonemap tonemap) const;

private:
    DisplaySize filmSize_;
    DisplaySize outputSize_;
    std::unique_ptr<DescriptorTable> table_;
    std::unique_ptr<ComputeProgram> program_;
};


} // namespace wf
