#version 460
#extension GL_KHR_shader_subgroup_basic : require
// Invocation i copies texel i of an r32ui storage texel buffer (word i, which holds i) to word
// 1024 + i, plus 1; word 1536 + i gets gl_SubgroupSize + 1. Reading gl_SubgroupSize makes the
// shader's NIR differ between vector widths, so llvmpipe compiles the shader afresh at each
// width while the image-load function it calls comes from the on-disk cache.
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Words { uint data[]; };
layout(binding = 1, r32ui) uniform readonly uimageBuffer words;
void main() {
    uint i = gl_GlobalInvocationID.x;
    data[1024u + i] = imageLoad(words, int(i)).x + 1u;
    data[1536u + i] = gl_SubgroupSize + 1u;
}
