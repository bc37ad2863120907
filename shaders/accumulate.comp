#version 460
// accumulate: adds the wave's samples of each pixel to the film, in sample order so that the
// sum is reproducible bit for bit. A sample with a NaN or Inf component is dropped (zeroed)
// and counted; the test is on the bit pattern so that no fast-math pass can fold it away.
// In: radiance of paths pixel + s * pixelCount. Out: film[pixel], counters.nonFiniteSamples.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "bindings.glsl"

layout(push_constant) uniform Push { PassConstants pass; };

bool isFiniteBits(vec3 v) {
    uvec3 exponent = floatBitsToUint(v) & uvec3(0x7f800000u);
    return all(notEqual(exponent, uvec3(0x7f800000u)));
}

void main() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= params.pixelCount)
        return;
    vec3 sum = vec3(0.0);
    uint dropped = 0u;
    for (uint s = 0u; s < pass.samplesPerPixel; ++s) {
        vec3 value = radiance[pixel + s * params.pixelCount].rgb;
        if (isFiniteBits(value))
            sum += value;
        else
            ++dropped;
    }
    if (dropped > 0u)
        atomicAdd(counters.nonFiniteSamples, dropped);
    film[pixel] += vec4(sum, float(pass.samplesPerPixel));
}
